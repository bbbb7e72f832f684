// The resting grid (src/core/resting_grid.h): queried from every moving box,
// with its large members paired by the caller, it must find exactly the
// (mover, resting) pairs whose boxes overlap, each once, for any mix of
// sizes, touching boxes, huge and non-finite ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "resting_grid.h"

namespace collision2d
{
namespace
{
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

Aabb box_at(double x, double y, double w, double h) { return {{x, y}, {x + w, y + h}}; }

/// Every (mover, resting) pair found by testing each mover against every resting box.
std::vector<BodyPair> brute_force(const std::vector<Aabb>& boxes, const std::vector<bool>& moving)
{
  std::vector<BodyPair> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    for (std::size_t j = 0; j < boxes.size(); ++j)
    {
      const bool finite = std::isfinite(boxes[i].lo.x + boxes[i].hi.x + boxes[i].lo.y + boxes[i].hi.y) &&
                          std::isfinite(boxes[j].lo.x + boxes[j].hi.x + boxes[j].lo.y + boxes[j].hi.y);
      const bool proper = boxes[i].lo.x <= boxes[i].hi.x && boxes[i].lo.y <= boxes[i].hi.y &&
                          boxes[j].lo.x <= boxes[j].hi.x && boxes[j].lo.y <= boxes[j].hi.y;
      if (moving[i] && !moving[j] && finite && proper && boxes[i].overlaps(boxes[j]))
      {
        pairs.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<BodyPair> from_grid(const std::vector<Aabb>& boxes, const std::vector<bool>& moving)
{
  std::vector<std::size_t> resting;
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    if (!moving[i])
    {
      resting.push_back(i);
    }
  }
  detail::RestingGrid grid;
  grid.build(boxes, resting);
  std::vector<BodyPair> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    if (moving[i])
    {
      grid.query(boxes[i], i, pairs);
      // The large members are the caller's to pair.
      for (std::size_t j : grid.large())
      {
        if (boxes[i].overlaps(boxes[j]) && std::isfinite(boxes[i].lo.x + boxes[i].hi.x + boxes[i].lo.y + boxes[i].hi.y) &&
            boxes[i].lo.x <= boxes[i].hi.x && boxes[i].lo.y <= boxes[i].hi.y)
        {
          pairs.emplace_back(std::min(i, j), std::max(i, j));
        }
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

TEST(RestingGrid, MatchesBruteForceOnRandomScenes)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> where(-50.0, 50.0);
  std::uniform_real_distribution<double> size(0.05, 3.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int scene = 0; scene < 20; ++scene)
  {
    std::vector<Aabb> boxes;
    std::vector<bool> moving;
    for (int k = 0; k < 600; ++k)
    {
      // A few boxes much larger than the rest (walls, a ground slab).
      const double scale = unit(rng) < 0.02 ? 40.0 : 1.0;
      boxes.push_back(box_at(where(rng), where(rng), scale * size(rng), size(rng)));
      moving.push_back(unit(rng) < (scene % 2 == 0 ? 0.1 : 0.7));
    }
    const std::vector<BodyPair> expected = brute_force(boxes, moving);
    EXPECT_EQ(from_grid(boxes, moving), expected) << "scene " << scene;
  }
}

TEST(RestingGrid, TouchingHugeFarAndNonFiniteBoxes)
{
  std::vector<Aabb> boxes = {
      box_at(0.0, 0.0, 1.0, 1.0),     // resting
      box_at(1.0, 0.0, 1.0, 1.0),     // moving, touches 0 along an edge
      box_at(-1e3, -1.0, 2e3, 1.0),   // a ground slab under both
      box_at(1e9, 1e9, 1.0, 1.0),     // far away, resting
      box_at(1e9 + 0.5, 1e9, 1.0, 1.0),  // far away, moving: overlaps 3
      {{kNan, 0.0}, {1.0, 1.0}},      // non-finite: pairs with nothing
      {{2.0, 2.0}, {1.0, 1.0}},       // inverted: pairs with nothing
      box_at(-1e6, -1e6, 2e6, 2e6),   // a moving box covering everything
  };
  const std::vector<bool> moving = {false, true, false, false, true, false, false, true};
  const std::vector<BodyPair> expected = brute_force(boxes, moving);
  EXPECT_EQ(from_grid(boxes, moving), expected);
  EXPECT_TRUE(std::find(expected.begin(), expected.end(), BodyPair{0, 1}) != expected.end());
  EXPECT_TRUE(std::find(expected.begin(), expected.end(), BodyPair{3, 4}) != expected.end());
}

TEST(RestingGrid, EmptyGridAndNoMovers)
{
  const std::vector<Aabb> boxes = {box_at(0.0, 0.0, 1.0, 1.0), box_at(0.5, 0.5, 1.0, 1.0)};
  EXPECT_TRUE(from_grid(boxes, {true, true}).empty());
  EXPECT_TRUE(from_grid(boxes, {false, false}).empty());
  EXPECT_EQ(from_grid(boxes, {true, false}), (std::vector<BodyPair>{{0, 1}}));
}

}  // namespace
}  // namespace collision2d
