// ContactSolver::correct_positions: a positional nudge that removes part of
// the penetration without touching velocities (so it adds no energy).
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "collision2d/contact_solver.h"
#include "contact_rows.h"

namespace collision2d
{
namespace
{
bool same_pair(const Contact& l, const Contact& r) { return l.a == r.a && l.b == r.b; }

/// Index of the deepest contact among order[begin, end) (the first on ties).
std::size_t deepest(const std::vector<Contact>& contacts, const std::vector<std::size_t>& order, std::size_t begin,
                    std::size_t end)
{
  std::size_t best = order[begin];
  for (std::size_t k = begin + 1; k < end; ++k)
    if (contacts[order[k]].penetration > contacts[best].penetration)
      best = order[k];
  return best;
}

/// Throws std::overflow_error naming the first body whose corrected position
/// is not finite.
void require_finite_positions(const std::vector<Body>& bodies)
{
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    if (!is_finite(bodies[i].position()))
      throw std::overflow_error("body " + std::to_string(i) +
                                ": position correction overflowed to a non-finite position (the input's depths "
                                "lie beyond what double precision can resolve)");
  }
}

/// The moves of correct_positions, one per pair (by its deepest point);
/// `order` lists the contacts sorted by pair.
void apply_corrections(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                       const std::vector<std::size_t>& order, double bias_factor, double slop)
{
  for (std::size_t begin = 0; begin < order.size();)
  {
    std::size_t end = begin + 1;
    while (end < order.size() && same_pair(contacts[order[end]], contacts[order[begin]]))
      ++end;
    const Contact& c = contacts[deepest(contacts, order, begin, end)];
    begin = end;

    Body& a = bodies[c.a];
    Body& b = bodies[c.b];
    const double w_a = a.inv_mass();
    const double w_b = b.inv_mass();
    const double w_sum = w_a + w_b;
    const double move = bias_factor * std::max(0.0, c.penetration - slop);
    if (!(w_sum > 0.0) || move == 0.0)
      continue;  // two immovable bodies, or nothing beyond the slop
    // Moves are translations along fixed normals, so their order does not matter.
    // A static or kinematic body is skipped outright: not even a -0.0 changes.
    if (w_a > 0.0)
      a.set_position(a.position() - (w_a / w_sum * move) * c.normal);
    if (w_b > 0.0)
      b.set_position(b.position() + (w_b / w_sum * move) * c.normal);
  }
}

}  // namespace

void ContactSolver::correct_positions(std::vector<Body>& bodies, const std::vector<Contact>& contacts) const
{
  detail::validate_bodies(bodies);
  for (std::size_t i = 0; i < contacts.size(); ++i)
    detail::validate_contact(contacts[i], i, bodies.size());

  // Group the points of each pair: a two-point manifold is one overlap, so it
  // is corrected once, by its deepest point, not once per point.
  std::vector<std::size_t> order(contacts.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&contacts](std::size_t l, std::size_t r) {
    const Contact& cl = contacts[l];
    const Contact& cr = contacts[r];
    return cl.a != cr.a ? cl.a < cr.a : (cl.b != cr.b ? cl.b < cr.b : l < r);
  });

  // All or nothing: an overflow (finite depths far beyond the supported
  // ranges) leaves the bodies exactly as they came in.
  detail::all_or_nothing(bodies, [&] {
    apply_corrections(bodies, contacts, order, bias_factor_, slop_);
    require_finite_positions(bodies);
  });
}

}  // namespace collision2d
