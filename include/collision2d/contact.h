// Contact records shared by detection, the solver, the world and the ROS face.
#pragma once

#include <cstddef>
#include <cstdint>

#include "collision2d/vec2.h"

namespace collision2d
{
/// One contact point between bodies a < b; `normal` is a unit vector from a
/// toward b and `penetration` the overlap depth along it (>= 0). A two-point
/// manifold is reported as two records of the same pair with the same normal.
/// `feature` identifies which features (reference face, incident vertex, ...)
/// produced the point, so persistent contacts can be matched across frames.
struct Contact
{
  std::size_t a = 0;
  std::size_t b = 0;
  Vec2 normal;
  Vec2 point;
  double penetration = 0.0;
  std::uint32_t feature = 0;
};

/// Impulses the solver applied at one contact (N s). `normal` >= 0 pushes b
/// along +normal and a along -normal; `tangent` acts along perp(normal) on b.
struct ContactImpulse
{
  double normal = 0.0;
  double tangent = 0.0;
};

}  // namespace collision2d
