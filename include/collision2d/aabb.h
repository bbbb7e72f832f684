// Axis-aligned bounding boxes for the broad phase.
#pragma once

#include <algorithm>

#include "collision2d/vec2.h"

namespace collision2d
{
struct Aabb
{
  Vec2 lo;
  Vec2 hi;

  /// Closed-interval test: boxes that merely touch still overlap, so the broad
  /// phase never drops a pair the narrow phase might call touching. All four
  /// comparisons are made (`&`, not `&&`): one branch for the test, where
  /// each comparison alone mispredicts often in a crowd of small boxes.
  bool overlaps(const Aabb& o) const
  {
    return (lo.x <= o.hi.x) & (o.lo.x <= hi.x) & (lo.y <= o.hi.y) & (o.lo.y <= hi.y);
  }
  Aabb inflated(double margin) const { return {{lo.x - margin, lo.y - margin}, {hi.x + margin, hi.y + margin}}; }
  /// The box swept by translating this one by d.
  Aabb swept(Vec2 d) const
  {
    return {{std::min(lo.x, lo.x + d.x), std::min(lo.y, lo.y + d.y)},
            {std::max(hi.x, hi.x + d.x), std::max(hi.y, hi.y + d.y)}};
  }
};

}  // namespace collision2d
