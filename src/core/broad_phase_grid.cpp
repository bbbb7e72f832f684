// The grid of the broad phase as a spatial hash laid out by counting sort:
// cells map to buckets of a power-of-two table, the (cell, box) entries are
// counted per bucket, the counts turned into offsets and the entries written
// into one flat array. No per-cell containers, so a warmed-up broad phase
// allocates nothing, and a scene's extent does not matter (only occupied cells
// cost anything). Distinct cells may share a bucket; entries carry their cell
// so that only boxes of the same cell are compared. A scene that fills its
// occupied range (a gas) gets one bucket per cell of that range instead: no
// hashing, and fewer, never shared buckets.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <tuple>

#include "collision2d/broad_phase.h"
#include "broad_phase_parts.h"

namespace collision2d
{
namespace
{
/// Buckets up to this size are compared all pairs; larger ones (a crowd in
/// one cell) are sorted and swept along x.
constexpr std::size_t kAllPairsBucket = 16;

/// The grid is laid out densely (one bucket per cell of the occupied range,
/// no hashing, no two cells sharing a bucket) when that range has at most
/// this many cells per entry: a compact scene such as a gas fills its range.
constexpr std::int64_t kDenseCellsPerEntry = 2;

/// Multiplicative hash constants (odd, with well-mixed bits).
constexpr std::uint64_t kHashX = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t kHashY = 0xC2B2AE3D27D4EB4Full;
constexpr unsigned kHashFold = 32;  // bits folded down so the mask sees the high bits

std::size_t power_of_two_at_least(std::size_t n)
{
  std::size_t p = 1;
  while (p < n)
  {
    p <<= 1;
  }
  return p;
}

}  // namespace

std::size_t BroadPhase::bucket_of(std::int32_t cx, std::int32_t cy) const
{
  if (dense_width_ > 0)
  {
    return static_cast<std::size_t>(static_cast<std::int64_t>(cy - occupied_.y0) * dense_width_ +
                                    (cx - occupied_.x0));
  }
  std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) * kHashX ^
                    static_cast<std::uint64_t>(static_cast<std::uint32_t>(cy)) * kHashY;
  h ^= h >> kHashFold;
  return static_cast<std::size_t>(h) & bucket_mask_;
}

std::size_t BroadPhase::choose_layout(std::size_t entry_count)
{
  const std::int64_t cells =
      grid_boxes_.empty() ? 0 : detail::cell_area(occupied_.x0, occupied_.y0, occupied_.x1, occupied_.y1);
  if (cells > 0 && cells <= kDenseCellsPerEntry * static_cast<std::int64_t>(entry_count))
  {
    dense_width_ = static_cast<std::int64_t>(occupied_.x1) - occupied_.x0 + 1;
    bucket_mask_ = 0;
    return static_cast<std::size_t>(cells);
  }
  // Hashed: about one bucket per entry keeps the chance of two cells sharing one low.
  dense_width_ = 0;
  const std::size_t bucket_count = power_of_two_at_least(std::max<std::size_t>(entry_count, 1));
  bucket_mask_ = bucket_count - 1;
  return bucket_count;
}

void BroadPhase::fill_grid(RangeRunner* runner)
{
  const std::size_t entry_count = entry_count_;
  const std::size_t bucket_count = choose_layout(entry_count);
  bucket_start_.assign(bucket_count + 1, 0);
  entries_.resize(entry_count);
  const std::size_t parts = detail::runner_parts(runner, entry_count);
  if (parts > 1)
  {
    entry_bucket_.resize(entry_count);
    fill_grid_in_parts(*runner, parts, bucket_count);
    return;
  }
  // Each entry is made and hashed once, while counting, and scattered from
  // that list in one flat pass: walking each box's cells again mispredicted
  // the short loops' ends as often as the first walk.
  staged_.resize(entry_count);
  std::size_t e = 0;
  for (std::size_t box : grid_boxes_)
  {
    const CellRange& r = ranges_[box];
    for (std::int32_t cy = r.y0; cy <= r.y1; ++cy)
    {
      for (std::int32_t cx = r.x0; cx <= r.x1; ++cx)
      {
        const std::size_t bucket = bucket_of(cx, cy);
        staged_[e++] = StagedEntry{cx, cy, static_cast<std::uint32_t>(box), static_cast<std::uint32_t>(bucket)};
        ++bucket_start_[bucket];
      }
    }
  }
  std::size_t end = 0;
  for (std::size_t& start : bucket_start_)
  {
    end += start;
    start = end;  // one past the bucket's end, decremented while scattering
  }
  for (const StagedEntry& staged : staged_)
  {
    entries_[--bucket_start_[staged.bucket]] = Entry{staged.cx, staged.cy, staged.box};
  }
}

