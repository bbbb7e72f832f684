// Broad phase: a box that is not finite or has lo above hi (on either axis,
// at either corner) pairs with nothing, in the grid and where every pair of a
// few boxes is tested.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "broad_phase_test_support.h"
#include "collision2d/broad_phase.h"
#include "random_scene.h"

namespace collision2d
{
namespace
{
using test::boxes_of;
using test::brute_force_usable;
using test::expect_sorted_unique_ordered;

TEST(BroadPhase, NonFiniteAndInvertedBoxesPairWithNothing)
{
  std::vector<Aabb> boxes = boxes_of(test::random_scene(8, 200, {12.0, 12.0}));
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::size_t> bad{3, 40, 41, 100, 150};
  boxes[3] = Aabb{{-inf, -inf}, {inf, inf}};
  boxes[40] = Aabb{{nan, 1.0}, {2.0, 3.0}};
  boxes[41] = Aabb{{1.0, 1.0}, {2.0, nan}};
  boxes[100] = Aabb{{5.0, 5.0}, {4.0, 6.0}};  // lo > hi along x
  boxes[150] = Aabb{{nan, nan}, {nan, nan}};
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  broad_phase.find_pairs(boxes, pairs);
  EXPECT_EQ(pairs, brute_force_usable(boxes));
  for (const BodyPair& p : pairs)
  {
    EXPECT_EQ(std::count(bad.begin(), bad.end(), p.first), 0);
    EXPECT_EQ(std::count(bad.begin(), bad.end(), p.second), 0);
  }
  EXPECT_GT(pairs.size(), 10u);
  std::vector<Aabb> all_bad(10, Aabb{{nan, nan}, {nan, nan}});
  broad_phase.find_pairs(all_bad, pairs);
  EXPECT_TRUE(pairs.empty());
}

TEST(BroadPhase, FewBoxesTestedPairwiseMatchTheGrid)
{
  // From 1 box to 16, across the size where every pair is tested instead of
  // gridded, on one reused broad phase: the same pairs, sorted, and no pair
  // with an unusable box.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  std::size_t found = 0;
  for (unsigned seed = 1; seed <= 40; ++seed)
  {
    const std::size_t n = 1 + seed % 16;
    std::vector<Aabb> boxes = boxes_of(test::random_scene(seed, n, {3.0, 3.0}));
    if (seed % 5 == 0)
    {
      boxes[seed % n] = Aabb{{nan, 0.0}, {1.0, 1.0}};
    }
    if (seed % 3 == 0)
    {
      // Inverted along x inside the scene: plain overlap tests would pair it.
      boxes.back() = Aabb{{1.5, -1.0}, {1.49, 4.0}};
    }
    broad_phase.find_pairs(boxes, pairs);
    EXPECT_EQ(pairs, brute_force_usable(boxes)) << n << " boxes, seed " << seed;
    expect_sorted_unique_ordered(pairs);
    found += pairs.size();
  }
  EXPECT_GT(found, 40u) << "scenes too sparse to test anything";
}

TEST(BroadPhase, FewBoxesOfEveryUnusableKindPairWithNothing)
{
  // Every box tested pairwise (at most BroadPhase::kAllPairsBoxes): each
  // kind of unusable box, on either axis and either corner, inside a crowd
  // of usable boxes that all overlap it, and two usable boxes that only touch.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Aabb> bad{
      Aabb{{nan, 0.0}, {1.0, 1.0}},  Aabb{{0.0, nan}, {1.0, 1.0}},  Aabb{{0.0, 0.0}, {nan, 1.0}},
      Aabb{{0.0, 0.0}, {1.0, nan}},  Aabb{{-inf, 0.0}, {1.0, 1.0}}, Aabb{{0.0, -inf}, {1.0, 1.0}},
      Aabb{{0.0, 0.0}, {inf, 1.0}},  Aabb{{0.0, 0.0}, {1.0, inf}},  Aabb{{-inf, -inf}, {inf, inf}},
      Aabb{{0.6, 0.0}, {0.4, 1.0}},  Aabb{{0.0, 0.6}, {1.0, 0.4}},
  };
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  for (const Aabb& unusable : bad)
  {
    const std::vector<Aabb> boxes{Aabb{{-1.0, -1.0}, {0.5, 0.5}}, unusable, Aabb{{0.5, 0.5}, {2.0, 2.0}},
                                  Aabb{{0.2, 0.2}, {0.8, 0.8}}};
    ASSERT_LE(boxes.size(), BroadPhase::kAllPairsBoxes);
    broad_phase.find_pairs(boxes, pairs);
    EXPECT_EQ(pairs, brute_force_usable(boxes));
    const std::vector<BodyPair> expected{{0, 2}, {0, 3}, {2, 3}};  // 0 and 2 meet at a corner
    EXPECT_EQ(pairs, expected) << "unusable box " << unusable.lo.x << " " << unusable.lo.y << " "
                               << unusable.hi.x << " " << unusable.hi.y;
  }
}

}  // namespace
}  // namespace collision2d
