// A body's move over a substep, and its velocity between the body record
// and the solver's copy (world_motion.h).
#include "world_motion.h"

namespace collision2d
{
namespace detail
{
bool WorldMotion::move_body(std::size_t i, const StepContext& ctx, bool swept)
{
  const FrameMotion motion = frame_motion(i);
  if (motion == FrameMotion::Still)
  {
    return false;
  }
  Body& b = bodies_[i];
  const double travel = swept ? toi_[i] * ctx.h : ctx.h;
  b.set_position(b.position() + b.velocity() * travel);
  return turns(ctx, motion, b.omega());
}

void WorldMotion::load_velocity(std::size_t i)
{
  const Body& b = bodies_[i];
  set_body_velocity(velocity_[i], b.velocity(), b.omega(), b.inv_mass(), b.inv_inertia());
}

void WorldMotion::store_velocity(std::size_t i)
{
  if (bodies_[i].type() == BodyType::Dynamic)
  {
    bodies_[i].set_velocity(velocity_[i].v);
    bodies_[i].set_omega(velocity_[i].omega);
  }
}

}  // namespace detail
}  // namespace collision2d