void BroadPhase::fill_grid_in_parts(RangeRunner& runner, std::size_t parts, std::size_t bucket_count)
{
  // A bucket fills from its end in entry order, so a part's entries go below
  // those of the parts before it: the entries land where one pass puts them.
  part_count_.assign(parts * bucket_count, 0);
  detail::run_parts(runner, parts, [&](std::size_t part) { count_entries(part, parts, bucket_count); });
  std::size_t end = 0;
  for (std::size_t b = 0; b < bucket_count; ++b)
  {
    std::size_t total = 0;
    for (std::size_t part = 0; part < parts; ++part)
    {
      total += part_count_[part * bucket_count + b];
    }
    end += total;
    std::size_t cursor = end;
    for (std::size_t part = 0; part < parts; ++part)
    {
      const std::size_t count = part_count_[part * bucket_count + b];
      part_count_[part * bucket_count + b] = cursor;
      cursor -= count;
    }
    bucket_start_[b] = end - total;
  }
  bucket_start_[bucket_count] = end;
  detail::run_parts(runner, parts, [&](std::size_t part) { scatter_entries(part, parts, bucket_count); });
}

void BroadPhase::count_entries(std::size_t part, std::size_t parts, std::size_t bucket_count)
{
  std::size_t* count = part_count_.data() + part * bucket_count;
  const std::size_t n = grid_boxes_.size();
  for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
  {
    const CellRange& r = ranges_[grid_boxes_[k]];
    std::size_t e = first_entry_[k];
    for (std::int32_t cy = r.y0; cy <= r.y1; ++cy)
    {
      for (std::int32_t cx = r.x0; cx <= r.x1; ++cx)
      {
        const std::size_t bucket = bucket_of(cx, cy);
        entry_bucket_[e++] = bucket;
        ++count[bucket];
      }
    }
  }
}

void BroadPhase::scatter_entries(std::size_t part, std::size_t parts, std::size_t bucket_count)
{
  std::size_t* cursor = part_count_.data() + part * bucket_count;
  const std::size_t n = grid_boxes_.size();
  for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
  {
    const std::size_t box = grid_boxes_[k];
    const CellRange& r = ranges_[box];
    std::size_t e = first_entry_[k];
    for (std::int32_t cy = r.y0; cy <= r.y1; ++cy)
    {
      for (std::int32_t cx = r.x0; cx <= r.x1; ++cx)
      {
        entries_[--cursor[entry_bucket_[e++]]] = Entry{cx, cy, box};
      }
    }
  }
}

void BroadPhase::pairs_in_grid(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner* runner)
{
  // In one part, or in as many as the runner has workers: each part searches
  // a share of the buckets, listing each pair under the part that owns its
  // first box, then each owner sorts its pairs into its own stretch of
  // `pairs` (broad_phase_sort.cpp).
  const std::size_t parts = detail::runner_parts(runner, entries_.size());
  large_pairs_.clear();
  pairs_of_large(boxes, large_pairs_);
  choose_owners(boxes.size(), parts);  // broad_phase_sort.cpp
  part_pairs_.resize(parts * parts);
  detail::for_each_part(runner, parts, [&](std::size_t part) { search_part(boxes, part, parts); });
  sort_by_owner(boxes.size(), parts, runner, pairs);  // broad_phase_sort.cpp
}

void BroadPhase::search_part(const std::vector<Aabb>& boxes, std::size_t part, std::size_t parts)
{
  // Each bucket is searched (and its entries sorted) by one part only. The
  // parts take equal shares of the entries, not of the buckets: a dense
  // grid's buckets are rows of cells, and a pyramid's lower rows hold most of
  // its boxes. Bucket b goes to the part its first entry falls in.
  const std::size_t buckets = bucket_start_.size() - 1;
  const auto first_bucket = [&](std::size_t k) {
    if (k == parts)
    {
      return buckets;
    }
    const std::size_t entry = entries_.size() * k / parts;
    return static_cast<std::size_t>(
        std::lower_bound(bucket_start_.begin(), bucket_start_.begin() + static_cast<std::ptrdiff_t>(buckets), entry) -
        bucket_start_.begin());
  };
  PartPairs* lists = part_pairs_.data() + part * parts;
  for (std::size_t owner = 0; owner < parts; ++owner)
  {
    lists[owner].pairs.clear();
  }
  auto add = [&](std::size_t i, std::size_t j) { lists[owner_of(i)].pairs.emplace_back(i, j); };
  pairs_in_buckets(boxes, first_bucket(part), first_bucket(part + 1), add);
}

