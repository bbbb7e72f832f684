// Detection for the substep (broad then narrow phase on fresh boxes) and the
// published contacts; the rows of the pairs found are world_contact_rows.cpp.
#include <algorithm>
#include <atomic>

#include "collision2d/collide.h"
#include "collision2d/touch_tolerance.h"
#include "collide_features.h"
#include "scratch_buffer.h"
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

/// Test hook: every frame rebuilds the resting grid and visits every body.
std::atomic<bool> g_full_body_passes{false};

bool coincident_disks(const Body& a, const Body& b)
{
  return a.shape() == Shape::Disk && b.shape() == Shape::Disk && a.position() == b.position();
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

void WorldImpl::detect(const StepContext& ctx, double margin, StepReport& report, bool prepare)
{
  pose_bodies();                                          // world_pose.cpp
  margin_ = margin;
  // Kept within the margin: a feature out of reach when the points were found
  // cannot reach the other body before the pair is found again.
  reuse_distance_ = prepare ? std::min(settings_.contact_reuse_distance, margin) : 0.0;
  // A mover that reaches a sleeping island wakes all of it, and the woken
  // bodies are movers for a second look: the island's contacts are solved in
  // the frame it wakes.
  do
  {
    find_mover_pairs();
  } while (wake_reached_islands());                       // world_sleeping_contacts.cpp
  // Impulses were made over the cached substep length; a changed dt or
  // substep count rescales them to this one.
  const double warm_scale = ctx.warm ? ctx.h / cache_h_ : 0.0;
  const bool friction = ctx.effects.friction;
  const std::size_t rows = place_pair_rows(warm_scale > 0.0 || friction);
  resize_to_overwrite(points_, rows);  // add_manifold writes every row
  if (prepare)
  {
    soft_rows_.expect_points(rows);
  }
  std::atomic<double> deepest{report.max_detected_penetration};
  std::atomic<bool> bounces{false};
  workers_.parallel_for(pairs_.size(), kMinSharedPairs, [&](std::size_t begin, std::size_t end) {
    double range_deepest = deepest.load();
    bool range_bounces = false;
    for (std::size_t k = begin; k < end; ++k)
    {
      if (collided_[k] == Collided::Hit)
      {
        range_deepest = std::max(range_deepest, add_manifold(k, warm_scale, friction));
        if (prepare)
        {
          range_bounces = prepare_pair_points(ctx.effects, k) || range_bounces;  // world_soft_step.cpp
        }
      }
    }
    raise_to(deepest, range_deepest);
    if (range_bounces)
    {
      bounces.store(true, std::memory_order_relaxed);
    }
  });
  report.max_detected_penetration = deepest.load();
  if (prepare)
  {
    bounces_ = bounces.load();
  }
  // Contacts kept aside still count (world_sleeping_contacts.cpp).
  if (!sleeping_contacts_.empty())
  {
    report.max_detected_penetration = std::max(report.max_detected_penetration, sleeping_penetration_);
  }
}

/// Broad and narrow phase of the pairs with a mover, within margin_.
void WorldImpl::find_mover_pairs()
{
  if (refresh_resting_grid())
  {
    body_pass_full_ = true;  // woken bodies join the movers
  }
  // The movers and the few large resting boxes (a ground) go to one broad
  // phase, in ascending body order; the other resting boxes are queried in
  // the resting grid. Merged in (i, j) order, the pairs are those of one
  // broad phase over every box, less the pairs in which nothing moves.
  const std::vector<std::size_t>& large = resting_grid_.large();
  looked_.resize(movers_.size() + large.size());
  std::merge(movers_.begin(), movers_.end(), large.begin(), large.end(), looked_.begin());
  const std::size_t m = looked_.size();
  mover_boxes_.resize(m);
  workers_.parallel_for(m, kMinSharedBodies, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      // The soft step collides once per frame, so a pair that the frame's
      // motion can close gets its contact now: the margin grows by how far
      // each body can travel in the frame (reach_ is 0 for a resting body).
      const std::size_t i = looked_[k];
      reach_[i] = margin_ > 0.0 && !is_resting_[i] ? frame_reach(bodies_[i]) : 0.0;
      const Aabb box = posed_box(i);
      mover_boxes_[k] = margin_ > 0.0 ? box.inflated(margin_ + reach_[i]) : box;
    }
  });
  if (clamping_ && margin_ == 0.0)
  {
    grow_stopped_boxes();                                 // world_toi.cpp
  }
  fat_pairs_.find_pairs(mover_boxes_, broad_phase_, mover_pairs_, workers_);  // fat_box_pairs.h
  auto kept = mover_pairs_.begin();
  for (const BodyPair& pair : mover_pairs_)
  {
    const std::size_t i = looked_[pair.first];
    const std::size_t j = looked_[pair.second];
    if (!is_resting_[i] || !is_resting_[j])
    {
      *kept++ = {i, j};  // looked_ ascends: the order holds
    }
  }
  mover_pairs_.erase(kept, mover_pairs_.end());
  resting_pairs_.clear();
  for (std::size_t k = 0; k < m && !resting_grid_.empty(); ++k)
  {
    if (!is_resting_[looked_[k]])
    {
      resting_grid_.query(mover_boxes_[k], looked_[k], resting_pairs_);
    }
  }
  if (resting_pairs_.empty())
  {
    pairs_.swap(mover_pairs_);  // no copy: each buffer keeps its capacity
  }
  else
  {
    merge_pairs();
  }
  // The narrow phase of the pairs with a moving body, split across the
  // workers (each writes its own pairs' slots); then, in pair order, what
  // each pair adds and where; then the points, split across the workers
  // again. The result is the same for any number of workers.
  place_pair_buffers(pairs_.size());
  workers_.parallel_for(pairs_.size(), kMinSharedPairs,
                        [this](std::size_t begin, std::size_t end) { collide_range(begin, end); });
}

