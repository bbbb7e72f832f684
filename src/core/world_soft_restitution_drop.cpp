// Restitution's way back (world_soft_restitution.cpp calls it at each
// substep's end). Restitution drives its points with normal impulses only,
// friction left out, so in a wedge that a moving kinematic body closes a
// jammed body has no way out but sideways, at the wedge's exit speed: the
// passes either find no fixed point, or find that exit (a disk thrown at
// 2260 m/s, a polygon at 1052 m/s from 55 m/s, in random worlds with a
// spinning bar). Each group of bodies that the restituted points join in
// which a point still misses its target, or whose velocity restitution
// changed far beyond its targets, goes back to the velocities and impulses the relax left, as if
// nothing in it could bounce this substep. Other groups keep their bounces.
#include <algorithm>
#include <cmath>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Whether restitution changed the relative velocity at the saved point by more than `bound` (m/s).
bool changed_more_than(const SavedImpulses& saved, const ContactPoint& p, const std::vector<BodyVelocity>& velocity,
                       double bound)
{
  return length(relative_velocity(p, velocity) - saved.relative) > bound;
}
}  // namespace

void WorldImpl::drop_wild_bounces(bool settled, double change_bound)
{
  const bool any_wild = std::any_of(bounce_start_.begin(), bounce_start_.end(), [&](const SavedImpulses& saved) {
    return changed_more_than(saved, points_[saved.point], velocity_, change_bound);
  });
  if (settled && !any_wild)
  {
    return;  // the common case: nothing to group
  }
  group_restituted_bodies();
  if (mark_wild_groups(settled, change_bound))
  {
    take_back_dropped_bounces();
  }
}

/// Marks the groups to drop in bounce_dropped_; true when there is one.
/// Residuals count only at the points restitution aims (bouncing, held);
/// velocity changes at every restituted point, the released ones too.
bool WorldImpl::mark_wild_groups(bool settled, double change_bound)
{
  bool marked = false;
  const auto mark_if = [&](std::size_t k, bool wild) {
    if (wild)
    {
      bounce_dropped_[bounce_group_of(points_[k])] = 1;
      marked = true;
    }
  };
  const auto missed = [&](std::size_t k) {
    return !settled && normal_residual(points_[k], velocity_) > settings_.restitution_threshold;
  };
  for (std::size_t i : bouncing_)
  {
    mark_if(bounce_points_[i].point, missed(bounce_points_[i].point));
  }
  for (const HeldPoint& held : held_)
  {
    mark_if(held.point, missed(held.point));
  }
  for (const SavedImpulses& saved : bounce_start_)
  {
    mark_if(saved.point, changed_more_than(saved, points_[saved.point], velocity_, change_bound));
  }
  return marked;
}

/// Every velocity change of restitution is an impulse at one of its points
/// (released, driven, or friction trimmed): taking back the difference puts
/// a dropped group's bodies back where the relax left them.
void WorldImpl::take_back_dropped_bounces()
{
  for (const SavedImpulses& saved : bounce_start_)
  {
    ContactPoint& p = points_[saved.point];
    if (bounce_dropped_[bounce_group_of(p)] != 0)
    {
      const Vec2 back = (saved.normal - p.lambda_n) * p.normal + (saved.tangent - p.lambda_t) * p.tangent();
      apply_impulse(p, back, velocity_);
      p.lambda_n = saved.normal;
      p.lambda_t = saved.tangent;
    }
  }
}

/// bounce_group_: union-find over the bodies of the points restitution
/// drives, two dynamic bodies joined by each point between them (static
/// and kinematic bodies join nothing); bounce_dropped_ cleared for them.
void WorldImpl::group_restituted_bodies()
{
  bounce_group_.resize(bodies_.size());
  bounce_dropped_.resize(bodies_.size());
  for (const SavedImpulses& saved : bounce_start_)
  {
    const ContactPoint& p = points_[saved.point];
    for (const std::size_t body : {p.a, p.b})
    {
      bounce_group_[body] = body;
      bounce_dropped_[body] = 0;
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
