// Sleeping of resting islands. An island is a set of dynamic bodies linked by
// contacts (static bodies do not link islands: a floor would merge every
// stack on it). It falls asleep when every member has rested (speed below
// the thresholds) for sleep_time and no moving kinematic body touches it;
// asleep bodies are not integrated or solved. A moving body touching one
// wakes it during detection, and the rest of its island wakes here at the end
// of the frame, because the woken member has not rested long enough.
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];  // path halving keeps the trees flat
    i = parent[i];
  }
  return i;
}

}  // namespace

void WorldImpl::update_sleep()
{
  const std::size_t n = bodies_.size();
  update_rest_times();
  island_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    island_[i] = i;
  }
  for (const ContactPoint& row : points_)
  {
    const bool dynamic_a = bodies_[row.a].type() == BodyType::Dynamic;
    const bool dynamic_b = bodies_[row.b].type() == BodyType::Dynamic;
    if (dynamic_a && dynamic_b)
    {
      island_[find_root(island_, row.a)] = find_root(island_, row.b);
    }
    else if (bodies_[dynamic_a ? row.b : row.a].type() == BodyType::Kinematic && is_mover(dynamic_a ? row.b : row.a))
    {
      rest_time_[dynamic_a ? row.a : row.b] = 0.0;  // being pushed is not resting
    }
  }
  island_awake_.assign(n, false);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (bodies_[i].type() == BodyType::Dynamic && rest_time_[i] < settings_.sleep_time)
    {
      island_awake_[find_root(island_, i)] = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (bodies_[i].type() != BodyType::Dynamic)
    {
      continue;
    }
    const bool sleep = !island_awake_[find_root(island_, i)];
    if (sleep && !asleep_[i])
    {
      bodies_[i].set_velocity(Vec2{0.0, 0.0});
      bodies_[i].set_omega(0.0);
    }
    asleep_[i] = sleep;
  }
}

void WorldImpl::update_rest_times()
{
  const double v2 = settings_.sleep_linear_speed * settings_.sleep_linear_speed;
  const double w2 = settings_.sleep_angular_speed * settings_.sleep_angular_speed;
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
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
