// WorldSettings::warm_start_before_integration: the poses of step 1 advance
// with a velocity predicted from the previous substep's contacts.
//
// In the Fx2D order a resting body is moved by its gravity kick g h^2 before
// the velocity solve cancels the kick, and the position passes must lift it
// back; a Gauss-Seidel pass carries that lift up a tall stack only in part.
// Here the previous substep's contact rows are warm-started with the
// impulses they carried and solved once more (with rest targets) before the
// poses move, so a resting body's kick is cancelled first and it stays where
// it rests; Box2D moves its poses with solved velocities in the same way.
//
// Warm-starting alone is not enough: a box on two points carries its weight
// in a split the Gauss-Seidel passes leave undetermined, and the split they
// end on changes from substep to substep. Moving a pose with the impulses of
// the previous split (not solved against each other) rocked the base-20
// pyramid at 4x2 until its top slid off (0.46 m in 10 s). The solve makes the
// predicted velocity consistent with the contacts (0.15 m: at 4x2 the pyramid
// still rattles, see WorldSettings), and it takes an impact's
// impulse back (the contact now separates), where warm-starting alone would
// lift the body by (1 + e) v h.
//
// Only the poses change: after detection every velocity is set back to its
// value after the gravity kick, so the Newton targets (measured before any
// impulse of the substep), the warm start of the velocity solve, the friction
// state and a cached contact that detection does not find again are exactly
// those of the default order.

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
  return row.a < ids_.size() && row.b < ids_.size() && ids_[row.a] == cache_[k].a && ids_[row.b] == cache_[k].b;
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
  if (points_.size() != cache_.size())
  {
    return;
  }
  // The same rescaling to this substep's length as detection applies.
  const double scale = settings_.warm_start_factor * ctx.h / cache_h_;
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    ContactPoint& row = points_[k];
    // Rows of bodies that fell asleep since are carried, as in detection.
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
