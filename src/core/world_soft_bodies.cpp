// The soft step's bodies (world_soft_step.cpp lists the stages): their
// poses and velocities at prepare, each substep's gravity and move on the
// frame's own copies, and those copies placed back on the bodies once a frame.
#include <algorithm>
#include <atomic>
#include <cmath>

#include "world_motion.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// A touching polygon turns at most this much per substep (rad): the frame's
/// contacts follow its pose from lever arms fixed at prepare, which a faster
/// spin would swing through the surface it touches (a disk's do not swing).
constexpr double kMaxTurnPerSubstep = 0.25 * 3.14159265358979323846;
}  // namespace

void WorldMotion::prepare_soft_bodies(bool rotation)
{
  const std::size_t n = bodies_.size();
  if (swept_reach_sq_.size() != n)  // only here are these sized, all together
  {
    velocity_.resize(n);
    stopped_.resize(n);
    touching_.resize(n);
    held_position_.resize(n);
    held_theta_.resize(n);
    prepared_position_.resize(n);
    prepared_theta_.resize(n);
    frame_position_.resize(n);
    frame_theta_.resize(n);
    frame_motion_.resize(n);
    swept_reach_sq_.resize(n);
  }
  // One pass over the body records, which a large world streams from memory.
  sweep_every_body_ = !sweep_candidates_pay();            // world_sweep_marks.cpp
  const bool candidates = !sweep_every_body_;
  if (candidates)
  {
    swept_.resize(bodies_.size());
  }
  const FreeSpeedBound bound =
      candidates ? free_speed_bound(settings_.dt / settings_.substeps, rotation) : FreeSpeedBound{};
  std::atomic<bool> any_may_turn_fast{false};
  for_each_body([&](std::size_t i) {
    load_velocity(i);                                     // world_motion.cpp
    reset_body_motion(i);
    if (candidates)
    {
      swept_[i] = 0;  // each substep sets only the candidates' flags
      if (may_turn_fast(i, bound) || may_spin_fast(i, bound))
      {
        any_may_turn_fast.store(true, std::memory_order_relaxed);
      }
    }
  });
  // The frame's active points are those of the pairs that hit (detect()),
  // so the short pair list says which bodies they touch; a substep can make
  // only those fast unless a free body may turn fast on its own.
  sweep_candidates_.clear();
  for (std::size_t k = 0; k < pairs_.size(); ++k)
  {
    if (pair_touches(k))
    {
      note_touching(pairs_[k].first);                     // world_sweep_marks.cpp
      note_touching(pairs_[k].second);
    }
  }
  choose_sweep_pass(any_may_turn_fast.load());
}

void WorldMotion::reset_body_motion(std::size_t i)
{
  prepared_position_[i] = bodies_[i].position();
  prepared_theta_[i] = bodies_[i].theta();
  frame_position_[i] = bodies_[i].position();
  frame_theta_[i] = bodies_[i].theta();
  frame_motion_[i] = frame_motion(i);
  stopped_[i] = false;
  touching_[i] = false;
  swept_reach_sq_[i] = sweep_reach_sq(i);
}

void WorldMotion::integrate_velocities(const StepContext& ctx, bool first)
{
  const Vec2 gravity_kick = settings_.gravity * ctx.h;
  const double max_spin = kMaxTurnPerSubstep * ctx.inv_h;
  // After the first substep a body no contact touches has had this kick in
  // the last move pass (integrate_positions), while its velocity was in cache.
  for_each_body([&](std::size_t i) {
    if ((first || touching_[i]) && frame_motion_[i] == FrameMotion::Dynamic)
    {
      velocity_[i].v = velocity_[i].v + gravity_kick;
      if (touching_[i] && !disk_[i])  // a disk's contacts do not swing (follow_pose)
      {
        velocity_[i].omega = std::clamp(velocity_[i].omega, -max_spin, max_spin);
      }
    }
  });
}

