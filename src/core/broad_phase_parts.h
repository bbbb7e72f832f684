// Internal to the core: how the broad phase shares a pass among the parts of
// a RangeRunner (broad_phase.h). Each part writes only its own items' slots
// or its own list, so the pairs are the same for any runner.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/broad_phase.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace collision2d
{
namespace detail
{
/// Boxes or grid entries below which a pass stays in one part: too little
/// work to pay for waking the runner's threads.
constexpr std::size_t kMinSharedBroadItems = 4096;

/// Cells in the inclusive range [x0, x1] x [y0, y1].
inline std::int64_t cell_area(std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1)
{
  return (static_cast<std::int64_t>(x1) - x0 + 1) * (static_cast<std::int64_t>(y1) - y0 + 1);
}

/// Whether a box takes part in pairing: finite, with lo <= hi on both axes.
/// Any other box is empty and pairs with nothing.
inline bool is_usable(const Aabb& box)
{
  return std::isfinite(box.lo.x) && std::isfinite(box.lo.y) && std::isfinite(box.hi.x) &&
         std::isfinite(box.hi.y) && box.lo.x <= box.hi.x && box.lo.y <= box.hi.y;
}

#if defined(__SSE2__)
/// _mm_movemask_pd of a test that holds on both axes of an (x, y) pair.
constexpr int kBothAxes = 3;

/// is_usable on a box's corners held as (x, y) pairs: x - x is 0 only for a
/// finite x, so both axes are tested at once.
inline bool is_usable(__m128d lo, __m128d hi)
{
  const __m128d finite = _mm_cmpord_pd(_mm_sub_pd(lo, lo), _mm_sub_pd(hi, hi));
  return _mm_movemask_pd(_mm_and_pd(finite, _mm_cmple_pd(lo, hi))) == kBothAxes;
}
#endif

/// How many parts a pass over `count` items takes (1: not shared).
inline std::size_t runner_parts(const RangeRunner* runner, std::size_t count)
{
  if (runner == nullptr || count < kMinSharedBroadItems)
  {
    return 1;
  }
  return static_cast<std::size_t>(std::max(runner->workers(), 1));
}

/// Part `part` of `parts` of [0, n): its first item.
inline std::size_t part_begin(std::size_t n, std::size_t part, std::size_t parts) { return n * part / parts; }

/// Calls f(part) for every part in [0, parts) on the runner's threads.
template <class F>
void run_parts(RangeRunner& runner, std::size_t parts, F f)
{
  runner.run(
      parts,
      [](void* context, std::size_t begin, std::size_t end) {
        for (std::size_t part = begin; part < end; ++part)
        {
          (*static_cast<F*>(context))(part);
        }
      },
      &f);
}

/// Calls f(part) for every part in [0, parts): on the calling thread when
/// there is one part, else on the runner's threads.
template <class F>
void for_each_part(RangeRunner* runner, std::size_t parts, F f)
{
  if (parts == 1)
  {
    f(0);
    return;
  }
  run_parts(*runner, parts, f);
}

/// Calls fill(part, list) for every part on the runner's threads, each with
/// its own list from `lists` (emptied, its storage kept from the last call),
/// then replaces `out` with the lists in part order, copied in parts: what one
/// pass appending in order gives. `out` is resized over its old contents, so
/// only the slots past its old size are zeroed first.
template <class T, class Fill>
void collect_in_parts(RangeRunner& runner, std::size_t parts, std::vector<std::vector<T>>& lists,
                      std::vector<T>& out, Fill fill)
{
  lists.resize(parts);
  run_parts(runner, parts, [&](std::size_t part) {
    // A local list: the parts' list headers share a cache line, which every
    // item added would otherwise write.
    std::vector<T> list;
    list.swap(lists[part]);
    list.clear();
    fill(part, list);
    list.swap(lists[part]);
  });
  std::size_t total = 0;
  for (const std::vector<T>& list : lists)
  {
    total += list.size();
  }
  out.resize(total);
  run_parts(runner, parts, [&](std::size_t part) {
    std::size_t at = 0;
    for (std::size_t p = 0; p < part; ++p)
    {
      at += lists[p].size();
    }
    std::copy(lists[part].begin(), lists[part].end(), out.begin() + static_cast<std::ptrdiff_t>(at));
  });
}

}  // namespace detail
}  // namespace collision2d
