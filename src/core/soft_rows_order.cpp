// The soft step's manifolds in height order (soft_rows.h): one key per noted
// manifold, radix sorted. In a large frame the workers share it: each takes a
// part of the notes, then a part of the keys in every digit's pass, and the
// parts meet between the counting and the moving, so every key lands where
// one pass puts it.
#include <algorithm>
#include <array>
#include <utility>

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

/// Sorts keys by their high half, keeping the order of equal ones: a least
/// significant digit radix sort, linear where a comparison sort cost more
/// than the colouring it orders. One pass counts every digit. The low halves
/// are distinct and ascending, so a comparison sort of the whole keys gives
/// the same order: below kRadixSortFrom keys it is cheaper than clearing and
/// summing the digit counts.
void sort_by_height(FrameBuffer<std::uint64_t>& keys, FrameBuffer<std::uint64_t>& scratch)
{
  if (keys.size() < kRadixSortFrom)
  {
    std::sort(keys.begin(), keys.end());
    return;
  }
  std::array<std::array<std::size_t, kDigits>, kKeyDigits> start{};
  for (const std::uint64_t key : keys)
  {
    for (int d = 0; d < kKeyDigits; ++d)
    {
      ++start[d][digit(key, d)];
    }
  }
  reserve_to_overwrite(scratch, keys.capacity());
  scratch.resize(keys.size());
  for (int d = 0; d < kKeyDigits; ++d)
  {
    if (keys.empty() || start[d][digit(keys.front(), d)] == keys.size())
    {
      continue;  // one value of this digit for all: nothing moves
    }
    std::size_t sum = 0;
    for (std::size_t& s : start[d])
    {
      sum += std::exchange(s, sum);
    }
    for (const std::uint64_t key : keys)
    {
      scratch[start[d][digit(key, d)]++] = key;
    }
    keys.swap(scratch);
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
  resize_to_overwrite(part_counts_, 2 * parts * kPartCounts);
  workers.run_team([&](std::size_t part) { order_part(part, parts, workers); });
  if (order_in_scratch_)
  {
    order_.swap(sort_scratch_);
  }
  order_.resize(ordered_);
  if (ordered_ < kRadixSortFrom)
  {
    std::sort(order_.begin(), order_.end());  // the parts left them in point order
  }
}

void SoftRows::order_part(std::size_t part, std::size_t parts, WorkerPool& workers)
{
  // Round r's counts are set r % 2: a part reads round r's until it moves
  // its keys, and writes round r + 2's only after the meeting that follows.
  const auto counts = [&](int round, std::size_t p) { return &part_counts_[((round % 2) * parts + p) * kPartCounts]; };
  // Round 0: each part's manifolds, then their keys below the parts after it.
  const std::size_t n = notes_.size();
  std::uint32_t mine = 0;
  for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
  {
    mine += notes_[k].first ? 1 : 0;
  }
  counts(0, part)[0] = mine;
  workers.sync();
  std::size_t total = 0;
  std::size_t at = 0;
  for (std::size_t p = 0; p < parts; ++p)
  {
    at += p < part ? counts(0, p)[0] : 0;
    total += counts(0, p)[0];
  }
  for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
  {
    if (notes_[k].first)
    {
      order_[at++] = std::uint64_t{notes_[k].key} << 32 | k;
    }
  }
  if (part == 0)
  {
    ordered_ = total;
    order_in_scratch_ = false;
  }
  if (total < kRadixSortFrom)
  {
    return;  // order_manifolds sorts them
  }
  workers.sync();
  // Rounds 1 ..: a digit each. The keys of a part's share go, in order,
  // after those of every smaller digit and of the parts before it.
  std::uint64_t* from = order_.data();
  std::uint64_t* to = sort_scratch_.data();
  const std::size_t begin = total * part / parts;
  const std::size_t end = total * (part + 1) / parts;
  for (int d = 0; d < kKeyDigits; ++d)
  {
    const int round = d + 1;
    std::uint32_t* own = counts(round, part);
    std::fill(own, own + kDigits, 0U);
    for (std::size_t k = begin; k < end; ++k)
    {
      ++own[digit(from[k], d)];
    }
    workers.sync();
    std::array<std::size_t, kDigits> start{};
    std::size_t sum = 0;
    for (std::size_t v = 0; v < kDigits; ++v)
    {
      std::size_t before = 0;
      std::size_t all = 0;
      for (std::size_t p = 0; p < parts; ++p)
      {
        before += p < part ? counts(round, p)[v] : 0;
        all += counts(round, p)[v];
      }
      if (all == total)
      {
        break;  // one value of this digit for all: nothing moves (every part sees it)
      }
      start[v] = sum + before;
      sum += all;
    }
    if (sum == 0)
    {
      continue;
    }
    for (std::size_t k = begin; k < end; ++k)
    {
      to[start[digit(from[k], d)]++] = from[k];
    }
    workers.sync();
    std::swap(from, to);
  }
  if (part == 0)
  {
    order_in_scratch_ = from != order_.data();
  }
}

}  // namespace detail
}  // namespace collision2d
