// Sleeping of resting islands. An island is a set of dynamic bodies linked by
// contacts (static bodies do not link islands: a floor would merge every
// stack on it). It falls asleep when every member has rested (speed below
// the thresholds) for sleep_time and no moving kinematic body touches it;
// asleep bodies are not integrated or solved, and their contacts are kept
// aside (world_sleeping_contacts.cpp). A moving body reaching one wakes its
// whole island during detection.
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Rest time is a sum of frames, and such sums fall short by rounding:
/// thirty frames of 1/60 s add up to 0.49999999999999994 s. A body has
/// rested sleep_time once it is within this fraction of a frame of it.
constexpr double kRestRoundingFrames = 1e-6;
}  // namespace

void WorldImpl::update_sleep()
{
  // Only the bodies this frame visits can change: the others sleep, or do
  // not move (for_each_body).
  const std::size_t n = bodies_.size();
  const std::size_t visits = visited_count();
  update_rest_times();
  island_.resize(n);
  island_awake_.resize(n);
  for (std::size_t k = 0; k < visits; ++k)
  {
    island_[visited(k)] = visited(k);
    island_awake_[visited(k)] = false;
  }
  for (const ContactPoint& row : points_)
  {
    const bool dynamic_a = bodies_[row.a].type() == BodyType::Dynamic;
    const bool dynamic_b = bodies_[row.b].type() == BodyType::Dynamic;
    if (dynamic_a && dynamic_b)
    {
      island_[island_root(island_, row.a)] = island_root(island_, row.b);
    }
    else if (bodies_[dynamic_a ? row.b : row.a].type() == BodyType::Kinematic && is_mover(dynamic_a ? row.b : row.a))
    {
      rest_time_[dynamic_a ? row.a : row.b] = 0.0;  // being pushed is not resting
    }
  }
  bool fell_asleep = false;
  const double rested_enough = settings_.sleep_time - kRestRoundingFrames * settings_.dt;
  for (std::size_t k = 0; k < visits; ++k)
  {
    const std::size_t i = visited(k);
    if (bodies_[i].type() == BodyType::Dynamic && rest_time_[i] < rested_enough)
    {
      island_awake_[island_root(island_, i)] = true;
    }
  }
  for (std::size_t k = 0; k < visits; ++k)
  {
    const std::size_t i = visited(k);
    if (bodies_[i].type() != BodyType::Dynamic)
    {
      continue;
    }
    const bool sleep = !island_awake_[island_root(island_, i)];
    if (!sleep && asleep_[i])
    {
      wake_island(island_label_[i], contacts_);           // set asleep without having rested
    }
    else if (sleep && !asleep_[i])
    {
      bodies_[i].set_velocity(Vec2{0.0, 0.0});
      bodies_[i].set_omega(0.0);
      asleep_[i] = true;
      fell_asleep = true;
    }
  }
  if (fell_asleep)
  {
    ++sleep_stamp_;
    keep_sleeping_for_rollback(false);                    // before the labels change
    label_new_sleepers();                                 // world_sleeping_contacts.cpp
    put_contacts_aside();
  }
}

void WorldImpl::make_room_to_move_contacts(std::size_t contacts)
{
  // A contact may move between the lists, and a merge's output becomes one
  // of them (merge_into swaps): each list has room for all of them. Once the
  // room is there this costs nothing.
  const std::size_t n = bodies_.size();
  const std::size_t all = contacts + sleeping_contacts_.size();
  make_room(island_, n);
  make_room(island_awake_, n);
  make_room(root_label_, n);
  make_room(rollback_.island_label, island_label_.size());
  make_room(rollback_.sleeping_contacts, sleeping_contacts_.size());
  for (std::vector<WorldContact>* list : {&contacts_, &sleeping_contacts_, &moved_contacts_, &merge_scratch_})
  {
    make_room(*list, all);
  }
}

void WorldImpl::update_rest_times()
{
  const double v2 = settings_.sleep_linear_speed * settings_.sleep_linear_speed;
  const double w2 = settings_.sleep_angular_speed * settings_.sleep_angular_speed;
  for (std::size_t k = 0; k < visited_count(); ++k)
  {
    const std::size_t i = visited(k);
    const Body& b = bodies_[i];
    if (b.type() != BodyType::Dynamic || asleep_[i])
    {
      continue;
    }
    const bool resting = length_sq(b.velocity()) <= v2 && b.omega() * b.omega() <= w2;
    rest_time_[i] = resting ? rest_time_[i] + settings_.dt : 0.0;
  }
}

}  // namespace detail
}  // namespace collision2d
