// The cosine and sine of the small angle a touching body has turned since
// prepare, which its contacts follow every substep (world_soft_step.cpp).
#pragma once

#include <cmath>

namespace collision2d
{
namespace detail
{
/// Below this angle (rad) turn_of sums the Taylor series (sine to the x^11
/// term, cosine to x^10): the first term left out is under 1e-25 of the
/// result, so the sum is within an ulp of the library's and nearly always
/// the same bits (test_turn.cpp). It covers a kept manifold's turn since
/// detection (at most acos(0.99985), about 0.0173 rad, world_contact_reuse.cpp)
/// as well as a substep's: the library call cost more than the rest of either.
constexpr double kSeriesTurn = 0.02;

/// cos and sin of `angle` (rad); for +-0, exactly 1 and the zero itself.
inline void turn_of(double angle, double& c, double& s)
{
  if (angle == 0.0)
  {
    c = 1.0;
    s = angle;
  }
  else if (std::abs(angle) < kSeriesTurn)
  {
    const double x2 = angle * angle;
    s = angle + angle * x2 * (-1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362880.0 +
                                                                                  x2 * (-1.0 / 39916800.0)))));
    c = 1.0 + x2 * (-0.5 + x2 * (1.0 / 24.0 + x2 * (-1.0 / 720.0 + x2 * (1.0 / 40320.0 + x2 * (-1.0 / 3628800.0)))));
  }
  else
  {
    c = std::cos(angle);
    s = std::sin(angle);
  }
}

}  // namespace detail
}  // namespace collision2d
