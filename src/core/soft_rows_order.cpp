// The soft step's manifolds in height order (soft_rows.h): one key per noted
// manifold, radix sorted. In a large frame the workers share it: each sorts
// the keys of its part of the notes, then merges a share of the output.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

#include "collision2d/setting_table.h"
#include "scratch_buffer.h"
#include "soft_rows.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Fewer keys than this are ordered by a comparison sort (sort_by_height).
constexpr std::size_t kRadixSortFrom = 256;
/// The radix: 8-bit digits over the high 32 bits of a key.
constexpr int kDigitBits = 8;
constexpr int kKeyDigits = 4;
constexpr std::size_t kDigits = std::size_t{1} << kDigitBits;

std::size_t digit(std::uint64_t key, int d)
{
  return static_cast<std::size_t>(key >> (32 + kDigitBits * d)) & (kDigits - 1);
}

/// Sorts n keys by their high half, keeping the order of equal ones: a
/// least significant digit radix sort, linear where a comparison sort cost
/// more than the colouring it orders. One pass counts every digit. Returns
/// where the sorted keys ended, `keys` or `scratch`. The low halves are
/// distinct and ascending, so a comparison sort of the whole keys gives the
/// same order: below kRadixSortFrom keys it is cheaper than clearing and
/// summing the digit counts.
std::uint64_t* sort_keys(std::uint64_t* keys, std::uint64_t* scratch, std::size_t n)
{
  if (n < kRadixSortFrom)
  {
    std::sort(keys, keys + n);
    return keys;
  }
  std::array<std::array<std::size_t, kDigits>, kKeyDigits> start{};
  for (std::size_t k = 0; k < n; ++k)
  {
    for (int d = 0; d < kKeyDigits; ++d)
    {
      ++start[d][digit(keys[k], d)];
    }
  }
  for (int d = 0; d < kKeyDigits; ++d)
  {
    if (start[d][digit(keys[0], d)] == n)
    {
      continue;  // one value of this digit for all: nothing moves
    }
    std::size_t sum = 0;
    for (std::size_t& s : start[d])
    {
      sum += std::exchange(s, sum);
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      scratch[start[d][digit(keys[k], d)]++] = keys[k];
    }
    std::swap(keys, scratch);
  }
  return keys;
}

/// sort_keys on a whole buffer, the sorted keys left in `keys`.
void sort_by_height(FrameBuffer<std::uint64_t>& keys, FrameBuffer<std::uint64_t>& scratch)
{
  if (keys.size() < kRadixSortFrom)
  {
    std::sort(keys.begin(), keys.end());
    return;
  }
  reserve_to_overwrite(scratch, keys.capacity());
  scratch.resize(keys.size());
  if (sort_keys(keys.data(), scratch.data(), keys.size()) != keys.data())
  {
    keys.swap(scratch);
  }
}

/// A run per worker, at most.
constexpr std::size_t kMaxRuns = static_cast<std::size_t>(kWorkerCount.max);

/// Sorted runs of distinct keys, one per part, end to end.
struct SortedRuns
{
  SortedRuns(const std::uint64_t* sorted, const std::uint32_t* counts, std::size_t stride, std::size_t parts)
    : keys(sorted), count(parts)
  {
    // The run of part p has counts[p * stride] keys.
    for (std::size_t p = 0; p < parts; ++p)
    {
      start[p + 1] = start[p] + counts[p * stride];
    }
  }
  std::size_t begin(std::size_t p) const { return start[p]; }
  std::size_t end(std::size_t p) const { return start[p + 1]; }
  std::size_t total() const { return start[count]; }
  /// How many keys of all the runs are below v.
  std::size_t below(std::uint64_t v) const
  {
    std::size_t n = 0;
    for (std::size_t p = 0; p < count; ++p)
    {
      n += static_cast<std::size_t>(std::lower_bound(keys + begin(p), keys + end(p), v) - (keys + begin(p)));
    }
    return n;
  }
  /// The key that `rank` keys of all the runs are below (rank < total()):
  /// each run's keys below it are the run's part of the first `rank`.
  std::uint64_t at_rank(std::size_t rank) const
  {
    std::uint64_t lo = 0;
    std::uint64_t hi = UINT64_MAX;
    while (lo < hi)
    {
      const std::uint64_t mid = lo + (hi - lo) / 2 + 1;
      if (below(mid) <= rank)
      {
        lo = mid;
      }
      else
      {
        hi = mid - 1;
      }
    }
    return lo;
  }

