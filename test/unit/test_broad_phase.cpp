// Broad phase: the grid must find exactly the overlapping box pairs a
// brute-force all-pairs test finds, sorted and unique, however it is reused and
// whatever the mix of sizes, and a warmed-up broad phase must not allocate.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <vector>

#include "broad_phase_test_support.h"
#include "collision2d/broad_phase.h"
#include "random_scene.h"
#include "range_runners.h"

#include "allocation_counter.h"

namespace collision2d
{
namespace
{
constexpr int kSceneBodies = 400;
using test::boxes_of;
using test::brute_force;
using test::expect_sorted_unique_ordered;

/// The unit boxes of a pyramid with `base` boxes in its lowest row, touching.
std::vector<Aabb> pyramid_boxes(int base)
{
  std::vector<Aabb> boxes;
  for (int row = 0; row < base; ++row)
  {
    for (int k = 0; k < base - row; ++k)
    {
      const Vec2 lo{0.5 * row + k, static_cast<double>(row)};
      boxes.push_back(Aabb{lo, lo + Vec2{1.0, 1.0}});
    }
  }
  return boxes;
}

TEST(BroadPhase, ARunnerFindsTheSamePairs)
{
  // Enough boxes that the runner's parts search the grid: a random scene,
  // and a pyramid, whose boxes crowd the lower rows of its dense grid (the
  // parts split the entries, not the rows).
  for (const std::vector<Aabb>& boxes :
       {boxes_of(test::random_scene(11, 6000, {150.0, 150.0})), pyramid_boxes(100)})
  {
    BroadPhase alone;
    BroadPhase shared;
    test::ReversedRunner runner;
    std::vector<BodyPair> want;
    std::vector<BodyPair> pairs;
    alone.find_pairs(boxes, want);
    shared.find_pairs(boxes, pairs, runner);
    EXPECT_GT(want.size(), 1000u) << "scene too sparse to test anything";
    EXPECT_EQ(pairs, want);
    EXPECT_EQ(want, brute_force(boxes));
    // Again, the parts now sharing the sort by the last call's pairs, and
    // with its pairs still in the list they replace.
    shared.find_pairs(boxes, pairs, runner);
    EXPECT_EQ(pairs, want);
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

Aabb box_at(Vec2 centre, Vec2 half)
{
  return {centre - half, centre + half};
}

TEST(BroadPhase, MixedSizesWithHugeGroundAndWalls)
{
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  const double side = 30.0;  // m
  for (unsigned seed = 11; seed < 14; ++seed)
  {
    std::vector<Aabb> boxes = boxes_of(test::random_scene(seed, kSceneBodies, {side, side}));
    // A ground slab far wider than the scene, walls as tall as it, and a
    // mid-sized plank: none of them fits a cell of the bodies' size.
    boxes.insert(boxes.begin() + 50, box_at({0.5 * side, 0.4}, {1e4, 0.6}));
    boxes.push_back(box_at({0.0, 0.5 * side}, {0.3, 0.5 * side}));
    boxes.push_back(box_at({side, 0.5 * side}, {0.3, 0.5 * side}));
    boxes.push_back(box_at({0.5 * side, 0.4 * side}, {6.0, 0.2}));
    broad_phase.find_pairs(boxes, pairs);
    const std::vector<BodyPair> want = brute_force(boxes);
    EXPECT_EQ(pairs, want) << "seed " << seed;
    const auto with_ground = std::count_if(want.begin(), want.end(), [](const BodyPair& p) {
      return p.first == 50 || p.second == 50;
    });
    EXPECT_GT(with_ground, 5) << "the ground should touch the bottom row of bodies";
  }
}

TEST(BroadPhase, CrowdInsideOneCellOfLargerBodies)
{
  // Most boxes are 1 m wide (so the cells are), and 200 tiny ones crowd into
  // a 0.4 m patch: one cell holds them all, only some of them overlap.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> scene(0.0, 20.0);
  std::uniform_real_distribution<double> patch(10.0, 10.4);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 700; ++i)
  {
    boxes.push_back(box_at({scene(rng), scene(rng)}, {0.5, 0.5}));
  }
  for (int i = 0; i < 200; ++i)
  {
    boxes.push_back(box_at({patch(rng), patch(rng)}, {0.01, 0.01}));
  }
  std::shuffle(boxes.begin(), boxes.end(), rng);
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  broad_phase.find_pairs(boxes, pairs);
  const std::vector<BodyPair> want = brute_force(boxes);
  EXPECT_EQ(pairs, want);
  EXPECT_LT(want.size(), 900u * 899u / 4u) << "the crowd should not be all-overlapping";
}

TEST(BroadPhase, EveryBoxInOneSpotPairsWithAll)
{
  // Identical boxes, then nearly identical ones: every pair overlaps.
  constexpr std::size_t kCount = 150;
  std::vector<Aabb> boxes(kCount, box_at({3.0, -2.0}, {0.25, 0.25}));
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  broad_phase.find_pairs(boxes, pairs);
  EXPECT_EQ(pairs.size(), kCount * (kCount - 1) / 2);
  EXPECT_EQ(pairs, brute_force(boxes));
  for (std::size_t i = 0; i < kCount; ++i)
  {
    boxes[i] = box_at({3.0 + 1e-3 * static_cast<double>(i % 7), -2.0}, {0.25, 0.25});
  }
  broad_phase.find_pairs(boxes, pairs);
  EXPECT_EQ(pairs, brute_force(boxes));
  // Points (zero-size boxes) on one spot: the cell size cannot come from them.
  std::vector<Aabb> points(kCount, Aabb{{1.0, 1.0}, {1.0, 1.0}});
  broad_phase.find_pairs(points, pairs);
  EXPECT_EQ(pairs.size(), kCount * (kCount - 1) / 2);
}

TEST(BroadPhase, TallColumnOfTouchingBoxes)
{
  // Boxes stacked so each one's top is exactly the next one's bottom, on a
  // ground slab; neighbours touch and must be paired, nothing else overlaps.
  constexpr int kHeight = 300;
  constexpr double kSide = 0.5;  // m
  std::vector<Aabb> boxes{Aabb{{-50.0, -1.0}, {50.0, 0.0}}};
  for (int i = 0; i < kHeight; ++i)
  {
    boxes.push_back(Aabb{{0.0, kSide * i}, {kSide, kSide * (i + 1)}});
  }
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  broad_phase.find_pairs(boxes, pairs);
  EXPECT_EQ(pairs.size(), static_cast<std::size_t>(kHeight));
  EXPECT_EQ(pairs, brute_force(boxes));
}

TEST(BroadPhase, FarAwayAndHugeCoordinates)
{
  // A scene 1e6 m from the origin, plus finite boxes at the ends of the double
  // range (cell indices saturate there) and a box as wide as the range.
  std::vector<Aabb> boxes = boxes_of(test::random_scene(21, 200, {15.0, 15.0}));
  for (Aabb& box : boxes)
  {
    box = {box.lo + Vec2{1e6, -1e6}, box.hi + Vec2{1e6, -1e6}};
  }
  const double big = 0.5 * std::numeric_limits<double>::max();
  boxes.push_back(box_at({big, big}, {1.0, 1.0}));
  boxes.push_back(box_at({big, big}, {2.0, 0.5}));
  boxes.push_back(box_at({-big, 0.0}, {1.0, 1.0}));
  boxes.push_back(Aabb{{-big, -1e6 + 7.0}, {big, -1e6 + 7.1}});
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  broad_phase.find_pairs(boxes, pairs);
  EXPECT_EQ(pairs, brute_force(boxes));
}

TEST(BroadPhase, WarmedUpCallsAllocateNothing)
{
  // Ten frames of a moving scene with a ground slab, played twice: the second
  // time every buffer (the broad phase's and the caller's pair list) already
  // has the capacity the frames need.
  std::vector<std::vector<Aabb>> frames;
  std::vector<Aabb> boxes = boxes_of(test::random_scene(17, kSceneBodies, {20.0, 20.0}));
  boxes.push_back(box_at({10.0, -0.5}, {100.0, 0.5}));
  for (int f = 0; f < 10; ++f)
  {
    for (Aabb& box : boxes)
    {
      box = {box.lo + Vec2{0.03, -0.02}, box.hi + Vec2{0.03, -0.02}};
    }
    frames.push_back(boxes);
  }
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  for (const std::vector<Aabb>& frame : frames)
  {
    broad_phase.find_pairs(frame, pairs);
  }
  const long before = test::g_allocations.load();
  for (const std::vector<Aabb>& frame : frames)
  {
    broad_phase.find_pairs(frame, pairs);
  }
  EXPECT_EQ(test::g_allocations.load() - before, 0);
  EXPECT_EQ(pairs, brute_force(frames.back()));
  EXPECT_GT(test::g_allocations.load() - before, 0) << "the counter must see the brute force's allocations";
}

}  // namespace
}  // namespace collision2d