bool WorldMotion::integrate_positions(StepContext& ctx, StepReport& report, bool last)
{
  // As advance() (world_step.cpp): fast bodies swept for time of impact
  // (world_toi.cpp, on one thread: it pairs bodies), then every body moved
  // with its velocity, shared among the workers. A body stopped at its time
  // of impact stays there for the rest of the frame, velocity kept: no
  // contact stops it before the next frame's collide finds the touching pair.
  const bool swept = sweep(ctx.h, report, false, ctx.effects.rotation);  // world_toi.cpp
  ctx.effects.time_of_impact = ctx.effects.time_of_impact || swept;
  poses_pending_ = true;
  const Vec2 gravity_kick = settings_.gravity * ctx.h;
  const bool kick_free = !last;
  std::atomic<bool> far{false};
  // The poses stay in frame_position_ and frame_theta_ and go onto the
  // bodies once per frame (place_bodies), as do the velocities: a substep
  // reads and writes no body record, which a large world streams from memory.
  // Inlined by request: the crossing check made the compiler call it per body.
  for_each_body([&](std::size_t i) __attribute__((always_inline)) {
    move_in_frame(i, ctx, swept);
    follow_body(i, ctx);
    if (kick_free && !touching_[i] && frame_motion_[i] == FrameMotion::Dynamic)
    {
      // Nothing reads its velocity before the next substep's kick would.
      velocity_[i].v = velocity_[i].v + gravity_kick;
    }
    // Checked while the poses are in cache: stop_static_crossings is rarely needed.
    if (last && moved_far_in_frame(i))
    {
      far.store(true, std::memory_order_relaxed);
    }
  });
  return far.load();
}

void WorldMotion::move_in_frame(std::size_t i, const StepContext& ctx, bool swept)
{
  // move_body's arithmetic on the frame's poses, the velocities the solver left.
  const FrameMotion motion = frame_motion_[i];
  if (motion == FrameMotion::Still)
  {
    return;
  }
  const BodyVelocity& state = velocity_[i];
  const double travel = swept ? toi_[i] * ctx.h : ctx.h;
  frame_position_[i] = frame_position_[i] + state.v * travel;
  if (turns(ctx, motion, state.omega))
  {
    frame_theta_[i] = frame_theta_[i] + state.omega * turn_time(i, ctx, swept);
  }
}

std::size_t WorldMotion::place_bodies(bool velocities)
{
  const bool poses = poses_pending_;
  poses_pending_ = false;
  std::atomic<std::size_t> first_bad{bodies_.size()};
  if (!poses && !velocities)
  {
    return first_bad.load();
  }
  for_each_body([&](std::size_t i) {
    Body& b = bodies_[i];
    if (velocities)
    {
      store_velocity(i);                                  // world_motion.cpp
    }
    if (poses)
    {
      if (frame_motion_[i] != FrameMotion::Still)
      {
        b.set_position(frame_position_[i]);
      }
      const double theta = frame_theta_[i];
      if (theta != b.theta() || std::signbit(theta) != std::signbit(b.theta()))
      {
        b.set_theta(theta);
      }
    }
    // Checked here while the record is in cache: a pass over the bodies fewer.
    note_non_finite(i, first_bad);
  });
  return first_bad.load();
}

/// After move_body: a stopped body held, a free one on its parabola,
/// and the pose change its contacts follow.
void WorldMotion::follow_body(std::size_t i, const StepContext& ctx)
{
  Vec2& position = frame_position_[i];
  if (stopped_[i])
  {
    position = held_position_[i];
    frame_theta_[i] = held_theta_[i];
    return;
  }
  if (clamped(i))
  {
    stopped_[i] = true;
    held_position_[i] = position;
    held_theta_[i] = frame_theta_[i];
  }
  else if (!touching_[i] && frame_motion_[i] == FrameMotion::Dynamic)
  {
    // In free flight the substep's mean velocity is the end one less half
    // its gravity kick: a thrown body follows its parabola exactly.
    position = position - (0.5 * ctx.h * ctx.h) * settings_.gravity;
  }
  if (touching_[i])  // only contact points read a body's motion since prepare
  {
    follow_pose(i);
  }
}

}  // namespace detail
}  // namespace collision2d
