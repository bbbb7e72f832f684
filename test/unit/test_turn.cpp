// turn_of (src/core/turn.h): the series it sums for small turns against the
// library's cosine and sine, and the zeros whose sign the contacts see.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "turn.h"

namespace collision2d
{
namespace detail
{
namespace
{
std::int64_t ulps_apart(double x, double y)
{
  std::int64_t a = 0;
  std::int64_t b = 0;
  std::memcpy(&a, &x, sizeof a);
  std::memcpy(&b, &y, sizeof b);
  return a > b ? a - b : b - a;
}

TEST(Turn, SmallTurnsAreWithinAnUlpOfTheLibrary)
{
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> angle(-kSeriesTurn, kSeriesTurn);
  constexpr int kAngles = 200000;
  int differing = 0;
  for (int n = 0; n < kAngles; ++n)
  {
    const double x = angle(random);
    double c = 0.0;
    double s = 0.0;
    turn_of(x, c, s);
    ASSERT_LE(ulps_apart(c, std::cos(x)), 1) << "cos(" << x << ")";
    ASSERT_LE(ulps_apart(s, std::sin(x)), 1) << "sin(" << x << ")";
    differing += c != std::cos(x) || s != std::sin(x);
  }
  // Within an ulp, and nearly always the same bits: the series must not move
  // trajectories that the library's values gave before.
  EXPECT_LE(differing, kAngles / 1000) << differing << " of " << kAngles << " angles differ in the last bit";
}

TEST(Turn, TheThresholdAndBeyondAreTheLibrarysOwn)
{
  for (const double x : {kSeriesTurn, -kSeriesTurn, 0.03, -0.3, 1.0, 3.0, -3.1})
  {
    double c = 0.0;
    double s = 0.0;
    turn_of(x, c, s);
    EXPECT_EQ(c, std::cos(x)) << x;
    EXPECT_EQ(s, std::sin(x)) << x;
  }
}

TEST(Turn, ZeroKeepsItsSign)
{
  for (const double zero : {0.0, -0.0})
  {
    double c = 0.0;
    double s = 1.0;
    turn_of(zero, c, s);
    EXPECT_EQ(c, 1.0);
    EXPECT_EQ(s, 0.0);
    EXPECT_EQ(std::signbit(s), std::signbit(zero));
  }
}

TEST(Turn, TinyTurnsKeepTheUnitCircle)
{
  for (const double x : {1e-300, -1e-12, 3e-7, -9.9e-4})
  {
    double c = 0.0;
    double s = 0.0;
    turn_of(x, c, s);
    EXPECT_NEAR(c * c + s * s, 1.0, 4e-16) << x;
    EXPECT_EQ(s, std::sin(x)) << x;
  }
}

}  // namespace
}  // namespace detail
}  // namespace collision2d
