// Tests of the soft rows: each lane path this build and CPU run, in turn.
#pragma once

#include <cstdio>
#include <utility>

#include "soft_rows.h"

namespace collision2d
{
namespace test
{
/// Forces each lane path of the soft rows that is available here (scalar,
/// two lanes on SSE2 or NEON, four on AVX2, eight on AVX-512), calls
/// f(label) with it, and restores the default path.
template <class F>
void for_each_row_lanes(F f)
{
  const std::pair<detail::RowLanes, const char*> paths[] = {
      {detail::RowLanes::Scalar, "scalar"}, {detail::RowLanes::Two, "two-lane"}, {detail::RowLanes::Four, "four-lane"},
      {detail::RowLanes::Eight, "eight-lane"}};
  for (const auto& [path, label] : paths)
  {
    if (!detail::set_row_lanes(path))
    {
      std::printf("%s rows: not available here\n", label);
      continue;
    }
    f(label);
  }
  detail::reset_row_lanes();
}

}  // namespace test
}  // namespace collision2d