void WorldImpl::place_pair_buffers(std::size_t n)
{
  // collide_range writes every manifold it reads, place_pair_rows every row
  // start and the cache starts of the pairs that hit (the only ones read).
  place_together(frame_block_, part(manifolds_, n), part(kept_from_, n), part(pair_rows_, n + 1),
                 part(pair_cache_, n), part(collided_, n));
  std::fill(kept_from_.begin(), kept_from_.end(), kNotKept);
}

void set_full_body_passes(bool full) { g_full_body_passes.store(full, std::memory_order_relaxed); }

/// pairs_: the movers' pairs merged with the resting grid's, in (i, j) order.
void WorldImpl::merge_pairs()
{
  std::sort(resting_pairs_.begin(), resting_pairs_.end());
  const std::size_t count = mover_pairs_.size() + resting_pairs_.size();
  resize_to_overwrite(pairs_, count);  // std::merge writes every pair
  std::merge(mover_pairs_.begin(), mover_pairs_.end(), resting_pairs_.begin(), resting_pairs_.end(), pairs_.begin());
}

bool WorldImpl::refresh_resting_grid()
{
  const std::size_t n = bodies_.size();
  if (g_full_body_passes.load(std::memory_order_relaxed))
  {
    resting_built_ = false;
  }
  if (resting_built_ && resting_version_ == version_ && resting_stamp_ == sleep_stamp_ && resting_margin_ == margin_ &&
      reach_.size() == n)
  {
    return false;
  }
  resting_built_ = true;
  resting_version_ = version_;
  resting_stamp_ = sleep_stamp_;
  resting_margin_ = margin_;
  movers_.clear();
  resting_.clear();
  boxes_.resize(n);
  reach_.assign(n, 0.0);
  is_resting_.assign(n, 0);
  resting_census_ = BodyCensus{};
  for (std::size_t i = 0; i < n; ++i)
  {
    if (is_mover(i))
    {
      movers_.push_back(i);
      continue;
    }
    resting_.push_back(i);
    is_resting_[i] = 1;
    count_body(i, resting_census_);
    boxes_[i] = margin_ > 0.0 ? bodies_[i].aabb().inflated(margin_) : bodies_[i].aabb();
  }
  resting_grid_.build(boxes_, resting_);
  return true;
}

/// With `posed`, the polygons' outlines come from pose_bodies (the poses
/// must not have changed since).
bool WorldImpl::collide_pair(std::size_t i, std::size_t j, double tolerance, Manifold& m, bool posed_now) const
{
  const Body& a = bodies_[i];
  const Body& b = bodies_[j];
  if (coincident_disks(a, b))
  {
    // As collide() would at distance 0: the whole sum of radii deep, the point
    // midway through the overlap.
    const double depth = a.radius() + b.radius();
    m.normal = kCoincidentNormal;
    m.count = 0;
    add_point(m, a.position() + m.normal * (a.radius() - 0.5 * depth), depth,
              pack_feature(FeatureKind::DiskDisk, false, 0, 0, 0));
    return true;
  }
  return posed_now ? collide_posed(posed(i), posed(j), m, tolerance) : collide(a, b, m, tolerance);
}

