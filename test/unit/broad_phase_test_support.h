// Broad-phase tests' references: the pairs a brute-force test of every box
// against every other finds, and the checks every pair list must pass.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/broad_phase.h"

namespace collision2d
{
namespace test
{
inline std::vector<Aabb> boxes_of(const std::vector<Body>& bodies)
{
  std::vector<Aabb> boxes;
  for (const Body& b : bodies)
  {
    boxes.push_back(b.aabb());
  }
  return boxes;
}

inline std::vector<BodyPair> brute_force(const std::vector<Aabb>& boxes)
{
  std::vector<BodyPair> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
    {
      if (boxes[i].overlaps(boxes[j]))
      {
        pairs.emplace_back(i, j);
      }
    }
  }
  return pairs;
}

inline void expect_sorted_unique_ordered(const std::vector<BodyPair>& pairs)
{
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    EXPECT_LT(pairs[k].first, pairs[k].second);
    if (k > 0)
    {
      EXPECT_LT(pairs[k - 1], pairs[k]);
    }
  }
}

/// Brute force restricted to usable boxes: finite, lo <= hi. The others pair
/// with nothing by contract.
inline std::vector<BodyPair> brute_force_usable(const std::vector<Aabb>& boxes)
{
  const auto usable = [](const Aabb& b) {
    return std::isfinite(b.lo.x) && std::isfinite(b.lo.y) && std::isfinite(b.hi.x) && std::isfinite(b.hi.y) &&
           b.lo.x <= b.hi.x && b.lo.y <= b.hi.y;
  };
  std::vector<BodyPair> pairs;
  for (const BodyPair& p : brute_force(boxes))
  {
    if (usable(boxes[p.first]) && usable(boxes[p.second]))
    {
      pairs.push_back(p);
    }
  }
  return pairs;
}

}  // namespace test
}  // namespace collision2d
