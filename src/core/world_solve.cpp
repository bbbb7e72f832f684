// The velocity stage of a substep (Fx2D steps 5 and 6) on the
// contact-solver kernel: velocities loaded once, points prepared with fixed
// Newton targets, warm started, solved in passes, stored back.
#include <algorithm>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{

void WorldImpl::load_velocities()
{
  velocity_.resize(bodies_.size());
  for_each_body([this](std::size_t i) { load_velocity(i); });
}

void WorldImpl::store_velocities()
{
  // Impulses never change a static or kinematic body (its points carry zero
  // inverse mass), so only dynamic bodies are written back.
  for_each_body([this](std::size_t i) { store_velocity(i); });
}

void WorldImpl::prepare_points(const ActiveEffects& effects)
{
  // Each point reads only its bodies and writes only itself; a manifold's
  // pair terms read its two points, kept on one worker.
  for_point_ranges([&](std::size_t begin, std::size_t end) { prepare_point_range(effects, begin, end); });
}

void WorldImpl::prepare_point_range(const ActiveEffects& effects, std::size_t begin, std::size_t end, bool targets)
{
  for (std::size_t k = begin; k < end; ++k)
  {
    ContactPoint& p = points_[k];
    if (!p.active)
    {
      continue;
    }
    const Body& a = bodies_[p.a];
    const Body& b = bodies_[p.b];
    if (!p.origin_known)  // else set where the point was added (set_new_origin, set_kept_origin)
    {
      p.r_a = p.point - a.position();
      p.r_b = p.point - b.position();
    }
    p.against_static = a.type() == BodyType::Static || b.type() == BodyType::Static;
    p.inv_mass_a = a.inv_mass();
    p.inv_mass_b = b.inv_mass();
    const Material& ma = materials_[p.a];
    const Material& mb = materials_[p.b];
    p.mu_s = effects.friction ? std::min(ma.static_friction, mb.static_friction) : 0.0;
    p.mu_k = effects.friction ? std::min(ma.kinetic_friction, mb.kinetic_friction) : 0.0;
    // With rotation off, bodies are modelled as not turning at all. A disk's
    // contact normal passes through its centre, so without friction it cannot
    // turn either; dropping its inertia there keeps the round-off of the lever
    // arm from spinning it.
    const bool rough = has_friction(p);
    p.inv_inertia_a = effects.rotation && (rough || a.shape() == Shape::Polygon) ? a.inv_inertia() : 0.0;
    p.inv_inertia_b = effects.rotation && (rough || b.shape() == Shape::Polygon) ? b.inv_inertia() : 0.0;
    // The soft step finds a contact as far ahead as its bodies can travel in
    // the frame. Friction acts where they meet, so a gap's arms reach each
    // body's surface, not the point midway (a disk striking rough ground
    // from 1 m was turned by a 0.5 m arm). The normal rows do not change.
    const double reach = targets ? 0.0 : surface_reach(p);
    if (reach > 0.0)
    {
      p.r_a -= reach * p.normal;
      p.r_b += reach * p.normal;
    }
    const double e = effects.restitution ? std::min(ma.restitution, mb.restitution) : 0.0;
    if (targets)
    {
      prepare_point(p, velocity_, e, settings_.restitution_threshold);
    }
    else
    {
      prepare_masses(p, e);
    }
  }
  for (std::size_t k = begin; k + 1 < end; ++k)
  {
    if (points_[k].active && points_[k].count == 2)
    {
      prepare_pair(points_[k], points_[k + 1]);
      ++k;
    }
  }
}

std::size_t WorldImpl::pair_boundary(std::size_t k) const
{
  while (k > 0 && k < points_.size() && points_[k].a == points_[k - 1].a && points_[k].b == points_[k - 1].b)
  {
    ++k;
  }
  return k;
}

void WorldImpl::warm_start()
{
  for (ContactPoint& p : points_)
  {
    if (p.active && !p.exact)
    {
      detail::warm_start(p, velocity_);
    }
  }
}

void WorldImpl::solve_velocities(bool friction)
{
  for (int pass = 0; pass < settings_.velocity_iterations; ++pass)
  {
    for_manifolds_kinematic_first([&](std::size_t k) {
      ContactPoint& p = points_[k];
      if (!p.active || p.exact)
      {
        return;
      }
      const bool rough = friction && has_friction(p);
      if (p.count == 2)
      {
        ContactPoint& q = points_[k + 1];
        if (rough && solve_stick_block(p, q, velocity_))
        {
          return;
        }
        bool changed = false;
        if (!solve_normal_block(p, q, velocity_, changed))
        {
          solve_normal(p, velocity_);
          solve_normal(q, velocity_);
        }
        if (rough)
        {
          solve_friction_pair(p, q, velocity_);
        }
        return;
      }
      solve_normal(p, velocity_);
      if (rough)
      {
        solve_friction(p, velocity_);
      }
    });
  }
}

double WorldImpl::velocity_residual() const
{
  double worst = 0.0;
  for (const ContactPoint& p : points_)
  {
    if (p.active)
    {
      worst = std::max(worst, normal_residual(p, velocity_));
    }
  }
  return worst;
}

}  // namespace detail
}  // namespace collision2d
