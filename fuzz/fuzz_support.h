// Shared by the fuzz targets: the input ranges inside which the core promises
// finite output (the ranges the test_extremes_* suites cover), and the checks
// that turn a broken promise into a crash libFuzzer reports.
//
// Outside those ranges (a speed of 1e300, a dt of 1e300) a finite input can
// legitimately overflow within a step; the core must then throw
// std::overflow_error instead of handing back inf or NaN, which the targets
// check everywhere; inside the ranges it must not overflow at all.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace fuzz
{
constexpr double kMaxCoordinate = 1e6;  ///< m, far-from-origin extreme
constexpr double kMaxSpeed = 1e4;       ///< m/s
constexpr double kMaxSpin = 1e4;        ///< rad/s
constexpr double kMinSize = 1e-4;       ///< m
constexpr double kMaxSize = 1e4;        ///< m
constexpr double kMinMass = 1e-6;       ///< kg
constexpr double kMaxMass = 1e6;        ///< kg
constexpr double kMaxDt = 1.0;          ///< s
constexpr double kMaxGravity = 1e3;     ///< m/s^2

/// Prints what failed and aborts, which libFuzzer records as a crash.
[[noreturn]] inline void fail(const char* what)
{
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}

inline void require(bool ok, const char* what)
{
  if (!ok)
  {
    fail(what);
  }
}

inline bool within(double v, double lo, double hi) { return v >= lo && v <= hi; }

/// Inside the promised ranges. Polygon size is judged by its bounding radius;
/// the mass of a static or kinematic body plays no part.
inline bool in_range(const Body& b)
{
  const bool mass_ok = b.type() != BodyType::Dynamic || within(b.mass(), kMinMass, kMaxMass);
  return mass_ok && within(b.radius(), kMinSize, kMaxSize) &&
         std::abs(b.position().x) <= kMaxCoordinate && std::abs(b.position().y) <= kMaxCoordinate &&
         length(b.velocity()) <= kMaxSpeed && std::abs(b.omega()) <= kMaxSpin;
}

inline bool in_range(const std::vector<Body>& bodies)
{
  for (const Body& b : bodies)
  {
    if (!in_range(b))
    {
      return false;
    }
  }
  return true;
}

inline bool finite_state(const Body& b)
{
  return non_finite_state_field(b) == nullptr;
}

/// Poses and velocities bit for bit equal (an all-or-nothing call that threw).
inline bool same_state(const std::vector<Body>& a, const std::vector<Body>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (!(a[i].position() == b[i].position() && a[i].theta() == b[i].theta() &&
          a[i].velocity() == b[i].velocity() && a[i].omega() == b[i].omega()))
    {
      return false;
    }
  }
  return true;
}

inline void require_finite(const std::vector<Body>& bodies, const char* what)
{
  for (const Body& b : bodies)
  {
    require(finite_state(b), what);
  }
}

}  // namespace fuzz
}  // namespace collision2d
