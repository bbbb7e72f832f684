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
    // With rotation off, bodies are modelled as not turning at all.
    row.inv_inertia_a = effects.rotation ? a.inv_inertia() : 0.0;
    row.inv_inertia_b = effects.rotation ? b.inv_inertia() : 0.0;
    const Vec2 t = perp(row.normal);
    row.normal_mass = 1.0 / effective_inverse_mass(row, row.normal);
    row.tangent_mass = 1.0 / effective_inverse_mass(row, t);
    const Material& ma = materials_[row.a];
    const Material& mb = materials_[row.b];
    row.mu_s = effects.friction ? min_of(ma.static_friction, mb.static_friction) : 0.0;
    row.mu_k = effects.friction ? min_of(ma.kinetic_friction, mb.kinetic_friction) : 0.0;
    // The approach speed is taken before the position solve and kept fixed
    // through the iterations; below the threshold a contact just rests.
    const double e = effects.restitution ? min_of(ma.restitution, mb.restitution) : 0.0;
    const double approach = -dot(relative_velocity(row), row.normal);
    row.target = e > 0.0 && approach > threshold ? e * approach : 0.0;
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
  const Body& a = bodies_[row.a];
  const Body& b = bodies_[row.b];
  return b.velocity() + cross(b.omega(), row.rb) - a.velocity() - cross(a.omega(), row.ra);
}

void World::correct_positions(double h)
{
  const double softness = settings_.compliance / (h * h);
  const double slop = settings_.slop;
  for (const ContactRow& row : rows_)
  {
    if (!row.active || row.penetration <= slop)
    {
      continue;
    }
    // Each point of a manifold takes its share, so a pair is corrected once.
    const double k = effective_inverse_mass(row, row.normal) + softness;
    const double lambda = (row.penetration - slop) / (row.count * k);
    // Moving the pose without touching the velocity is the previous-pose
    // shift: the correction never turns into velocity.
    displace(row.a, -lambda, row.normal, row.ra, row.inv_mass_a, row.inv_inertia_a);
    displace(row.b, lambda, row.normal, row.rb, row.inv_mass_b, row.inv_inertia_b);
  }
}

void World::displace(std::size_t i, double lambda, Vec2 n, Vec2 r, double inv_mass, double inv_inertia)
{
  Body& body = bodies_[i];
  if (inv_mass == 0.0)
  {
    return;
  }
  body.set_position(body.position() + (inv_mass * lambda) * n);
  if (inv_inertia != 0.0)
  {
    body.set_theta(body.theta() + inv_inertia * lambda * cross(r, n));
  }
}

void World::warm_start()
{
  for (const ContactRow& row : rows_)
  {
    if (row.active && (row.impulse.normal != 0.0 || row.impulse.tangent != 0.0))
    {
      apply_impulse(row, row.impulse.normal * row.normal + row.impulse.tangent * perp(row.normal));
    }
  }
}

void World::solve_velocities(bool friction)
{
  for (int pass = 0; pass < settings_.velocity_iterations; ++pass)
  {
    for (ContactRow& row : rows_)
    {
      if (!row.active)
      {
        continue;
      }
      solve_normal(row);
      if (friction && (row.mu_s > 0.0 || row.mu_k > 0.0))
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
  const double needed = row.impulse.tangent - vt * row.tangent_mass;
  // Coulomb: stick when the impulse that stops sliding is inside the static
  // cone, otherwise slide at the kinetic bound against the motion.
  const double stick_limit = row.mu_s * row.impulse.normal;
  const double slide_limit = row.mu_k * row.impulse.normal;
  const double total = std::abs(needed) <= stick_limit ? needed : std::max(-slide_limit, std::min(slide_limit, needed));
  const double change = total - row.impulse.tangent;
  row.impulse.tangent = total;
  apply_impulse(row, change * t);
}

void World::apply_impulse(const ContactRow& row, Vec2 impulse)
{
  Body& a = bodies_[row.a];
  Body& b = bodies_[row.b];
  if (row.inv_mass_a != 0.0)
  {
    a.set_velocity(a.velocity() - row.inv_mass_a * impulse);
    a.set_omega(a.omega() - row.inv_inertia_a * cross(row.ra, impulse));
  }
  if (row.inv_mass_b != 0.0)
  {
    b.set_velocity(b.velocity() + row.inv_mass_b * impulse);
    b.set_omega(b.omega() + row.inv_inertia_b * cross(row.rb, impulse));
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
