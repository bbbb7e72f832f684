// The broad phase's pairs kept from frame to frame (fat_box_pairs.h).
#include "fat_box_pairs.h"

#include <algorithm>

#include "broad_phase_parts.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// A box is enlarged by this fraction of its larger side on every side: a
/// unit box by 0.1 m, far more than a resting body moves between frames,
/// while the enlarged boxes of a stack's neighbours overlap no further ones.
constexpr double kFatFraction = 0.1;
/// After enlarged boxes were left at once, the next ones are built this many
/// frames later, then twice as many, up to kMaxWait: where bodies keep moving
/// (a gas, a rain) the exact boxes' pairs cost less than enlarged ones.
constexpr int kFirstWait = 1;
constexpr int kMaxWait = 64;
/// Enlarged boxes are made again at once, and this frame's pairs taken from
/// theirs, when the last ones served at least this many frames ...
constexpr int kMinServedFrames = 2;
/// ... and paired at most this many times as many boxes as the exact ones:
/// then pairing them costs about what pairing the exact boxes would.
constexpr std::size_t kMaxFatPairsPerPair = 2;

Aabb enlarged(const Aabb& box)
{
  // A box too large to enlarge within range stays as it is.
  const Aabb fat = box.inflated(kFatFraction * std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y));
  return is_usable(fat) ? fat : box;
}

bool inside(const Aabb& box, const Aabb& fat)
{
  return fat.lo.x <= box.lo.x && fat.lo.y <= box.lo.y && box.hi.x <= fat.hi.x && box.hi.y <= fat.hi.y;
}

}  // namespace

void FatBoxPairs::find_pairs(const std::vector<Aabb>& boxes, BroadPhase& broad_phase, std::vector<BodyPair>& pairs,
                             RangeRunner& runner)
{
  if (boxes.size() <= BroadPhase::kAllPairsBoxes)
  {
    // Every pair is tested at once: checking enlarged boxes first costs more.
    pair_exactly(boxes, broad_phase, pairs, runner);
    return;
  }
  if (still_inside(boxes, runner))
  {
    if (!built_)
    {
      build(broad_phase, runner);
    }
    ++reused_;
    wait_ = kFirstWait;
    serve(boxes, pairs, runner);
    return;
  }
  if (worth_rebuilding())
  {
    // A settling stack sinks out of its enlarged boxes every few frames.
    // Pairing new enlarged boxes now gives this frame's pairs too: one
    // pairing instead of the exact boxes' now and the enlarged ones' next frame.
    enlarge(boxes);
    build(broad_phase, runner);
    serve(boxes, pairs, runner);
    return;
  }
  if (frames_to_wait_ > 0)
  {
    --frames_to_wait_;
  }
  else
  {
    enlarge(boxes);
    frames_to_wait_ = wait_;
    wait_ = std::min(2 * wait_, kMaxWait);
  }
  pair_exactly(boxes, broad_phase, pairs, runner);
}

void FatBoxPairs::pair_exactly(const std::vector<Aabb>& boxes, BroadPhase& broad_phase, std::vector<BodyPair>& pairs,
                               RangeRunner& runner)
{
  broad_phase.find_pairs(boxes, pairs, runner);
  ++exact_count_;
}

bool FatBoxPairs::worth_rebuilding() const
{
  return built_ && served_ >= kMinServedFrames && fat_pairs_.size() <= kMaxFatPairsPerPair * exact_pairs_;
}

void FatBoxPairs::build(BroadPhase& broad_phase, RangeRunner& runner)
{
  broad_phase.find_pairs(fat_, fat_pairs_, runner);
  built_ = true;
  ++built_count_;
  served_ = 0;
}

void FatBoxPairs::serve(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner& runner)
{
  keep_overlapping(boxes, pairs, runner);
  ++served_;
  exact_pairs_ = pairs.size();
}

void FatBoxPairs::keep_overlapping(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs,
                                   RangeRunner& runner)
{
  // Boxes that overlap lie in enlarged boxes that overlap, so every pair is
  // among the kept ones, which are in (i, j) order; an unusable box pairs
  // with nothing, as in BroadPhase.
  const auto keep = [&](std::size_t begin, std::size_t end, std::vector<BodyPair>& out) {
    for (std::size_t k = begin; k < end; ++k)
    {
      const BodyPair& pair = fat_pairs_[k];
      const Aabb& a = boxes[pair.first];
      const Aabb& b = boxes[pair.second];
      if (a.overlaps(b) && is_usable(a) && is_usable(b))
      {
        out.push_back(pair);
      }
    }
  };
  const std::size_t n = fat_pairs_.size();
  const std::size_t parts = runner_parts(&runner, n);
  if (parts == 1)
  {
    pairs.clear();
    keep(0, n, pairs);
    return;
  }
  collect_in_parts(runner, parts, part_pairs_, pairs, [&](std::size_t part, std::vector<BodyPair>& kept) {
    keep(part_begin(n, part, parts), part_begin(n, part + 1, parts), kept);
  });
}

bool FatBoxPairs::still_inside(const std::vector<Aabb>& boxes, RangeRunner& runner)
{
  if (!enlarged_ || boxes.size() != fat_.size())
  {
    return false;
  }
  const auto inside_all = [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      if (!is_usable(boxes[k]) || !inside(boxes[k], fat_[k]))
      {
        return false;
      }
    }
    return true;
  };
  const std::size_t parts = runner_parts(&runner, boxes.size());
  if (parts == 1)
  {
    return inside_all(0, boxes.size());
  }
  part_inside_.assign(parts, 0);
  run_parts(runner, parts, [&](std::size_t part) {
    part_inside_[part] = inside_all(part_begin(boxes.size(), part, parts), part_begin(boxes.size(), part + 1, parts))
                             ? 1
                             : 0;
  });
  return std::find(part_inside_.begin(), part_inside_.end(), 0) == part_inside_.end();
}

void FatBoxPairs::enlarge(const std::vector<Aabb>& boxes)
{
  enlarged_ = false;  // until every box is written
  built_ = false;
  fat_.resize(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k)
  {
    fat_[k] = enlarged(boxes[k]);
  }
  enlarged_ = true;
}

}  // namespace detail
}  // namespace collision2d
