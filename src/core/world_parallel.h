// Internal to the core: how the World shares a stage among its workers
// (worker_pool.h), declared in world_impl.h, which includes this at its end.
// The per-body passes (for_each_body) are world_motion.h's: the motion
// layer below the contacts runs them too.
// Results are the same for any number of workers.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace collision2d
{
namespace detail
{
template <class F>
void WorldImpl::for_point_ranges(F f)
{
  workers_.parallel_for(points_.size(), kMinSharedPoints,
                        [&](std::size_t begin, std::size_t end) { f(pair_boundary(begin), pair_boundary(end)); });
}

template <class T, class F, class Fold>
T WorldImpl::fold_in_parts(std::size_t count, std::size_t min_shared, std::vector<T>& answers, T start, F answer,
                           Fold fold)
{
  const std::size_t parts = count < min_shared ? 1 : static_cast<std::size_t>(workers_.workers());
  if (parts == 1)
  {
    // Folded straight from registers: an answer stored to its slot field by
    // field and read back whole stalled the load (docs/performance.md).
    return fold(start, answer(std::size_t{0}, count));
  }
  // A part works in locals and stores once: the parts' slots share a cache
  // line, which writing them item by item would bounce.
  answers.resize(parts);
  workers_.parallel_for(parts, 2, [&](std::size_t begin, std::size_t end) {
    for (std::size_t part = begin; part < end; ++part)
    {
      answers[part] = answer(count * part / parts, count * (part + 1) / parts);
    }
  });
  T folded = start;
  for (const T& part : answers)
  {
    folded = fold(folded, part);
  }
  return folded;
}

template <class F>
double WorldImpl::max_over(std::size_t count, std::size_t min_shared, double start, F value)
{
  // std::max keeps the earlier of equal values and skips a NaN value, so the
  // parts' results folded in order give the one-thread bits.
  const auto part_max = [&](std::size_t begin, std::size_t end) {
    double best = start;
    for (std::size_t k = begin; k < end; ++k)
    {
      best = std::max(best, value(k));
    }
    return best;
  };
  return fold_in_parts(count, min_shared, partial_max_, start, part_max,
                       [](double best, double part) { return std::max(best, part); });
}

}  // namespace detail
}  // namespace collision2d
