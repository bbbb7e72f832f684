// Time of impact of turning bodies, checked against the narrow phase on
// densely sampled poses: no pose before the returned t overlaps deeper than
// the touch tolerance, the pose at t touches, and a sweep that returns 1
// never overlaps. With no turn the overload is the closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "collision2d/collide.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/time_of_impact.h"
#include "collision2d/touch_tolerance.h"

namespace collision2d
{
namespace
{
/// Poses sampled across a sweep for the independent check.
constexpr int kSamples = 4000;
constexpr int kCases = 300;

/// A 1 kg box of half-sizes half_x by half_y (m), at rest.
Body box(double half_x, double half_y, Vec2 position, double theta)
{
  return scenes::make_box(1.0, 2.0 * half_x, 2.0 * half_y, position, theta);
}

struct TurningSweep
{
  Body a;
  Vec2 da;
  double turn_a;
  Body b;
  Vec2 db;
  double turn_b;
};

Body posed(const Body& body, Vec2 d, double turn, double t)
{
  Body copy = body;
  copy.set_position(body.position() + t * d);
  copy.set_theta(body.theta() + t * turn);
  return copy;
}

double tolerance_of(const TurningSweep& s)
{
  return kRelativeTouchTolerance * (s.a.radius() + s.b.radius());
}

/// Whether the pair overlaps deeper than the touch tolerance at fraction t.
bool overlaps_at(const TurningSweep& s, double t)
{
  Manifold m;
  return collide(posed(s.a, s.da, s.turn_a, t), posed(s.b, s.db, s.turn_b, t), m, -tolerance_of(s));
}

/// Whether the pair is within twice the touch tolerance of touching at t.
bool touches_at(const TurningSweep& s, double t)
{
  Manifold m;
  return collide(posed(s.a, s.da, s.turn_a, t), posed(s.b, s.db, s.turn_b, t), m, 2.0 * tolerance_of(s));
}

/// A thin bar (a link) turning about its middle, and a disk or a small box
/// somewhere around it moving slowly.
TurningSweep random_sweep(std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double half_length = 0.5 + 0.5 * std::abs(unit(rng));
  const double half_width = 0.005 + 0.01 * std::abs(unit(rng));
  Body bar = box(half_length, half_width, {0.1 * unit(rng), 0.1 * unit(rng)}, 3.0 * unit(rng));
  const double reach = 0.9 * half_length;
  const Vec2 at{reach * unit(rng), reach * unit(rng)};
  const double size = 0.005 + 0.02 * std::abs(unit(rng));
  Body other = unit(rng) > 0.0 ? Body(1.0, size, at, {0.0, 0.0}) : box(size, 0.5 * size, at, 3.0 * unit(rng));
  return TurningSweep{bar, {0.05 * unit(rng), 0.05 * unit(rng)}, 4.0 * unit(rng), other,
                      {0.05 * unit(rng), 0.05 * unit(rng)}, 0.0};
}

void expect_first_touch(const TurningSweep& s, const std::string& what)
{
  SCOPED_TRACE(what);
  const double t = time_of_impact(s.a, s.da, s.turn_a, s.b, s.db, s.turn_b);
  ASSERT_GE(t, 0.0);
  ASSERT_LE(t, 1.0);
  if (t > 0.0)
  {
    EXPECT_FALSE(overlaps_at(s, 0.0)) << "overlapping at the start, so t should be 0";
  }
  int overlapping_before = 0;
  for (int k = 0; k < kSamples; ++k)
  {
    const double sample = t * k / kSamples;
    overlapping_before += overlaps_at(s, sample) && sample > 0.0 ? 1 : 0;
  }
  EXPECT_EQ(overlapping_before, 0) << "an overlap before t = " << t;
  if (t < 1.0)
  {
    EXPECT_TRUE(touches_at(s, t)) << "not touching at t = " << t;
  }
}

TEST(TimeOfImpactTurning, NoTurnIsTheClosedForm)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int c = 0; c < kCases; ++c)
  {
    const Body a = box(0.5, 0.1, {0.0, 0.0}, unit(rng));
    const Body b = unit(rng) > 0.0 ? Body(1.0, 0.2, {2.0 * unit(rng), 2.0 * unit(rng)}, {0.0, 0.0})
                                   : box(0.2, 0.3, {2.0 * unit(rng), 2.0 * unit(rng)}, unit(rng));
    const Vec2 da{unit(rng), unit(rng)};
    const Vec2 db{2.0 * unit(rng), 2.0 * unit(rng)};
    EXPECT_EQ(time_of_impact(a, da, 0.0, b, db, 0.0), time_of_impact(a, da, b, db));
  }
}

TEST(TimeOfImpactTurning, FirstTouchOfATurningBarAgainstSampledPoses)
{
  std::mt19937 rng(11);
  int hits = 0;
  for (int c = 0; c < kCases; ++c)
  {
    const TurningSweep s = random_sweep(rng);
    expect_first_touch(s, "case " + std::to_string(c));
    hits += time_of_impact(s.a, s.da, s.turn_a, s.b, s.db, s.turn_b) < 1.0 ? 1 : 0;
  }
  // The cases must exercise both answers.
  EXPECT_GT(hits, kCases / 10);
  EXPECT_LT(hits, kCases);
}

TEST(TimeOfImpactTurning, ABarTurningFarInOneSweepStillFindsAThinBody)
{
  // A 2 m bar turning 6 rad (its tip moves about 6 m) and a 1 cm disk and a
  // 2 mm plate in its path: the first touch is found, not stepped over.
  const Body bar = box(1.0, 0.01, {0.0, 0.0}, 0.0);
  const Body disk(1.0, 0.01, {0.9 * std::cos(2.0), 0.9 * std::sin(2.0)}, {0.0, 0.0});
  const Body plate = box(0.05, 0.001, {0.7 * std::cos(4.0), 0.7 * std::sin(4.0)}, 4.0);
  for (const Body* other : {&disk, &plate})
  {
    for (double turn : {6.0, -6.0})
    {
      const TurningSweep s{bar, {0.0, 0.0}, turn, *other, {0.0, 0.0}, 0.0};
      expect_first_touch(s, "turn " + std::to_string(turn));
      EXPECT_LT(time_of_impact(s.a, s.da, s.turn_a, s.b, s.db, s.turn_b), 1.0) << "stepped over";
    }
  }
}

}  // namespace
}  // namespace collision2d
