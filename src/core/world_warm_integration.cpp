// WorldSettings::warm_start_before_integration: step 1 advances the poses
// with velocities predicted from the previous substep's contacts, warm-started
// and solved once with rest targets, so a resting body's gravity kick is
// cancelled before it moves instead of being lifted back by the position
// passes. The solve matters, not the warm start alone: the split of a box's
// weight over its two points changes from substep to substep, and moving with
// an unsolved split rocks a pyramid (docs/performance.md has the figures).
// Only the poses change: after detection every velocity is set back to its
// value after the kick, so the Newton targets, the warm start, the friction
// state and the cache are exactly those of the default order.

#include "world_impl.h"

namespace collision2d
{
namespace detail
{

bool WorldImpl::previous_point_matches(std::size_t k) const
{
  // points_ still holds the previous substep's rows, which carry what the
  // cache lacks (lever arms, masses, friction state). Bodies removed since
  // shift the dense indices: such rows are left out.
  const ContactPoint& row = points_[k];
  return row.a < ids_.size() && row.b < ids_.size() && ids_[row.a] == contacts_[k].a && ids_[row.b] == contacts_[k].b;
}

void WorldImpl::predict_velocities(const StepContext& ctx)
{
  kicked_velocity_.resize(bodies_.size());
  kicked_omega_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    kicked_velocity_[i] = bodies_[i].velocity();
    kicked_omega_[i] = bodies_[i].omega();
  }
  // The rows must line up with the cache; right after an island fell asleep
  // or woke (its contacts put aside or brought back) they do not, and that
  // substep is not predicted.
  if (points_.size() != contacts_.size())
  {
    return;
  }
  // The same rescaling to this substep's length as detection applies.
  const double scale = ctx.h / cache_h_;
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    ContactPoint& row = points_[k];
    // Rows of bodies asleep now are left out, as detection leaves them out.
    row.active = row.active && previous_point_matches(k) && !asleep_[row.a] && !asleep_[row.b];
    row.lambda_n *= scale;
    row.lambda_t *= scale;
    // The prediction is of resting contacts; an impact's bounce is the
    // velocity solve's business, which measures its own approach speed.
    row.target = 0.0;
    row.exact = false;
  }
  load_velocities();
  warm_start();
  solve_velocities(ctx.effects.friction);
  store_velocities();
}

void WorldImpl::restore_velocities()
{
  for (std::size_t i = 0; i < kicked_velocity_.size() && i < bodies_.size(); ++i)
  {
    bodies_[i].set_velocity(kicked_velocity_[i]);
    bodies_[i].set_omega(kicked_omega_[i]);
  }
}

}  // namespace detail
}  // namespace collision2d