template <class Add>
void BroadPhase::pairs_in_buckets(const std::vector<Aabb>& boxes, std::size_t begin, std::size_t end, Add& add)
{
  for (std::size_t b = begin; b < end; ++b)
  {
    if (bucket_start_[b + 1] - bucket_start_[b] > 1)
    {
      pairs_in_bucket(boxes, bucket_start_[b], bucket_start_[b + 1], add);
    }
  }
}

template <class Add>
void BroadPhase::pairs_in_bucket(const std::vector<Aabb>& boxes, std::size_t begin, std::size_t end, Add& add)
{
  // `same_cell` joins the box test with `&`: one branch for the whole test
  // (Aabb::overlaps), where a bucket of two or three boxes mispredicts each
  // comparison alone.
  const auto report_if_overlapping = [&](bool same_cell, const Entry& a, const Entry& b) {
    if ((same_cell & boxes[a.box].overlaps(boxes[b.box])) && owns(a.cx, a.cy, a.box, b.box))
    {
      add(std::min(a.box, b.box), std::max(a.box, b.box));
    }
  };
  if (end - begin <= kAllPairsBucket)
  {
    for (std::size_t a = begin; a < end; ++a)
    {
      const Entry& e = entries_[a];
      for (std::size_t b = a + 1; b < end; ++b)
      {
        const Entry& f = entries_[b];
        report_if_overlapping((e.cx == f.cx) & (e.cy == f.cy), e, f);
      }
    }
    return;
  }
  const auto first = entries_.begin() + static_cast<std::ptrdiff_t>(begin);
  const auto last = entries_.begin() + static_cast<std::ptrdiff_t>(end);
  std::sort(first, last, [&boxes](const Entry& a, const Entry& b) {
    return std::make_tuple(a.cx, a.cy, boxes[a.box].lo.x) < std::make_tuple(b.cx, b.cy, boxes[b.box].lo.x);
  });
  for (std::size_t a = begin; a < end; ++a)
  {
    const Entry& e = entries_[a];
    for (std::size_t b = a + 1; b < end && entries_[b].cx == e.cx && entries_[b].cy == e.cy &&
                                boxes[entries_[b].box].lo.x <= boxes[e.box].hi.x;
         ++b)
    {
      report_if_overlapping(true, e, entries_[b]);
    }
  }
}

void BroadPhase::large_against_grid(const std::vector<Aabb>& boxes, std::size_t large,
                                    std::vector<BodyPair>& pairs) const
{
  const CellRange& r = ranges_[large];
  const CellRange clip{std::max(r.x0, occupied_.x0), std::max(r.y0, occupied_.y0), std::min(r.x1, occupied_.x1),
                       std::min(r.y1, occupied_.y1)};
  if (clip.x0 > clip.x1 || clip.y0 > clip.y1)
  {
    return;
  }
  const auto report_if_overlapping = [&](const Entry& e) {
    if (boxes[large].overlaps(boxes[e.box]) && owns(e.cx, e.cy, large, e.box))
    {
      pairs.emplace_back(std::min(large, e.box), std::max(large, e.box));
    }
  };
  // Probe the covered cells, or scan every entry when that is cheaper (a slab
  // under the whole scene covers more cells than are occupied).
  if (detail::cell_area(clip.x0, clip.y0, clip.x1, clip.y1) >= static_cast<std::int64_t>(entries_.size()))
  {
    for (const Entry& e : entries_)
    {
      if (e.cx >= clip.x0 && e.cx <= clip.x1 && e.cy >= clip.y0 && e.cy <= clip.y1)
      {
        report_if_overlapping(e);
      }
    }
    return;
  }
  for (std::int32_t cy = clip.y0; cy <= clip.y1; ++cy)
  {
    for (std::int32_t cx = clip.x0; cx <= clip.x1; ++cx)
    {
      const std::size_t b = bucket_of(cx, cy);
      for (std::size_t k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k)
      {
        if (entries_[k].cx == cx && entries_[k].cy == cy)
        {
          report_if_overlapping(entries_[k]);
        }
      }
    }
  }
}

}  // namespace collision2d