  const std::uint64_t* keys;
  std::size_t count;  ///< runs
  std::array<std::size_t, kMaxRuns + 1> start{};
};

/// Writes places [from, to) of the merged runs into `out`.
void merge_share(const SortedRuns& runs, std::size_t from, std::size_t to, std::uint64_t* out)
{
  std::array<std::size_t, kMaxRuns> head{};
  std::array<std::size_t, kMaxRuns> stop{};
  const std::size_t total = runs.total();
  const std::uint64_t first = from < total ? runs.at_rank(from) : UINT64_MAX;
  const std::uint64_t last = to < total ? runs.at_rank(to) : UINT64_MAX;
  for (std::size_t p = 0; p < runs.count; ++p)
  {
    const std::uint64_t* b = runs.keys + runs.begin(p);
    const std::uint64_t* e = runs.keys + runs.end(p);
    head[p] = static_cast<std::size_t>((from < total ? std::lower_bound(b, e, first) : e) - runs.keys);
    stop[p] = static_cast<std::size_t>((to < total ? std::lower_bound(b, e, last) : e) - runs.keys);
  }
  for (std::size_t k = from; k < to; ++k)
  {
    std::size_t take = runs.count;
    for (std::size_t p = 0; p < runs.count; ++p)
    {
      if (head[p] < stop[p] && (take == runs.count || runs.keys[head[p]] < runs.keys[head[take]]))
      {
        take = p;
      }
    }
    out[k] = runs.keys[head[take]++];
  }
}

}  // namespace

void SoftRows::order_manifolds(WorkerPool& workers)
{
  // At most one manifold per point: reserved so, the keys never grow by
  // copying, and the pages past the last manifold are never touched.
  const std::size_t parts = parts_for(workers);
  if (parts == 1)
  {
    order_.clear();
    reserve_to_overwrite(order_, notes_.size());
    for (std::size_t k = 0; k < notes_.size(); ++k)
    {
      if (notes_[k].first)
      {
        order_.push_back(std::uint64_t{notes_[k].key} << 32 | k);
      }
    }
    sort_by_height(order_, sort_scratch_);
    return;
  }
  resize_to_overwrite(order_, notes_.size());  // the parts write the first `total` keys
  resize_to_overwrite(sort_scratch_, notes_.size());
  resize_to_overwrite(part_counts_, parts * kPartCounts);
  workers.run_stages(3, [&](std::size_t stage, std::size_t part, std::size_t n) { order_part(stage, part, n); });
  order_.swap(sort_scratch_);  // the parts merged into sort_scratch_
  order_.resize(SortedRuns{order_.data(), part_counts_.data(), kPartCounts, parts}.total());
}

void SoftRows::order_part(std::size_t stage, std::size_t part, std::size_t parts)
{
  // Each part's manifolds go, in point order, after those of the parts
  // before it; each part sorts its own where it wrote them (in its core's
  // cache), and the parts then merge a share each into sort_scratch_. A
  // radix sort whose every digit's pass was shared moved each key between
  // the cores' caches on every pass, and took as long on two workers as on one.
  std::uint32_t* counts = part_counts_.data();
  const std::size_t n = notes_.size();
  if (stage == 0)
  {
    std::uint32_t mine = 0;
    for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
    {
      mine += notes_[k].first ? 1 : 0;
    }
    counts[part * kPartCounts] = mine;
    return;
  }
  const SortedRuns runs{order_.data(), counts, kPartCounts, parts};
  if (stage == 2)
  {
    const std::size_t total = runs.total();
    merge_share(runs, total * part / parts, total * (part + 1) / parts, sort_scratch_.data());
    return;
  }
  const std::size_t at = runs.begin(part);
  std::size_t next = at;
  for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
  {
    if (notes_[k].first)
    {
      order_[next++] = std::uint64_t{notes_[k].key} << 32 | k;
    }
  }
  const std::size_t mine = counts[part * kPartCounts];
  std::uint64_t* own = order_.data() + at;
  const std::uint64_t* sorted = sort_keys(own, sort_scratch_.data() + at, mine);
  if (sorted != own)
  {
    std::copy(sorted, sorted + mine, own);
  }
}

}  // namespace detail
}  // namespace collision2d
