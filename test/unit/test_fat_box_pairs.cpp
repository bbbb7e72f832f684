// The broad phase's pairs kept from frame to frame (src/core/fat_box_pairs.h):
// every frame's pairs must be exactly BroadPhase's for the boxes of that
// frame, whether the kept pairs were reused or found again, for boxes that
// jitter in place, jump, turn unusable (non-finite, inverted) or huge, and
// when the list of bodies changes; and on a runner's parts as on one. Boxes
// that keep moving never pair their enlarged ones; boxes of a settling stack
// take their pairs from enlarged ones made again as they sink. A few boxes
// are paired directly.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "fat_box_pairs.h"
#include "range_runners.h"

namespace collision2d
{
namespace
{
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

class SerialRunner : public RangeRunner
{
public:
  int workers() const override { return 1; }
  void run(std::size_t count, Job job, void* context) override { job(context, 0, count); }
};

/// Unit boxes in rows one above the other, `pitch` apart along a row, every
/// other row shifted by `shift`.
std::vector<Aabb> row_boxes(std::size_t columns, std::size_t rows, double pitch, double shift)
{
  std::vector<Aabb> boxes;
  for (std::size_t r = 0; r < rows; ++r)
  {
    for (std::size_t c = 0; c < columns; ++c)
    {
      const double x = static_cast<double>(c) * pitch + shift * static_cast<double>(r % 2);
      const double y = static_cast<double>(r) * 1.0;
      boxes.push_back({{x, y}, {x + 1.0, y + 1.0}});
    }
  }
  return boxes;
}

/// A loose grid: each box touches or nearly touches its neighbours.
std::vector<Aabb> grid_boxes(std::size_t columns, std::size_t rows) { return row_boxes(columns, rows, 1.02, 0.0); }

/// Bricks, each touching its neighbours: as in a stack, the enlarged boxes
/// pair with few more boxes than the exact ones.
std::vector<Aabb> brick_boxes(std::size_t columns, std::size_t rows) { return row_boxes(columns, rows, 1.0, 0.5); }

/// Every box moved by d (m).
void move_all(std::vector<Aabb>& boxes, Vec2 d)
{
  for (Aabb& box : boxes)
  {
    box = {box.lo + d, box.hi + d};
  }
}

/// One frame: the kept pairs' answer against a fresh broad phase's.
void expect_same_pairs(detail::FatBoxPairs& kept, const std::vector<Aabb>& boxes, RangeRunner& runner)
{
  BroadPhase fresh;
  BroadPhase reused;
  std::vector<BodyPair> want;
  std::vector<BodyPair> pairs;
  fresh.find_pairs(boxes, want);
  kept.find_pairs(boxes, reused, pairs, runner);
  EXPECT_EQ(pairs, want);
}

void expect_same_pairs(detail::FatBoxPairs& kept, const std::vector<Aabb>& boxes)
{
  SerialRunner runner;
  expect_same_pairs(kept, boxes, runner);
}

TEST(FatBoxPairs, JitteringAndJumpingBoxesGiveTheBroadPhasesPairs)
{
  std::vector<Aabb> boxes = grid_boxes(12, 8);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  std::uniform_int_distribution<std::size_t> pick(0, boxes.size() - 1);
  detail::FatBoxPairs kept;
  std::size_t jumps = 0;
  for (int frame = 0; frame < 200; ++frame)
  {
    for (Aabb& box : boxes)
    {
      const Vec2 d{jitter(rng), jitter(rng)};
      box = {box.lo + d, box.hi + d};
    }
    if (frame % 17 == 5)
    {
      // A jump far outside its enlarged box, onto another box.
      boxes[pick(rng)] = boxes[pick(rng)];
      ++jumps;
    }
    expect_same_pairs(kept, boxes);
  }
  EXPECT_GT(kept.reused(), 100u) << "the kept pairs were never reused";
  EXPECT_LT(kept.reused(), 200u - jumps + 1) << "a jump must find the pairs again";
}

TEST(FatBoxPairs, BoxesThatKeepMovingNeverPairTheirEnlargedBoxes)
{
  // A rain: every box moves further than its enlargement each frame, so
  // pairing the enlarged boxes would buy nothing. They are paired only once
  // every box has stayed inside them for a frame: here when the boxes land.
  std::vector<Aabb> boxes = grid_boxes(20, 10);
  detail::FatBoxPairs kept;
  const Vec2 fall{0.0, -0.3};  // m a frame, past a unit box's 0.1 m enlargement
  for (int frame = 0; frame < 150; ++frame)  // several tries, the waits between them doubling
  {
    move_all(boxes, fall);
    expect_same_pairs(kept, boxes);
  }
  EXPECT_EQ(kept.built(), 0u) << "boxes leaving their enlarged ones at once must not pair them";
  EXPECT_EQ(kept.reused(), 0u);
  for (int frame = 0; frame < 130; ++frame)  // longer than the longest wait
  {
    expect_same_pairs(kept, boxes);
  }
  EXPECT_EQ(kept.built(), 1u) << "boxes at rest pair their enlarged ones once";
  EXPECT_GT(kept.reused(), 60u);
}

TEST(FatBoxPairs, ASettlingStackTakesItsPairsFromEnlargedBoxes)
{
  // A stack sinking as its contacts take the load: every box leaves its
  // enlarged one (0.1 m) every fourth frame. The enlarged boxes are made
  // again and paired at once; only the first frame pairs the exact boxes.
  std::vector<Aabb> boxes = brick_boxes(20, 10);
  detail::FatBoxPairs kept;
  const Vec2 sink{0.0, -0.03};  // m a frame
  constexpr int kFrames = 100;
  for (int frame = 0; frame < kFrames; ++frame)
  {
    move_all(boxes, sink);
    expect_same_pairs(kept, boxes);
  }
  EXPECT_EQ(kept.paired_exactly(), 1u) << "a settling stack must not fall back to its exact boxes";
  EXPECT_GE(kept.built(), static_cast<std::size_t>(kFrames / 4)) << "the boxes left their enlarged ones";
  EXPECT_EQ(kept.built() + kept.reused(), static_cast<std::size_t>(kFrames))
      << "each frame after the first served by enlarged boxes";
  // Falling past the enlargement each frame: enlarged boxes made again would
  // be left at once, so the exact boxes are paired.
  const Vec2 fall{0.0, -0.3};
  for (int frame = 0; frame < 20; ++frame)
  {
    move_all(boxes, fall);
    expect_same_pairs(kept, boxes);
  }
  EXPECT_GE(kept.paired_exactly(), 19u) << "enlarged boxes left at once must not be made again at once";
}

TEST(FatBoxPairs, SinkingBoxesWhoseEnlargedOnesPairManyMoreTryAgainLater)
{
  // The same sinking, but the boxes stand 0.02 m apart: their enlarged boxes
  // also pair each box with its side and corner neighbours, four times the
  // exact pairs, so they are not made again at once.
  std::vector<Aabb> boxes = grid_boxes(20, 10);
  detail::FatBoxPairs kept;
  const Vec2 sink{0.0, -0.03};  // m a frame
  for (int frame = 0; frame < 100; ++frame)
  {
    move_all(boxes, sink);
    expect_same_pairs(kept, boxes);
  }
  EXPECT_GT(kept.paired_exactly(), 10u) << "enlarged boxes that pair many more must wait between tries";
  EXPECT_GT(kept.reused(), 10u);
}

TEST(FatBoxPairs, ARunnersPartsKeepTheSamePairs)
{
  // Enough boxes that the runner's parts check the enlarged boxes and keep
  // the overlapping pairs: reused frames, a box of the last part leaving
  // its enlarged box, and one turning unusable.
  std::vector<Aabb> boxes = grid_boxes(80, 60);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  detail::FatBoxPairs kept;
  test::ReversedRunner runner;
  for (int frame = 0; frame < 12; ++frame)
  {
    for (Aabb& box : boxes)
    {
      const Vec2 d{jitter(rng), jitter(rng)};
      box = {box.lo + d, box.hi + d};
    }
    if (frame == 4)
    {
      boxes[boxes.size() - 3] = boxes[boxes.size() / 2];
    }
    if (frame == 8)
    {
      boxes[boxes.size() - 7].lo.y = kNan;
    }
    expect_same_pairs(kept, boxes, runner);
  }
  EXPECT_GT(kept.reused(), 4u) << "the kept pairs were never reused";
  EXPECT_LT(kept.reused(), 11u) << "a box leaving its enlarged one must find the pairs again";
}

TEST(FatBoxPairs, UnusableAndHugeBoxesPairAsInTheBroadPhase)
{
  std::vector<Aabb> boxes = grid_boxes(6, 4);
  detail::FatBoxPairs kept;
  expect_same_pairs(kept, boxes);
  // Each case for several frames: the enlarged boxes are built again after a
  // wait, so some frames pair enlarged boxes and some the exact ones.
  const auto frames = [&](const std::vector<Aabb>& now, int count) {
    for (int frame = 0; frame < count; ++frame)
    {
      expect_same_pairs(kept, now);
    }
  };
  // Inverted by less than its enlargement: the enlarged box is usable and
  // overlaps its neighbours, but the box itself pairs with nothing.
  boxes[7].lo.x = boxes[7].hi.x + 0.05;
  frames(boxes, 8);
  boxes[9].hi.y = kNan;
  frames(boxes, 8);
  // A box too large to enlarge, then everything back in place.
  boxes[3] = {{-1e308, -1e308}, {1e308, 1e308}};
  frames(boxes, 8);
  const std::size_t before = kept.reused();
  frames(grid_boxes(6, 4), 130);  // longer than the longest wait
  EXPECT_GT(kept.reused(), before) << "boxes back in place must reuse the kept pairs";
}

TEST(FatBoxPairs, AnotherNumberOfBoxesFindsThePairsAgain)
{
  std::vector<Aabb> boxes = grid_boxes(5, 5);
  detail::FatBoxPairs kept;
  expect_same_pairs(kept, boxes);
  expect_same_pairs(kept, boxes);
  EXPECT_EQ(kept.reused(), 1u);
  // Two boxes trade places: each is outside its enlarged box.
  std::swap(boxes.front(), boxes.back());
  expect_same_pairs(kept, boxes);
  EXPECT_EQ(kept.reused(), 1u);
  // One box fewer, every other one in place.
  boxes.pop_back();
  expect_same_pairs(kept, boxes);
  EXPECT_EQ(kept.reused(), 1u);
  expect_same_pairs(kept, boxes);
  EXPECT_EQ(kept.reused(), 2u);
}

TEST(FatBoxPairs, AFewBoxesArePairedDirectly)
{
  // Up to BroadPhase::kAllPairsBoxes boxes every pair is tested each frame
  // and nothing is kept; past it the enlarged boxes are kept again.
  std::vector<Aabb> boxes = grid_boxes(4, 2);
  ASSERT_LE(boxes.size(), BroadPhase::kAllPairsBoxes);
  detail::FatBoxPairs kept;
  for (int frame = 0; frame < 6; ++frame)
  {
    if (frame == 3)
    {
      boxes[5].hi.x = kNan;
    }
    expect_same_pairs(kept, boxes);
  }
  EXPECT_EQ(kept.reused(), 0u) << "a few boxes need no enlarged ones";
  boxes = grid_boxes(5, 4);
  for (int frame = 0; frame < 3; ++frame)
  {
    expect_same_pairs(kept, boxes);
  }
  EXPECT_EQ(kept.reused(), 2u) << "more boxes keep their enlarged ones again";
}

}  // namespace
}  // namespace collision2d
