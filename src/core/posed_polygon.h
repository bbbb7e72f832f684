// Internal to the core: a polygon's outline at its current pose. The World
// works it out once per detection, so each pair a body is in reuses its
// rotated vertices and face normals instead of rotating them again.
#pragma once

#include <cstddef>

#include "collision2d/body.h"
#include "collision2d/collide.h"

namespace collision2d
{
namespace detail
{
struct PosedPolygon
{
  const Body* body = nullptr;
  const Vec2* vertices = nullptr;  ///< world (m), counter-clockwise; null for a disk
  const Vec2* normals = nullptr;   ///< world unit face normals, normals[i] for edge i -> i+1
};

/// Writes a polygon's world vertices and face normals (vertex_count() of
/// each) with the arithmetic collide() uses, so results are the same bits.
void pose_polygon(const Body& polygon, Vec2* vertices, Vec2* normals);

/// collide() for two posed polygons (collide_polygons.cpp).
bool polygon_polygon(const PosedPolygon& a, const PosedPolygon& b, Manifold& m, double touch_tolerance);

/// collide() for two bodies whose polygons are given posed at their current
/// poses (a disk's PosedPolygon has null outlines).
bool collide_posed(const PosedPolygon& a, const PosedPolygon& b, Manifold& m, double touch_tolerance);

}  // namespace detail
}  // namespace collision2d
