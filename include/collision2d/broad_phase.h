// Broad phase: candidate pairs whose bounding boxes overlap, below O(n^2) for
// scattered scenes.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "collision2d/aabb.h"

namespace collision2d
{
using BodyPair = std::pair<std::size_t, std::size_t>;

/// Sort-and-sweep along the axis of largest spread. Keeps its scratch buffers
/// between calls, so a world that calls it every substep allocates nothing once
/// warmed up.
class BroadPhase
{
public:
  /// Replaces `pairs` with every (i, j), i < j, whose boxes overlap, sorted by
  /// (i, j) so results do not depend on the sweep order.
  void find_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs);

private:
  struct Endpoint
  {
    double lo;
    double hi;
    std::size_t index;
  };
  std::vector<Endpoint> sorted_;
};

}  // namespace collision2d
