// Detection for the substep (broad then narrow phase on fresh boxes), the
// warm-start cache keyed by (body ids, feature), and the published contacts.
#include <algorithm>

#include "collision2d/collide.h"
#include "collision2d/touch_tolerance.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Direction used for two disks whose centres coincide, where the contact
/// normal is undefined and collide() would throw mid-step: any unit vector
/// separates them, "up" is as good as another.
constexpr Vec2 kCoincidentNormal{0.0, 1.0};

bool coincident_disks(const Body& a, const Body& b)
{
  return a.shape() == Shape::Disk && b.shape() == Shape::Disk && a.position() == b.position();
}

bool pair_less(const WorldContact& c, BodyId a, BodyId b)
{
  return c.a < a || (c.a == a && c.b < b);
}

}  // namespace

bool WorldImpl::is_mover(std::size_t i) const
{
  const Body& b = bodies_[i];
  switch (b.type())
  {
    case BodyType::Dynamic:
      return !asleep_[i];
    case BodyType::Kinematic:
      return b.velocity() != Vec2{0.0, 0.0} || b.omega() != 0.0;
    case BodyType::Static:
      break;
  }
  return false;
}

double WorldImpl::frame_reach(const Body& b) const
{
  const double dt = settings_.dt;
  const double along = (length(b.velocity()) + length(settings_.gravity) * dt) * dt;
  return along + std::abs(b.omega()) * b.radius() * dt;
}

void WorldImpl::detect(const StepContext& ctx, double margin, StepReport& report)
{
  const std::size_t n = bodies_.size();
  boxes_.resize(n);
  reach_.resize(n);
  workers_.parallel_for(n, kMinSharedBodies, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      // The soft step collides once per frame, so a pair that the frame's
      // motion can close gets its contact now: the margin grows by how far
      // each body can travel in the frame.
      reach_[i] = margin > 0.0 && is_mover(i) ? frame_reach(bodies_[i]) : 0.0;
      boxes_[i] = margin > 0.0 ? bodies_[i].aabb().inflated(margin + reach_[i]) : bodies_[i].aabb();
    }
  });
  broad_phase_.find_pairs(boxes_, pairs_, workers_);
  // The narrow phase of the pairs with a moving body, split across the
  // workers (each writes its own pairs' slots); then, in pair order, what
  // each pair adds and where; then the points, split across the workers
  // again. The result is the same for any number of workers.
  margin_ = margin;
  manifolds_.resize(pairs_.size());
  collided_.resize(pairs_.size());
  workers_.run(pairs_.size(), &WorldImpl::collide_range, this);
  // Impulses were made over the cached substep length; a changed dt or
  // substep count rescales them to this one.
  const double warm_scale = ctx.warm ? ctx.h / cache_h_ : 0.0;
  const bool friction = ctx.effects.friction;
  points_.resize(place_pair_rows(warm_scale > 0.0 || friction));
  workers_.parallel_for(pairs_.size(), kMinSharedPairs, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      fill_pair_rows(k, warm_scale, friction);
    }
  });
  report.max_detected_penetration = max_over(points_.size(), kMinSharedPoints, report.max_detected_penetration,
                                             [this](std::size_t k) { return points_[k].penetration; });
}

