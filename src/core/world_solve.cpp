// Penetration resolution and velocity resolution of one substep (SPEC section
// 3, steps 3 and 5) over the rows prepared from detection.
#include <algorithm>
#include <cmath>

#include "collision2d/world.h"

namespace collision2d
{
namespace
{
double min_of(double a, double b) { return a < b ? a : b; }


}  // namespace

void World::prepare_rows(const ActiveEffects& effects)
{
  const double threshold = settings_.restitution_threshold;
  for (ContactRow& row : rows_)
  {
    if (!row.active)
    {
      continue;
    }
    const Body& a = bodies_[row.a];
    const Body& b = bodies_[row.b];
    row.ra = row.point - a.position();
    row.rb = row.point - b.position();
    row.inv_mass_a = a.inv_mass();
    row.inv_mass_b = b.inv_mass();
    const Material& ma = materials_[row.a];
    const Material& mb = materials_[row.b];
    row.mu_s = effects.friction ? min_of(ma.static_friction, mb.static_friction) : 0.0;
    row.mu_k = effects.friction ? min_of(ma.kinetic_friction, mb.kinetic_friction) : 0.0;
    // With rotation off, bodies are modelled as not turning at all. A disk's
    // contact normal passes through its centre, so without friction it cannot
    // turn either; dropping its inertia there keeps the round-off of the lever
    // arm from spinning it.
    const bool rough = row.mu_s > 0.0 || row.mu_k > 0.0;
    row.inv_inertia_a = effects.rotation && (rough || a.shape() == Shape::Polygon) ? a.inv_inertia() : 0.0;
    row.inv_inertia_b = effects.rotation && (rough || b.shape() == Shape::Polygon) ? b.inv_inertia() : 0.0;
    const Vec2 t = perp(row.normal);
    row.normal_mass = 1.0 / effective_inverse_mass(row, row.normal);
    row.tangent_mass = 1.0 / effective_inverse_mass(row, t);
    row.pair_tangent_mass = row.tangent_mass;
    // The approach speed is taken before the position solve and kept fixed
    // through the iterations; below the threshold a contact just rests.
    const double e = effects.restitution ? min_of(ma.restitution, mb.restitution) : 0.0;
    const double approach = -dot(relative_velocity(row), row.normal);
    row.target = e > 0.0 && approach > threshold ? e * approach : 0.0;
  }
  for (std::size_t k = 0; k + 1 < rows_.size(); ++k)
  {
    ContactRow& first = rows_[k];
    if (first.active && first.count == 2)
    {
      // Tangent mass at the manifold's midpoint, for the pair's friction row.
      ContactRow mid = first;
      mid.ra = 0.5 * (first.ra + rows_[k + 1].ra);
      mid.rb = 0.5 * (first.rb + rows_[k + 1].rb);
      first.pair_tangent_mass = 1.0 / effective_inverse_mass(mid, perp(first.normal));
      ++k;
    }
  }
}

double World::effective_inverse_mass(const ContactRow& row, Vec2 direction) const
{
  const double arm_a = cross(row.ra, direction);
  const double arm_b = cross(row.rb, direction);
  return row.inv_mass_a + row.inv_mass_b + row.inv_inertia_a * arm_a * arm_a + row.inv_inertia_b * arm_b * arm_b;
}

Vec2 World::relative_velocity(const ContactRow& row) const
{
  return relative_velocity_at(row, row.ra, row.rb);
}

Vec2 World::relative_velocity_at(const ContactRow& row, Vec2 ra, Vec2 rb) const
{
  const Body& a = bodies_[row.a];
  const Body& b = bodies_[row.b];
  return b.velocity() + cross(b.omega(), rb) - a.velocity() - cross(a.omega(), ra);
}

void World::correct_positions(double h, bool friction, StepReport& report)
{
  const double softness = settings_.compliance / (h * h);
  moved_.assign(bodies_.size(), Vec2{0.0, 0.0});
  turned_.assign(bodies_.size(), 0.0);
  const bool exact = settings_.solver_mode == SolverMode::Exact && settings_.exact_position_correction;
  if (exact)
  {
    // Every static-friction hold first, then the islands' penetrations at once
    // (world_exact.cpp); a failed island is left to the passes below.
    hold_all_static_friction(friction);
    solve_position_islands(softness, report);
  }
  for (int pass = 0; pass < settings_.position_iterations; ++pass)
  {
    correct_pass(softness, !exact && friction && pass == 0, pass > 0);
  }
}

void World::correct_pass(double softness, bool hold, bool resting_only)
{
  // The extra passes are for resting contacts, where each substep's gravity
  // sag accumulates. An impact (Newton target > 0) separates in the velocity
  // solve anyway; pushing it further apart changes which contacts the next
  // substep sees, and in the 16-disk elastic gas of test_extremes_long_runs
  // that let the Gauss-Seidel passes gain energy (6.9e-5 of it over 1e5
  // frames with 4 passes on every contact, none with this restriction).
  for (std::size_t k = 0; k < rows_.size(); k += rows_[k].count == 2 ? 2 : 1)
  {
    ContactRow& row = rows_[k];
    if (!row.active || row.position_solved || (resting_only && row.target > 0.0))
    {
      continue;
    }
    const bool pair = row.count == 2;
    // Depths are taken after the corrections already made (so a stack's
    // correction travels up it in one pass instead of diffusing over many
    // substeps), and for both points of a pair before either moves (so the
    // first point's turn does not tilt the second).
    if (hold && !row.kinetic && row.mu_s > 0.0)
    {
      hold_static_friction(row, pair ? rows_[k + 1] : row);
    }
    const double first = current_depth(row);
    const double second = pair ? current_depth(rows_[k + 1]) : 0.0;
    if (pair && settings_.position_block && correct_pair(row, rows_[k + 1], first, second, softness))
    {
      continue;
    }
    correct_point(row, first, softness);
    if (pair)
    {
      correct_point(rows_[k + 1], second, softness);
    }
  }
}

void World::hold_all_static_friction(bool friction)
{
  for (std::size_t k = 0; friction && k < rows_.size(); k += rows_[k].count == 2 ? 2 : 1)
  {
    const ContactRow& row = rows_[k];
    if (row.active && !row.kinetic && row.mu_s > 0.0)
    {
      hold_static_friction(row, row.count == 2 ? rows_[k + 1] : row);
    }
  }
}

Vec2 World::integration_move(std::size_t i, Vec2 r) const
{
  // Pose change since the previous pose, shifted by this substep's
  // corrections: what the integration alone moved the material point at r.
  const Body& body = bodies_[i];
  const double turn = body.theta() - prev_theta_[i] - turned_[i];
  return body.position() - prev_position_[i] - moved_[i] + cross(turn, r);
}

void World::hold_static_friction(const ContactRow& first, const ContactRow& second)
{
  // Integration moves a resting body by its gravity kick before the
  // velocity solve stops it; on a slope part of that move runs along the
  // surface, and undone only in the normal direction it would become a creep
  // of g h sin(theta) downhill. A sticking contact therefore also takes back
  // the tangential move, as long as it stays inside the static cone of the
  // normal approach it came with (Coulomb at the position level, as XPBD's
  // static friction).
  const Vec2 ra = 0.5 * (first.ra + second.ra);
  const Vec2 rb = 0.5 * (first.rb + second.rb);
  const Vec2 slip = integration_move(first.b, rb) - integration_move(first.a, ra);
  const Vec2 t = perp(first.normal);
  const double tangential = dot(slip, t);
  const double approach = -dot(slip, first.normal);
  if (tangential == 0.0 || std::abs(tangential) > first.mu_s * std::max(0.0, approach))
  {
    return;
  }
  // The slip of a resting body is its gravity kick, a translation, so it is
  // taken back by translation: a turn would tilt the body, the normal
  // correction would level it again and leave part of the slip in place.
  const double lambda = -tangential / (first.inv_mass_a + first.inv_mass_b);
  displace(first.a, -lambda, t, ra, first.inv_mass_a, 0.0);
  displace(first.b, lambda, t, rb, first.inv_mass_b, 0.0);
}

double World::current_depth(const ContactRow& row) const
{
  const double approach = dot(moved_[row.b] - moved_[row.a], row.normal) + turned_[row.b] * cross(row.rb, row.normal) -
                          turned_[row.a] * cross(row.ra, row.normal);
  return row.penetration - approach;
}

void World::correct_point(const ContactRow& row, double depth, double softness)
{
  if (depth <= settings_.slop)
  {
    return;
  }
  // Each point of a manifold takes its share, so a pair is corrected once.
  const double k = effective_inverse_mass(row, row.normal) + softness;
  const double lambda = (depth - settings_.slop) / (row.count * k);
  // Moving the pose without touching the velocity is the previous-pose
  // shift: the correction never turns into velocity.
  displace(row.a, -lambda, row.normal, row.ra, row.inv_mass_a, row.inv_inertia_a);
  displace(row.b, lambda, row.normal, row.rb, row.inv_mass_b, row.inv_inertia_b);
}

void World::displace(std::size_t i, double lambda, Vec2 n, Vec2 r, double inv_mass, double inv_inertia)
{
  if (inv_mass == 0.0)
  {
    return;
  }
  Body& body = bodies_[i];
  const Vec2 move = (inv_mass * lambda) * n;
  body.set_position(body.position() + move);
  moved_[i] += move;
  if (inv_inertia != 0.0)
  {
    const double turn = inv_inertia * lambda * cross(r, n);
    body.set_theta(body.theta() + turn);
    turned_[i] += turn;
  }
}

void World::warm_start()
{
  for (const ContactRow& row : rows_)
  {
    if (row.active && !row.exact && (row.impulse.normal != 0.0 || row.impulse.tangent != 0.0))
    {
      apply_impulse(row, row.impulse.normal * row.normal + row.impulse.tangent * perp(row.normal));
    }
  }
}

void World::solve_velocities(bool friction)
{
  for (int pass = 0; pass < settings_.velocity_iterations; ++pass)
  {
    for (std::size_t k = 0; k < rows_.size(); k += rows_[k].count == 2 ? 2 : 1)
    {
      ContactRow& row = rows_[k];
      if (!row.active || row.exact)
      {
        continue;
      }
      const bool rough = friction && (row.mu_s > 0.0 || row.mu_k > 0.0);
      if (row.count == 2)
      {
        solve_pair(row, rows_[k + 1], rough);
        continue;
      }
      solve_normal(row);
      if (rough)
      {
        solve_friction(row);
      }
    }
  }
}

void World::solve_normal(ContactRow& row)
{
  const double vn = dot(relative_velocity(row), row.normal);
  // Accumulated impulse stays >= 0: a contact pushes, never pulls.
  const double total = std::max(0.0, row.impulse.normal + (row.target - vn) * row.normal_mass);
  const double change = total - row.impulse.normal;
  row.impulse.normal = total;
  apply_impulse(row, change * row.normal);
}

void World::solve_friction(ContactRow& row)
{
  const Vec2 t = perp(row.normal);
  const double vt = dot(relative_velocity(row), t);
  const double total = coulomb(row, row.impulse.tangent - vt * row.tangent_mass, row.impulse.normal);
  const double change = total - row.impulse.tangent;
  row.impulse.tangent = total;
  apply_impulse(row, change * t);
}

double World::coulomb(ContactRow& row, double needed, double normal_impulse)
{
  // A contact that stuck in the previous substep holds up to the static
  // cone; past it, it is clamped there and slides from the next substep on,
  // at the kinetic bound, until the impulse that stops it fits inside the
  // kinetic cone again. (Deciding stick or slip from one Gauss-Seidel pass's
  // estimate instead lets a transient overshoot drop a sticking contact to
  // the kinetic bound, from where it never recovers.)
  const double limit = (row.kinetic ? row.mu_k : row.mu_s) * normal_impulse;
  row.sliding = std::abs(needed) > limit;
  return std::max(-limit, std::min(limit, needed));
}

void World::solve_friction_pair(ContactRow& first, ContactRow& second)
{
  // Both points of a manifold lie on one face: they share the tangent and,
  // for a rigid pair, the tangential slip speed, so two per-point friction
  // rows would be one constraint twice, with no unique split and a stick/slip
  // flip when one point's share hits its own cone. The pair is solved as one
  // row at the midpoint against the cone of the summed normal impulse, and
  // the result is split in proportion to the normal impulses, which keeps
  // each point inside its own cone.
  const Vec2 t = perp(first.normal);
  const Vec2 ra = 0.5 * (first.ra + second.ra);
  const Vec2 rb = 0.5 * (first.rb + second.rb);
  const double vt = dot(relative_velocity_at(first, ra, rb), t);
  const double normal_sum = first.impulse.normal + second.impulse.normal;
  const double old_total = first.impulse.tangent + second.impulse.tangent;
  const double total = coulomb(first, old_total - vt * first.pair_tangent_mass, normal_sum);
  second.sliding = first.sliding;
  apply_impulse_at(first, ra, rb, (total - old_total) * t);
  const double share = normal_sum > 0.0 ? first.impulse.normal / normal_sum : 0.5;
  first.impulse.tangent = share * total;
  second.impulse.tangent = total - first.impulse.tangent;
}

void World::apply_impulse(const ContactRow& row, Vec2 impulse)
{
  apply_impulse_at(row, row.ra, row.rb, impulse);
}

void World::apply_impulse_at(const ContactRow& row, Vec2 ra, Vec2 rb, Vec2 impulse)
{
  Body& a = bodies_[row.a];
  Body& b = bodies_[row.b];
  if (row.inv_mass_a != 0.0)
  {
    a.set_velocity(a.velocity() - row.inv_mass_a * impulse);
    a.set_omega(a.omega() - row.inv_inertia_a * cross(ra, impulse));
  }
  if (row.inv_mass_b != 0.0)
  {
    b.set_velocity(b.velocity() + row.inv_mass_b * impulse);
    b.set_omega(b.omega() + row.inv_inertia_b * cross(rb, impulse));
  }
}

double World::velocity_residual() const
{
  double worst = 0.0;
  for (const ContactRow& row : rows_)
  {
    if (!row.active)
    {
      continue;
    }
    const double gap = dot(relative_velocity(row), row.normal) - row.target;
    // A pushing contact must meet its target exactly; an idle one only
    // must not approach faster than it allows.
    const double residual = row.impulse.normal > 0.0 ? std::abs(gap) : std::max(0.0, -gap);
    worst = std::max(worst, residual);
  }
  return worst;
}

}  // namespace collision2d
