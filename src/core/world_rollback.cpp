// What a step keeps aside so that a step refused part way (an overflow, a
// failed allocation) leaves the World exactly as it was (world_rollback.h).
#include <algorithm>

#include "scratch_buffer.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Copies `from` into `to`, growing `to` geometrically: a plain assignment
/// allocates the exact size, so a count that creeps up would allocate each
/// time. The workers copy a long list in parts.
template <typename T, typename Allocator>
void keep_copy(const std::vector<T, Allocator>& from, std::vector<T, Allocator>& to, WorkerPool& workers)
{
  resize_to_overwrite(to, from.size());
  workers.parallel_for(from.size(), kMinSharedPoints, [&](std::size_t begin, std::size_t end) {
    std::copy(from.begin() + static_cast<std::ptrdiff_t>(begin), from.begin() + static_cast<std::ptrdiff_t>(end),
              to.begin() + static_cast<std::ptrdiff_t>(begin));
  });
}
}  // namespace

void WorldImpl::save_motion(int frames)
{
  // Only what a step changes is kept aside (no outlines, no scratch), in
  // buffers that keep their capacity from step to step.
  // While the movers stay the movers only they change; the first change of
  // what sleeps keeps the others too (keep_sleeping_for_rollback).
  rollback_.movers_only = movers_current();
  rollback_.motion.resize(bodies_.size());
  rollback_.rest_time.resize(bodies_.size());
  const std::size_t count = rollback_.movers_only ? movers_.size() : bodies_.size();
  workers_.parallel_for(count, kMinSharedBodies, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      keep_body(rollback_.movers_only ? movers_[k] : k);
    }
  });
  // A step that publishes its contacts once leaves the contacts it started
  // from untouched until that publish (detection only reads them), and
  // checks its bodies are finite before it: no copy is needed.
  const int publishes = frames * (settings_.soft_step ? 1 : settings_.substeps);
  rollback_.contacts_in_place = publishes == 1;
  rollback_.contacts_published = false;
  if (!rollback_.contacts_in_place)
  {
    keep_copy(contacts_, rollback_.contacts, workers_);
  }
  rollback_.asleep = asleep_;
  rollback_.active = true;
  rollback_.sleeping_kept = false;
  rollback_.time = time_;
  rollback_.frame_count = frame_count_;
  rollback_.cache_h = cache_h_;
  // The next detection keeps a body stopped at its time of impact touching.
  rollback_.clamping = clamping_;
  if (clamping_)
  {
    rollback_.toi = toi_;
  }
  // A prediction reads the previous substep's points (world_warm_integration.cpp).
  if (settings_.warm_start_before_integration)
  {
    keep_copy(points_, rollback_.points, workers_);
  }
}

void WorldImpl::keep_body(std::size_t i)
{
  const Body& b = bodies_[i];
  rollback_.motion[i] = {b.position(), b.theta(), b.velocity(), b.omega()};
  rollback_.rest_time[i] = rest_time_[i];
}

void WorldImpl::restore_motion()
{
  rest_known_ = false;  // the rest frame remembered may be one this step made
  // What the step keeps from frame to frame only to save work may be half
  // rebuilt: the next step builds it afresh (the same pairs and movers).
  resting_built_ = false;
  fat_pairs_.forget();
  const std::size_t count = rollback_.movers_only ? movers_.size() : bodies_.size();
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::size_t i = rollback_.movers_only ? movers_[k] : k;
    Body& b = bodies_[i];
    const BodyMotion& m = rollback_.motion[i];
    b.set_position(m.position);
    b.set_theta(m.theta);
    b.set_velocity(m.velocity);
    b.set_omega(m.omega);
    rest_time_[i] = rollback_.rest_time[i];
  }
  if (!rollback_.contacts_in_place)
  {
    contacts_.swap(rollback_.contacts);
  }
  asleep_.swap(rollback_.asleep);
  ++sleep_stamp_;
  rollback_.active = false;
  if (rollback_.sleeping_kept)
  {
    sleeping_contacts_.swap(rollback_.sleeping_contacts);
    sleeping_penetration_ = rollback_.sleeping_penetration;
    island_label_.swap(rollback_.island_label);
    next_island_label_ = rollback_.next_island_label;
  }
  time_ = rollback_.time;
  frame_count_ = rollback_.frame_count;
  cache_h_ = rollback_.cache_h;
  clamping_ = rollback_.clamping;
  if (clamping_)
  {
    toi_.swap(rollback_.toi);
  }
  if (settings_.warm_start_before_integration)
  {
    points_.swap(rollback_.points);
  }
}

}  // namespace detail
}  // namespace collision2d
