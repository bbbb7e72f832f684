// The soft step's restitution, when it may not keep its answer: a group of
// bodies its points join goes back to the velocities and impulses the relax
// left, as if nothing in it could bounce this substep
// (world_soft_restitution.cpp drives the points; this file takes it back).
//
// Two answers are dropped. One where the passes found no fixed point:
// restitution leaves friction out, and a disk squeezed by a kinematic body
// against a static one, jammed by friction, has none without it short of the
// speed the wedge's angle gives (thrown at 2260 m/s in a random world). And
// one that makes energy where no moving kinematic body can have given it:
// Newton's rule on a jammed chain of bodies can have a fixed point far from
// any real bounce (a 0.16 kg polygon between a wall and a light box that a
// 50 kg box pressed, thrown at 1180 m/s).
#include <algorithm>
#include <cmath>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Restitution may give a group back the kinetic energy the substep's solve
/// took, plus this fraction of what it had when the solve began. One bounce
/// gives back at most what its solve took (e <= 1); the fixed points dropped
/// here gave back tens of times what the group had.
constexpr double kBounceEnergyMargin = 1.0;

double body_kinetic_energy(const BodyVelocity& b)
{
  const double linear = b.inv_mass > 0.0 ? 0.5 * dot(b.v, b.v) / b.inv_mass : 0.0;
  const double angular = b.inv_inertia > 0.0 ? 0.5 * b.omega * b.omega / b.inv_inertia : 0.0;
  return linear + angular;
}
}  // namespace

void WorldImpl::drop_bounces(bool unsettled)
{
  group_restituted_bodies();
  const bool any_unsettled = unsettled && mark_unsettled_groups();
  const bool any_energetic = mark_energetic_groups();
  if (!any_unsettled && !any_energetic)
  {
    return;
  }
  // Every velocity change of restitution is an impulse at one of its points
  // (released, driven, or friction trimmed): taking back the difference
  // puts the group's bodies back where the relax left them.
  for (const SavedImpulses& saved : bounce_start_)
  {
    ContactPoint& p = points_[saved.point];
    if (bounce_groups_[bounce_group_of(p)].dropped)
    {
      const Vec2 back = (saved.normal - p.lambda_n) * p.normal + (saved.tangent - p.lambda_t) * p.tangent();
      apply_impulse(p, back, velocity_);
      p.lambda_n = saved.normal;
      p.lambda_t = saved.tangent;
    }
  }
}

/// The groups in which a point still misses its target by more than
/// `restitution_threshold`; whether there are any.
bool WorldImpl::mark_unsettled_groups()
{
  bool dropped = false;
  const auto mark = [&](std::size_t k) {
    const ContactPoint& p = points_[k];
    if (normal_residual(p, velocity_) > settings_.restitution_threshold)
    {
      bounce_groups_[bounce_group_of(p)].dropped = true;
      dropped = true;
    }
  };
  for (std::size_t i : bouncing_)
  {
    mark(bounce_points_[i].point);
  }
  for (const HeldPoint& held : held_)
  {
    mark(held.point);
  }
  return dropped;
}

/// The groups, no moving kinematic body among them, whose restitution gave
/// back more kinetic energy than kBounceEnergyMargin allows; whether there
/// are any. The work at a point is its impulse change times the mean of its
/// relative velocities before and after; summed over a group, the kinetic
/// energy restitution gave it (a moving kinematic body would add its own).
/// Gravity may add the free fall over a gap a bounce skips: the group's mass
/// at its fastest target.
bool WorldImpl::mark_energetic_groups()
{
  for (const SavedImpulses& saved : bounce_start_)
  {
    const ContactPoint& p = points_[saved.point];
    BounceGroup& group = bounce_groups_[bounce_group_of(p)];
    const Vec2 impulse = (p.lambda_n - saved.normal) * p.normal + (p.lambda_t - saved.tangent) * p.tangent();
    group.work += 0.5 * dot(impulse, saved.velocity + relative_velocity(p, velocity_));
    group.target = std::max(group.target, std::abs(p.target));
    for (const std::size_t body : {p.a, p.b})
    {
      if (awake_dynamic(body) && !bounce_groups_[body].counted)
      {
        bounce_groups_[body].counted = true;
        group.mass += bodies_[body].mass();
        group.energy_start += body_kinetic_energy(solve_start_[body]);
        group.energy_after += body_kinetic_energy(velocity_[body]);
      }
      group.kinematic = group.kinematic || moving_kinematic(body);
    }
  }
  bool dropped = false;
  for (const SavedImpulses& saved : bounce_start_)
  {
    BounceGroup& group = bounce_groups_[bounce_group_of(points_[saved.point])];
    const double taken = group.energy_start - (group.energy_after - group.work);  // by the solve
    const double allowed = std::max(0.0, taken) + kBounceEnergyMargin * group.energy_start +
                           0.5 * group.mass * group.target * group.target;
    if (!group.kinematic && group.work > allowed)
    {
      group.dropped = true;
      dropped = true;
    }
  }
  return dropped;
}

/// bounce_group_: union-find over the bodies of the points restitution
/// drives, two dynamic bodies joined by each point between them (static
/// and kinematic bodies join nothing); bounce_groups_ cleared for them.
void WorldImpl::group_restituted_bodies()
{
  bounce_group_.resize(bodies_.size());
  bounce_groups_.resize(bodies_.size());
  for (const SavedImpulses& saved : bounce_start_)
  {
    const ContactPoint& p = points_[saved.point];
    for (const std::size_t body : {p.a, p.b})
    {
      bounce_group_[body] = body;
      bounce_groups_[body] = BounceGroup{};
    }
  }
  for (const SavedImpulses& saved : bounce_start_)
  {
    const ContactPoint& p = points_[saved.point];
    if (awake_dynamic(p.a) && awake_dynamic(p.b))
    {
      bounce_group_[island_root(bounce_group_, p.a)] = island_root(bounce_group_, p.b);
    }
  }
}

/// The group of a restituted point: its dynamic body's.
std::size_t WorldImpl::bounce_group_of(const ContactPoint& p)
{
  return island_root(bounce_group_, awake_dynamic(p.a) ? p.a : p.b);
}

}  // namespace detail
}  // namespace collision2d
