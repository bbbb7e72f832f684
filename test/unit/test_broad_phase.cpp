// Broad phase: the sweep must find exactly the overlapping box pairs a
// brute-force all-pairs test finds, sorted and unique, however it is reused.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "collision2d/broad_phase.h"
#include "random_scene.h"

namespace collision2d
{
namespace
{
constexpr int kSceneBodies = 400;

std::vector<Aabb> boxes_of(const std::vector<Body>& bodies)
{
  std::vector<Aabb> boxes;
  for (const Body& b : bodies)
  {
    boxes.push_back(b.aabb());
  }
  return boxes;
}

std::vector<BodyPair> brute_force(const std::vector<Aabb>& boxes)
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

void expect_sorted_unique_ordered(const std::vector<BodyPair>& pairs)
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

TEST(BroadPhase, MatchesBruteForceOnRandomScenes)
{
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  // Wide, tall and square scenes, so both sweep axes are used.
  const Vec2 extents[] = {{40.0, 8.0}, {8.0, 40.0}, {18.0, 18.0}};
  unsigned seed = 7;
  for (const Vec2& extent : extents)
  {
    for (int repeat = 0; repeat < 3; ++repeat)
    {
      const std::vector<Aabb> boxes = boxes_of(test::random_scene(seed++, kSceneBodies, extent));
      broad_phase.find_pairs(boxes, pairs);
      const std::vector<BodyPair> want = brute_force(boxes);
      EXPECT_GT(want.size(), 20u) << "scene too sparse to test anything";
      EXPECT_EQ(pairs, want) << "seed " << seed - 1;
      expect_sorted_unique_ordered(pairs);
    }
  }
}

TEST(BroadPhase, ReuseAcrossMovingAndResizedScenes)
{
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  std::mt19937 rng(99);
  std::normal_distribution<double> jitter(0.0, 0.05);
  std::vector<Aabb> boxes = boxes_of(test::random_scene(3, kSceneBodies, {20.0, 20.0}));
  for (int frame = 0; frame < 20; ++frame)
  {
    // Small coherent motion, then every fifth frame a reshuffle of indices
    // (the previous order is then far from sorted) and a change of count.
    for (Aabb& box : boxes)
    {
      const Vec2 d{jitter(rng), jitter(rng)};
      box = {box.lo + d, box.hi + d};
    }
    if (frame % 5 == 4)
    {
      std::shuffle(boxes.begin(), boxes.end(), rng);
      boxes.resize(boxes.size() - 17);
    }
    broad_phase.find_pairs(boxes, pairs);
    EXPECT_EQ(pairs, brute_force(boxes)) << "frame " << frame;
  }
}

TEST(BroadPhase, TouchingBoxesArePairedAndSmallInputsWork)
{
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs{{5, 6}};  // stale content must be replaced
  broad_phase.find_pairs({}, pairs);
  EXPECT_TRUE(pairs.empty());
  broad_phase.find_pairs({Aabb{{0.0, 0.0}, {1.0, 1.0}}}, pairs);
  EXPECT_TRUE(pairs.empty());
  // Corner to corner and edge to edge both count (closed boxes).
  const std::vector<Aabb> boxes{{{0.0, 0.0}, {1.0, 1.0}}, {{1.0, 1.0}, {2.0, 2.0}}, {{2.0, 0.0}, {3.0, 1.0}},
                                {{5.0, 5.0}, {6.0, 6.0}}};
  broad_phase.find_pairs(boxes, pairs);
  const std::vector<BodyPair> want{{0, 1}, {1, 2}};
  EXPECT_EQ(pairs, want);
}

}  // namespace
}  // namespace collision2d
