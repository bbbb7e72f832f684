#include "contact_rows.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collision2d
{
namespace detail
{
namespace
{
// Detection produces unit normals; a hand-made contact far from unit length
// would silently scale its impulses, so it is rejected.
constexpr double kUnitNormalTolerance = 1e-6;

bool is_dynamic(const BodyVelocity& body) { return body.inv_mass > 0.0; }

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];  // path halving keeps later finds short
    i = parent[i];
  }
  return i;
}

void unite(std::vector<std::size_t>& parent, std::size_t i, std::size_t j)
{
  const std::size_t ri = find_root(parent, i);
  const std::size_t rj = find_root(parent, j);
  // The smaller index becomes the root so the result does not depend on order.
  if (ri < rj)
    parent[rj] = ri;
  else if (rj < ri)
    parent[ri] = rj;
}

}  // namespace

void validate_contact(const Contact& c, std::size_t index, std::size_t body_count)
{
  // Messages are built only on failure, so valid contacts cost no allocation.
  if (c.a >= body_count || c.b >= body_count || c.a == c.b)
    throw std::invalid_argument("contact " + std::to_string(index) + " names bodies " + std::to_string(c.a) +
                                " and " + std::to_string(c.b) + " of " + std::to_string(body_count));
  if (!is_finite(c.normal) || !(std::abs(length_sq(c.normal) - 1.0) <= kUnitNormalTolerance))
    throw std::invalid_argument("contact " + std::to_string(index) + ": normal is not a finite unit vector");
  if (!is_finite(c.point) || !std::isfinite(c.penetration))
    throw std::invalid_argument("contact " + std::to_string(index) + ": point or penetration is not finite");
}

void validate_bodies(const std::vector<Body>& bodies)
{
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    const char* field = non_finite_state_field(bodies[i]);
    if (field != nullptr)
      throw std::invalid_argument("body " + std::to_string(i) + ": " + field + " is not finite");
  }
}

void load_velocities(const std::vector<Body>& bodies, std::vector<BodyVelocity>& state)
{
  state.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    const Body& body = bodies[i];
    set_body_velocity(state[i], body.velocity(), body.omega(), body.inv_mass(), body.inv_inertia());
  }
}

void store_velocities(const std::vector<BodyVelocity>& state, std::vector<Body>& bodies)
{
  // Checked before anything is written, so an overflow leaves the bodies as
  // they came in.
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    if (state[i].inv_mass > 0.0 && !(is_finite(state[i].v) && std::isfinite(state[i].omega)))
      throw std::overflow_error("body " + std::to_string(i) +
                                ": the solve overflowed to a non-finite velocity (the input's sizes, speeds or "
                                "masses lie beyond what double precision can resolve)");
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    if (state[i].inv_mass <= 0.0)
      continue;
    bodies[i].set_velocity(state[i].v);
    bodies[i].set_omega(state[i].omega);
  }
}

double total_kinetic_energy(const std::vector<Body>& bodies)
{
  double energy = 0.0;
  for (const Body& body : bodies)
    energy += body.kinetic_energy();
  return energy;
}

void prepare_problem(const std::vector<Body>& bodies, const std::vector<Contact>& contacts, double restitution,
                     double mu, ContactProblem& problem)
{
  load_velocities(bodies, problem.state);
  build_rows(bodies, problem.state, contacts, restitution, mu, problem.rows);
  partition_islands(problem.state, problem.rows, problem.islands, problem.parent);
}

void store_impulses(const ContactPoints& rows, std::size_t contact_count,
                    std::vector<ContactImpulse>& impulses)
{
  impulses.assign(contact_count, ContactImpulse{});
  for (const ContactPoint& row : rows)
    impulses[row.contact] = {row.lambda_n, row.lambda_t};
}

void build_rows(const std::vector<Body>& bodies, const std::vector<BodyVelocity>& state,
                const std::vector<Contact>& contacts, double restitution, double mu, ContactPoints& rows)
{
  rows.clear();
  rows.reserve(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const Contact& c = contacts[i];
    validate_contact(c, i, bodies.size());
    ContactPoint p;
    p.contact = i;
    p.a = c.a;
    p.b = c.b;
    p.normal = c.normal;
    p.point = c.point;
    p.separation = -c.penetration;
    p.feature = c.feature;
    p.r_a = c.point - bodies[c.a].position();
    p.r_b = c.point - bodies[c.b].position();
    p.inv_mass_a = state[c.a].inv_mass;
    p.inv_mass_b = state[c.b].inv_mass;
    p.inv_inertia_a = state[c.a].inv_inertia;
    p.inv_inertia_b = state[c.b].inv_inertia;
    p.mu_s = mu;
    p.mu_k = mu;
    // Every approach counts (threshold 0): an instantaneous solve has no
    // resting contacts to protect from jitter.
    prepare_point(p, state, restitution, 0.0);
    if (p.k_n > 0.0)
    {
      rows.push_back(p);
    }
  }
}

void partition_islands(const std::vector<BodyVelocity>& state, ContactPoints& rows,
                        std::vector<IslandRange>& islands, std::vector<std::size_t>& parent)
{
  parent.resize(state.size());
  for (std::size_t i = 0; i < parent.size(); ++i)
    parent[i] = i;
  for (const ContactPoint& row : rows)
    if (is_dynamic(state[row.a]) && is_dynamic(state[row.b]))
      unite(parent, row.a, row.b);
  for (ContactPoint& row : rows)
    row.island = find_root(parent, is_dynamic(state[row.a]) ? row.a : row.b);

  // Contact index last makes the order total, so the solve is deterministic.
  std::sort(rows.begin(), rows.end(), [](const ContactPoint& l, const ContactPoint& r) {
    if (l.island != r.island)
      return l.island < r.island;
    if (l.a != r.a)
      return l.a < r.a;
    if (l.b != r.b)
      return l.b < r.b;
    return l.contact < r.contact;
  });

  islands.clear();
  islands.reserve(rows.size());
  for (std::size_t begin = 0; begin < rows.size();)
  {
    std::size_t end = begin + 1;
    while (end < rows.size() && rows[end].island == rows[begin].island)
      ++end;
    islands.push_back({begin, end});
    begin = end;
  }
}

}  // namespace detail
}  // namespace collision2d
