// The soft step's restitution, when it may not keep its answer: a group of
// bodies its points join goes back to the velocities and impulses the relax
// left, as if nothing in it could bounce this substep
// (world_soft_restitution.cpp drives the points; this file takes it back).
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
/// The passes found no fixed point. Restitution leaves friction out, and a
/// disk squeezed by a kinematic body against a static one, jammed by
/// friction, has none without it short of the speed the wedge's angle gives
/// (thrown at 2260 m/s in a random world). Each group of bodies that the
/// points join in which a point still misses its target by more than
/// `restitution_threshold` goes back to the velocities and impulses the
/// relax left, as if nothing in it could bounce this substep.
void WorldImpl::drop_unsettled_bounces()
{
  group_restituted_bodies();
  bool dropped = false;
  const auto mark = [&](std::size_t k) {
    const ContactPoint& p = points_[k];
    if (normal_residual(p, velocity_) > settings_.restitution_threshold)
    {
      bounce_dropped_[bounce_group_of(p)] = 1;
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
  if (!dropped)
  {
    return;
  }
  // Every velocity change of restitution is an impulse at one of its points
  // (released, driven, or friction trimmed): taking back the difference
  // puts the group's bodies back where the relax left them.
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