std::size_t WorldImpl::place_pair_rows(bool cached)
{
  // In pair order: a body woken here makes later pairs with it movers, and
  // the cache cursor walks forward.
  pair_rows_.resize(pairs_.size() + 1);
  pair_cache_.resize(pairs_.size());
  std::size_t rows = 0;
  for (std::size_t k = 0; k < pairs_.size(); ++k)
  {
    pair_rows_[k] = rows;
    const std::size_t i = pairs_[k].first;
    const std::size_t j = pairs_[k].second;
    if (!dynamic_pair(i, j))
    {
      continue;
    }
    if (!is_mover(i) && !is_mover(j))
    {
      collided_[k] = Collided::Carried;
      pair_cache_[k] = cached_pair(ids_[i], ids_[j]);
      rows += carried_rows(pair_cache_[k], ids_[i], ids_[j]);
      continue;
    }
    // A pair whose body woke up earlier in this loop was not collided yet.
    if (collided_[k] == Collided::NotTried)
    {
      collided_[k] = collide_pair(i, j, pair_tolerance(i, j), manifolds_[k]) ? Collided::Hit : Collided::Miss;
    }
    if (collided_[k] != Collided::Hit)
    {
      continue;
    }
    // A moving body reached a sleeping one: its island takes part again.
    if (asleep_[i] || asleep_[j])
    {
      wake(asleep_[i] ? i : j);
    }
    const int count = manifolds_[k].count;
    pair_cache_[k] = cached && count > 0 ? cached_pair(ids_[i], ids_[j]) : cache_.size();
    rows += static_cast<std::size_t>(count);
  }
  pair_rows_[pairs_.size()] = rows;
  return rows;
}

std::size_t WorldImpl::carried_rows(std::size_t first, BodyId a, BodyId b) const
{
  std::size_t end = first;
  while (end < cache_.size() && cache_[end].a == a && cache_[end].b == b)
  {
    ++end;
  }
  return end - first;
}

void WorldImpl::fill_pair_rows(std::size_t k, double warm_scale, bool friction)
{
  if (collided_[k] == Collided::Hit)
  {
    add_manifold(k, warm_scale, friction);
  }
  else if (collided_[k] == Collided::Carried)
  {
    carry_sleeping_pair(k);
  }
}

bool WorldImpl::collide_pair(std::size_t i, std::size_t j, double tolerance, Manifold& m) const
{
  const Body& a = bodies_[i];
  const Body& b = bodies_[j];
  if (coincident_disks(a, b))
  {
    m.normal = kCoincidentNormal;
    m.count = 1;
    m.points[0] = ManifoldPoint{a.position(), a.radius() + b.radius(), 0};
    return true;
  }
  return collide(a, b, m, tolerance);
}

void WorldImpl::collide_range(void* world, std::size_t begin, std::size_t end)
{
  WorldImpl& w = *static_cast<WorldImpl*>(world);
  for (std::size_t k = begin; k < end; ++k)
  {
    const std::size_t i = w.pairs_[k].first;
    const std::size_t j = w.pairs_[k].second;
    Collided& result = w.collided_[k];
    result = Collided::NotTried;
    if (w.dynamic_pair(i, j) && (w.is_mover(i) || w.is_mover(j)))
    {
      result = w.collide_pair(i, j, w.pair_tolerance(i, j), w.manifolds_[k]) ? Collided::Hit : Collided::Miss;
    }
  }
}

bool WorldImpl::dynamic_pair(std::size_t i, std::size_t j) const
{
  return bodies_[i].type() == BodyType::Dynamic || bodies_[j].type() == BodyType::Dynamic;
}

double WorldImpl::pair_tolerance(std::size_t i, std::size_t j) const
{
  // The soft step keeps pairs within its speculative margin; the Fx2D step
  // keeps a body stopped at its time of impact touching its obstacle.
  const bool touch = clamped(i) || clamped(j);
  const double touching = touch ? kRelativeTouchTolerance * (bodies_[i].radius() + bodies_[j].radius()) : 0.0;
  return std::max(margin_ + reach_[i] + reach_[j], touching);
}

void WorldImpl::add_manifold(std::size_t k, double warm_scale, bool friction)
{
  const std::size_t i = pairs_[k].first;
  const std::size_t j = pairs_[k].second;
  const Manifold& m = manifolds_[k];
  for (int c = 0; c < m.count; ++c)
  {
    ContactPoint& row = points_[pair_rows_[k] + static_cast<std::size_t>(c)];
    row = ContactPoint{};
    row.a = i;
    row.b = j;
    row.normal = m.normal;
    row.point = m.points[c].point;
    row.penetration = m.points[c].penetration;
    row.separation = m.points[c].separation;
    row.feature = m.points[c].feature;
    row.count = m.count;
    const WorldContact* cached =
        warm_scale > 0.0 || friction ? find_cached(pair_cache_[k], ids_[i], ids_[j], row.feature) : nullptr;
    if (cached != nullptr)
    {
      row.lambda_n = warm_scale * cached->impulse.normal;
      row.lambda_t = warm_scale * cached->impulse.tangent;
      row.kinetic = friction && cached->sliding;
      row.anchor_drift = cached->anchor_drift;
    }
  }
}

