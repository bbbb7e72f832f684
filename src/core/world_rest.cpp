// A world at rest: every dynamic body asleep and no kinematic body moving.
// Such a frame moves nothing, and the contacts it publishes are the ones it
// carried in, so once one whole frame has started and ended at rest, every
// later frame would repeat it bit for bit until something changes the world
// (any World call that edits it bumps version_). Those frames are replayed:
// the clock advances and the rest frame's report is added again. A step made
// only of them keeps nothing aside and checks nothing (the state does not
// change), and closes with the rest state's figures, so a settled world costs
// next to nothing per step.
#include <algorithm>
#include <atomic>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
std::atomic<bool> g_replay_enabled{true};
std::atomic<std::uint64_t> g_replayed_frames{0};
}  // namespace

void set_rest_replay_enabled(bool enabled) { g_replay_enabled.store(enabled, std::memory_order_relaxed); }

std::uint64_t replayed_rest_frames() { return g_replayed_frames.load(std::memory_order_relaxed); }

bool WorldImpl::at_rest() const
{
  if (movers_current())
  {
    return movers_.empty();
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (bodies_[i].type() == BodyType::Dynamic ? !asleep_[i] : is_mover(i))
    {
      return false;
    }
  }
  return true;
}

bool WorldImpl::replay_rest_frame(StepReport& report)
{
  if (!rest_known_ || rest_version_ != version_ || !g_replay_enabled.load(std::memory_order_relaxed))
  {
    return false;
  }
  add_frame(report, rest_frame_);
  time_ += settings_.dt;
  ++frame_count_;
  g_replayed_frames.fetch_add(1, std::memory_order_relaxed);
  return true;
}

bool WorldImpl::replay_rest_step(int frames, StepReport& report)
{
  // replay_rest_frame checks the rest still holds; its answer is the same for
  // every frame of the step, so a refusal comes before anything is replayed.
  if (!rest_finish_known_)
  {
    return false;
  }
  for (int f = 0; f < frames; ++f)
  {
    if (!replay_rest_frame(report))
    {
      return false;
    }
  }
  report.max_penetration = rest_finish_.max_penetration;
  report.kinetic_energy = rest_finish_.kinetic_energy;
  report.sleeping_bodies = rest_finish_.sleeping_bodies;
  return true;
}

void WorldImpl::note_finish(const StepReport& report)
{
  rest_finish_known_ = rest_known_ && rest_version_ == version_;
  rest_finish_ = report;
}

void WorldImpl::note_frame(bool started_at_rest, const StepReport& frame)
{
  rest_finish_known_ = false;  // the step this frame is in has not closed yet
  rest_known_ = started_at_rest && at_rest();
  rest_version_ = version_;
  rest_frame_ = frame;
}

void WorldImpl::add_frame(StepReport& total, const StepReport& frame)
{
  total.frames += frame.frames;
  total.substeps += frame.substeps;
  total.contact_count = frame.contact_count;
  total.active |= frame.active;
  total.max_detected_penetration = std::max(total.max_detected_penetration, frame.max_detected_penetration);
  total.velocity_residual = std::max(total.velocity_residual, frame.velocity_residual);
  total.warm_substep_residual = frame.warm_substep_residual;
  total.swept_bodies += frame.swept_bodies;
  total.toi_clamps += frame.toi_clamps;
  total.exact_islands += frame.exact_islands;
  total.exact_fallbacks += frame.exact_fallbacks;
}

}  // namespace detail
}  // namespace collision2d