void WorldImpl::collide_range(std::size_t begin, std::size_t end)
{
  std::size_t cursor = contacts_.size() + 1;  // the range's first lookup searches
  for (std::size_t k = begin; k < end; ++k)
  {
    const std::size_t i = pairs_[k].first;
    const std::size_t j = pairs_[k].second;
    Collided& result = collided_[k];
    result = Collided::NotTried;
    if (!dynamic_pair(i, j))
    {
      continue;  // every pair found has a mover (find_mover_pairs)
    }
    if (keep_manifold(k, i, j, cursor))                 // world_contact_reuse.cpp
    {
      result = Collided::Hit;
      continue;
    }
    result = collide_pair(i, j, pair_tolerance(i, j), manifolds_[k], true) ? Collided::Hit : Collided::Miss;
  }
}

double WorldImpl::pair_tolerance(std::size_t i, std::size_t j) const
{
  // The soft step keeps pairs within its speculative margin; the Fx2D step
  // keeps a body stopped at its time of impact touching its obstacle.
  const bool touch = clamped(i) || clamped(j);
  const double touching = touch ? kRelativeTouchTolerance * (bodies_[i].radius() + bodies_[j].radius()) : 0.0;
  return std::max(margin_ + reach_[i] + reach_[j], touching);
}

void WorldImpl::publish_contacts(bool soft_frame)
{
  // One pass for all: each point is read (and written) once while in cache,
  // into its contact, over the last frame's (detection was their last reader).
  std::atomic<double> deepest{0.0};
  const bool packed = soft_frame && rows_on();
  size_contacts(points_.size());
  if (rollback_.active)
  {
    rollback_.contacts_published = true;
  }
  workers_.parallel_for(points_.size(), kMinSharedPoints, [&](std::size_t begin, std::size_t end) {
    double range_deepest = 0.0;
    for (std::size_t k = begin; k < end; ++k)
    {
      // The point itself is not written: nothing reads it after the
      // publish, and a large frame's points have left the cache by now.
      const ContactPoint& row = points_[k];
      const PointOutcome outcome = packed ? soft_rows_.point_outcome(k, row) : own_outcome(row);
      CarriedSlip slip{outcome.sliding, row.anchor_drift};
      if (soft_frame && row.active)
      {
        const Vec2 offset = anchor_offset(row, velocity_);  // read once for both
        slip = carry_slip(row, outcome.sliding, offset);
        range_deepest = std::max(range_deepest, -separation_at(row, offset));
      }
      // Field by field: the buffer is cold, and whole-struct temporaries
      // went through the stack first.
      WorldContact& c = contacts_[k];
      c.a = ids_[row.a];
      c.b = ids_[row.b];
      c.contact.a = row.a;
      c.contact.b = row.b;
      c.contact.normal = row.normal;
      c.contact.point = row.point;
      c.contact.penetration = row.depth();
      c.contact.feature = row.feature;
      c.impulse.normal = outcome.normal;
      c.impulse.tangent = outcome.tangent;
      c.sliding = slip.sliding;
      c.anchor_drift = slip.anchor_drift;
      if (row.origin_known)  // a soft frame's point, contacts kept (add_manifold)
      {
        publish_origin(row, c.origin);
      }
      else
      {
        c.origin = ContactOrigin{};
      }
    }
    raise_to(deepest, range_deepest);
  });
  followed_known_ = soft_frame;
  followed_deepest_ = deepest.load();
}

/// contacts_ resized to n contacts, to be overwritten.
void WorldImpl::size_contacts(std::size_t n)
{
  // The last contacts are dead here, but a new block is taken before the old
  // one goes: a step refused for want of memory still finds them in place.
  if (n <= contacts_.capacity())
  {
    if (n > contacts_.size())
    {
      touch_pages_first(workers_, contacts_.data() + contacts_.size(), contacts_.data() + n);
    }
    contacts_.resize(n);
    return;
  }
  std::vector<WorldContact> grown;
  grown.reserve(kGrowthRoom * n);
  // Taken: from here nothing throws, and the old pages go before the new
  // ones are written, so the two are not resident together.
  give_back_pages(contacts_.data(), contacts_.capacity() * sizeof(WorldContact));
  touch_pages_first(workers_, grown.data(), grown.data() + n);
  grown.resize(n);
  contacts_.swap(grown);
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
    if (collide_pair(row.a, row.b, 0.0, m, false))
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