void WorldImpl::carry_sleeping_pair(std::size_t k)
{
  // Nothing moves in a sleeping island, so its contacts and impulses stay
  // what they were when it fell asleep; they are kept (unsolved) so the
  // island stays one island and wakes with its impulses intact.
  const std::size_t first = pair_cache_[k];
  for (std::size_t r = pair_rows_[k]; r < pair_rows_[k + 1]; ++r)
  {
    const WorldContact& cached = cache_[first + (r - pair_rows_[k])];
    ContactPoint& row = points_[r];
    row = ContactPoint{};
    row.a = pairs_[k].first;
    row.b = pairs_[k].second;
    row.normal = cached.contact.normal;
    row.point = cached.contact.point;
    row.penetration = cached.contact.penetration;
    row.feature = cached.contact.feature;
    row.active = false;
    row.lambda_n = cached.impulse.normal;
    row.lambda_t = cached.impulse.tangent;
    row.sliding = cached.sliding;
  }
}

std::size_t WorldImpl::cached_pair(BodyId a, BodyId b) const
{
  // The cache is in (a, b) order because contacts are published in broad-phase
  // pair order and dense indices follow ids; detection asks in that order too,
  // so the cursor only moves forward (a search covers any other order).
  if (cache_cursor_ > cache_.size() || (cache_cursor_ > 0 && !pair_less(cache_[cache_cursor_ - 1], a, b)))
  {
    const auto found = std::lower_bound(cache_.begin(), cache_.end(), std::make_pair(a, b),
                                        [](const WorldContact& c, const std::pair<BodyId, BodyId>& key) {
                                          return pair_less(c, key.first, key.second);
                                        });
    cache_cursor_ = static_cast<std::size_t>(found - cache_.begin());
    return cache_cursor_;
  }
  while (cache_cursor_ < cache_.size() && pair_less(cache_[cache_cursor_], a, b))
  {
    ++cache_cursor_;
  }
  return cache_cursor_;
}

const WorldContact* WorldImpl::find_cached(std::size_t first, BodyId a, BodyId b, std::uint32_t feature) const
{
  for (auto it = cache_.begin() + first; it != cache_.end() && it->a == a && it->b == b; ++it)
  {
    if (it->contact.feature == feature)
    {
      return &*it;
    }
  }
  return nullptr;
}

void WorldImpl::publish_contacts()
{
  contacts_.resize(points_.size());
  workers_.parallel_for(points_.size(), kMinSharedPoints, [this](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      const ContactPoint& row = points_[k];
      WorldContact& c = contacts_[k];
      c.a = ids_[row.a];
      c.b = ids_[row.b];
      c.contact = Contact{row.a, row.b, row.normal, row.point, row.penetration, row.feature};
      c.impulse = ContactImpulse{row.lambda_n, row.lambda_t};
      c.sliding = row.sliding;
      c.anchor_drift = row.anchor_drift;
    }
  });
}

double WorldImpl::measure_penetration() const
{
  // The correction is linearised and pairs share bodies, so the depth left is
  // measured again at the final poses rather than predicted.
  double deepest = 0.0;
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    const ContactPoint& row = points_[k];
    const bool new_pair = k == 0 || points_[k - 1].a != row.a || points_[k - 1].b != row.b;
    if (!row.active || !new_pair)
    {
      continue;
    }
    Manifold m;
    if (collide_pair(row.a, row.b, 0.0, m))
    {
      for (int p = 0; p < m.count; ++p)
      {
        deepest = std::max(deepest, m.points[p].penetration);
      }
    }
  }
  return deepest;
}

}  // namespace detail
}  // namespace collision2d
