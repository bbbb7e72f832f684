// Internal to the core: sizes and gaps of outlines at given poses, for the
// time of impact of turning bodies and the World's sweep.
#pragma once

#include "collision2d/body.h"

namespace collision2d
{
namespace detail
{
/// Distance from the centroid to the nearest face (m): the thinnest a body
/// can be seen from any direction is twice this.
double inner_radius(const Body& b);

/// A body's outline placed at `position`, turned to `theta` (rad).
struct PosedOutline
{
  const Body* body;
  Vec2 position;
  double cos_theta;
  double sin_theta;
};

/// A lower bound on the distance between two outlines (m), negative when
/// they overlap, and 0 exactly when they touch: the exact distance for a
/// disk, the largest separation along a face normal for two polygons.
double outline_gap(const PosedOutline& a, const PosedOutline& b);

/// A point's signed distance to a body's outline at its pose (m, negative
/// inside) and the outward normal it is measured along: along the line from
/// a disk's centre; the nearest face's for a polygon (its largest face
/// separation: exact inside, at most the distance outside).
struct PointGap
{
  double gap;
  Vec2 normal;
};
PointGap outline_point_gap(const Body& b, Vec2 p);  // world_static_crossing.cpp

}  // namespace detail
}  // namespace collision2d
