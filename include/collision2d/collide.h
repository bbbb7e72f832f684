// Narrow phase: contact manifolds between two bodies at their current poses.
#pragma once

#include <cstdint>

#include "collision2d/body.h"

namespace collision2d
{
struct ManifoldPoint
{
  Vec2 point;                  ///< world contact point (m)
  double penetration = 0.0;    ///< depth along the normal (m), >= 0
  double separation = 0.0;     ///< signed gap along the normal (m): -depth, > 0 for a point within reach
  std::uint32_t feature = 0;   ///< which features made this point (for warm starting)
};

/// Up to two points with one shared unit normal pointing from the first body
/// to the second. Fixed size: building one allocates nothing.
struct Manifold
{
  Vec2 normal;
  ManifoldPoint points[2];
  int count = 0;
};

/// Fills `m` and returns true when the outlines of `a` and `b` overlap by more
/// than `-touch_tolerance` (m). With touch_tolerance = 0 only strict overlap
/// counts (exact touching is not a contact); a positive tolerance also reports
/// pairs that are within that gap as contacts of zero penetration.
/// Throws std::runtime_error when the normal is undefined (coincident centres
/// of two overlapping disks).
bool collide(const Body& a, const Body& b, Manifold& m, double touch_tolerance = 0.0);

}  // namespace collision2d
