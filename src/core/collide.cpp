// Narrow phase: contact manifolds for
// disk-disk, polygon-disk (either order) and polygon-polygon pairs.
//
// Contact points are placed halfway between the two outlines along the
// normal (the middle of the overlap, or of the gap for touch-tolerance
// contacts), so neither body is favoured.
//
// ManifoldPoint::feature encoding (stable while the same features touch, so a
// world can match contacts across frames and warm start them):
//   bits  0-11  incident feature: the incident polygon's edge index
//               (polygon-polygon), 0 otherwise
//   bits 12-23  reference feature: the reference polygon's face index
//               (polygon-polygon, polygon face vs disk) or vertex index
//               (polygon vertex vs disk), 0 for disk-disk
//   bit  24     clip slot: 0 for the point from the incident edge's first
//               vertex (or its clipped replacement), 1 for the second
//   bit  25     1 when the reference polygon is the SECOND argument of collide()
//   bits 26-27  kind: 0 disk-disk, 1 polygon face vs disk, 2 polygon vertex vs
//               disk, 3 polygon-polygon
// Indices are taken modulo 4096; polygons with more vertices may alias ids,
// which only costs a missed warm start.
#include "collision2d/collide.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "collide_features.h"
#include "posed_polygon.h"

namespace collision2d
{
using detail::add_point;
using detail::DiskFeature;
using detail::FeatureKind;
using detail::nearest_feature_to_disk;
using detail::pack_feature;
using detail::PosedPolygon;
using detail::within_reach;

namespace
{
bool disk_disk(const Body& a, const Body& b, Manifold& m, double touch_tolerance)
{
  const Vec2 d = b.position() - a.position();
  // No underflow to a false zero for nearly coincident centres, and the same
  // bits on every target (std::hypot rounds differently between libms).
  const double distance = portable_hypot(d.x, d.y);
  const double depth = a.radius() + b.radius() - distance;
  if (!within_reach(depth, touch_tolerance))
  {
    return false;
  }
  if (distance == 0.0)
  {
    throw std::runtime_error("collide: two overlapping disks have coincident centres, the contact normal is undefined");
  }
  m.normal = d / distance;
  add_point(m, a.position() + m.normal * (a.radius() - 0.5 * depth), depth,
            pack_feature(FeatureKind::DiskDisk, false, 0, 0, 0));
  return true;
}

/// Polygon face whose plane the point (polygon frame) is furthest outside of.
std::size_t face_of_max_separation(const Body& polygon, Vec2 local_point, double& separation)
{
  const auto& vertices = polygon.local_vertices();
  const auto& normals = polygon.local_face_normals();
  std::size_t best = 0;
  separation = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const double s = dot(normals[i], local_point - vertices[i]);
    if (s > separation)
    {
      separation = s;
      best = i;
    }
  }
  return best;
}

}  // namespace

namespace detail
{
bool nearest_feature_to_disk(const Body& polygon, Vec2 centre, double radius, double touch_tolerance,
                             DiskFeature& f)
{
  double separation = 0.0;
  const std::size_t face = face_of_max_separation(polygon, centre, separation);
  if (!within_reach(radius - separation, touch_tolerance))
  {
    return false;  // that face plane separates them
  }
  const auto& vertices = polygon.local_vertices();
  const std::size_t next = (face + 1) % vertices.size();
  // Outside the polygon the closest point lies on the face of max separation
  // or one of its two end vertices; inside, the face of max separation is the
  // face of least penetration.
  if (separation > 0.0)
  {
    for (const std::size_t v : {face, next})
    {
      const Vec2 other = vertices[v == face ? next : face];
      if (dot(centre - vertices[v], other - vertices[v]) <= 0.0)
      {
        const Vec2 d = centre - vertices[v];
        const double distance = length(d);
        f = {d / distance, vertices[v], radius - distance, FeatureKind::PolygonVertexDisk, v};
        return within_reach(f.depth, touch_tolerance);
      }
    }
  }
  const Vec2 n = polygon.local_face_normals()[face];
  f = {n, centre - n * separation, radius - separation, FeatureKind::PolygonFaceDisk, face};
  return true;
}

}  // namespace detail

namespace
{
/// Manifold with the normal from the polygon to the disk.
bool polygon_disk(const Body& polygon, const Body& disk, Manifold& m, double touch_tolerance,
                  bool polygon_is_second)
{
  const double c = polygon.cos_theta();
  const double s = polygon.sin_theta();
  const Vec2 centre = rotate_inv(disk.position() - polygon.position(), c, s);
  DiskFeature f;
  if (!nearest_feature_to_disk(polygon, centre, disk.radius(), touch_tolerance, f))
  {
    return false;
  }
  m.normal = rotate(f.normal, c, s);
  const Vec2 closest = polygon.position() + rotate(f.closest, c, s);
  const Vec2 deepest = disk.position() - m.normal * disk.radius();
  add_point(m, 0.5 * (closest + deepest), f.depth, pack_feature(f.kind, polygon_is_second, f.index, 0, 0));
  return true;
}

/// Room for a polygon's posed outline: on the stack up to kStackVertices
/// vertices (the narrow phase allocates nothing for common shapes).
class PoseBuffer
{
public:
  PosedPolygon pose(const Body& polygon)
  {
    const std::size_t n = polygon.vertex_count();
    Vec2* vertices = stack_;
    if (n > kStackVertices)
    {
      heap_.resize(2 * n);
      vertices = heap_.data();
    }
    detail::pose_polygon(polygon, vertices, vertices + n);
    return {&polygon, vertices, vertices + n};
  }

private:
  static constexpr std::size_t kStackVertices = 16;
  Vec2 stack_[2 * kStackVertices];
  std::vector<Vec2> heap_;
};

bool disk_involved(const Body& a, const Body& b, Manifold& m, double touch_tolerance)
{
  if (a.shape() == Shape::Disk && b.shape() == Shape::Disk)
  {
    return disk_disk(a, b, m, touch_tolerance);
  }
  if (b.shape() == Shape::Disk)
  {
    return polygon_disk(a, b, m, touch_tolerance, false);
  }
  if (!polygon_disk(b, a, m, touch_tolerance, true))
  {
    return false;
  }
  m.normal = -m.normal;  // computed from the polygon (b) toward the disk (a)
  return true;
}

}  // namespace

bool collide(const Body& a, const Body& b, Manifold& m, double touch_tolerance)
{
  m.count = 0;
  if (a.shape() == Shape::Disk || b.shape() == Shape::Disk)
  {
    return disk_involved(a, b, m, touch_tolerance);
  }
  PoseBuffer pose_a;
  PoseBuffer pose_b;
  return polygon_polygon(pose_a.pose(a), pose_b.pose(b), m, touch_tolerance);
}

namespace detail
{
bool collide_posed(const PosedPolygon& a, const PosedPolygon& b, Manifold& m, double touch_tolerance)
{
  m.count = 0;
  if (a.vertices == nullptr || b.vertices == nullptr)
  {
    return disk_involved(*a.body, *b.body, m, touch_tolerance);
  }
  return polygon_polygon(a, b, m, touch_tolerance);
}

}  // namespace detail
}  // namespace collision2d
