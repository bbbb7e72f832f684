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

#include "posed_polygon.h"

namespace collision2d
{
using detail::PosedPolygon;

namespace
{
constexpr std::uint32_t kIndexMask = 0xFFFu;
constexpr int kReferenceShift = 12;
constexpr int kSlotShift = 24;
constexpr int kSecondIsReferenceShift = 25;
constexpr int kKindShift = 26;

enum class FeatureKind : std::uint32_t
{
  DiskDisk = 0,
  PolygonFaceDisk = 1,
  PolygonVertexDisk = 2,
  PolygonPolygon = 3
};

/// The second polygon's face becomes the reference only when it is better by
/// more than this fraction of the first one's separation plus this fraction of
/// the pair's size (m/m). A box resting on a box has two equally good faces;
/// a slight tilt must not swap them, or the contact's features change and
/// warm starting (which matches by feature) starts the contact cold.
constexpr double kReferenceRelative = 1e-3;
constexpr double kReferenceHysteresis = 2e-3;

std::uint32_t pack_feature(FeatureKind kind, bool second_is_reference, std::size_t reference,
                           std::size_t incident, int slot)
{
  return (static_cast<std::uint32_t>(kind) << kKindShift) |
         (static_cast<std::uint32_t>(second_is_reference) << kSecondIsReferenceShift) |
         (static_cast<std::uint32_t>(slot) << kSlotShift) |
         ((static_cast<std::uint32_t>(reference) & kIndexMask) << kReferenceShift) |
         (static_cast<std::uint32_t>(incident) & kIndexMask);
}

/// Body::world_vertex and Body::world_face_normal with the same arithmetic,
/// but visible to the compiler here (pose_polygon calls them per vertex).
Vec2 world_vertex_of(const Body& b, std::size_t i)
{
  return b.position() + rotate(b.local_vertices()[i], b.cos_theta(), b.sin_theta());
}

Vec2 world_normal_of(const Body& b, std::size_t i)
{
  return rotate(b.local_face_normals()[i], b.cos_theta(), b.sin_theta());
}

/// Strict overlap without a tolerance (exact touching is not a contact);
/// with one, gaps up to the tolerance count.
bool within_reach(double depth, double touch_tolerance)
{
  return touch_tolerance > 0.0 ? depth >= -touch_tolerance : depth > -touch_tolerance;
}

void add_point(Manifold& m, Vec2 point, double depth, std::uint32_t feature)
{
  ManifoldPoint& p = m.points[m.count++];
  p.point = point;
  p.penetration = std::max(0.0, depth);
  p.separation = -depth;
  p.feature = feature;
}

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

/// The polygon feature nearest a disk, in the polygon frame.
struct DiskFeature
{
  Vec2 normal;
  Vec2 closest;
  double depth = 0.0;
  FeatureKind kind = FeatureKind::PolygonFaceDisk;
  std::size_t index = 0;
};

/// Normal from the polygon to the disk centre (polygon frame), closest polygon
/// point and overlap depth; false when the disk is out of reach.
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

struct FaceQuery
{
  double separation = -std::numeric_limits<double>::infinity();
  std::size_t face = 0;
};

/// Largest over the reference's faces of the smallest signed distance of the
/// other polygon's vertices to that face plane (SAT on the reference normals).
FaceQuery max_face_separation(const PosedPolygon& reference, const Body& other)
{
  FaceQuery best;
  const auto& other_vertices = other.local_vertices();
  for (std::size_t i = 0; i < reference.body->vertex_count(); ++i)
  {
    const Vec2 n = reference.normals[i];
    // Work in the other body's frame: one rotation per face, not per vertex.
    const Vec2 n_other = rotate_inv(n, other.cos_theta(), other.sin_theta());
    const double offset = dot(n, other.position() - reference.vertices[i]);
    double deepest = std::numeric_limits<double>::infinity();
    for (const Vec2& v : other_vertices)
    {
      deepest = std::min(deepest, dot(n_other, v));
    }
    if (deepest + offset > best.separation)
    {
      best = {deepest + offset, i};
    }
  }
  return best;
}

/// Edge of `polygon` whose normal is most anti-parallel to world normal n.
std::size_t incident_edge(const Body& polygon, Vec2 n)
{
  const Vec2 n_local = rotate_inv(n, polygon.cos_theta(), polygon.sin_theta());
  const auto& normals = polygon.local_face_normals();
  std::size_t best = 0;
  for (std::size_t k = 1; k < normals.size(); ++k)
  {
    if (dot(normals[k], n_local) < dot(normals[best], n_local))
    {
      best = k;
    }
  }
  return best;
}

struct ClipPoint
{
  Vec2 point;
  int slot = 0;
};

/// Keeps the part of the segment (or single point) `in` with
/// dot(dir, x) <= limit; a clipped end is replaced by the crossing point and
/// keeps its slot. Returns the number of points left.
int clip_segment(const ClipPoint in[2], int in_count, Vec2 dir, double limit, ClipPoint out[2])
{
  double d[2] = {0.0, 0.0};
  int count = 0;
  for (int i = 0; i < in_count; ++i)
  {
    d[i] = dot(dir, in[i].point) - limit;
    if (d[i] <= 0.0)
    {
      out[count++] = in[i];
    }
  }
  if (in_count == 2 && d[0] * d[1] < 0.0)
  {
    const Vec2 crossing = in[0].point + (d[0] / (d[0] - d[1])) * (in[1].point - in[0].point);
    out[count++] = {crossing, d[0] > 0.0 ? in[0].slot : in[1].slot};
  }
  return count;
}

/// Incident edge of `incident` clipped to the side planes of reference face
/// `face`; points within reach go into m (normal = reference face normal).
void clip_incident_edge(const PosedPolygon& reference, std::size_t face, const PosedPolygon& incident,
                        bool second_is_reference, double touch_tolerance, Manifold& m)
{
  const Vec2 n = reference.normals[face];
  const Vec2 tangent = perp(n);  // along the counter-clockwise reference face
  const Vec2 r1 = reference.vertices[face];
  const Vec2 r2 = reference.vertices[(face + 1) % reference.body->vertex_count()];
  const std::size_t edge = incident_edge(*incident.body, n);
  const ClipPoint segment[2] = {{incident.vertices[edge], 0},
                                {incident.vertices[(edge + 1) % incident.body->vertex_count()], 1}};
  ClipPoint after_first[2];
  ClipPoint clipped[2];
  const int first_count = clip_segment(segment, 2, -tangent, -dot(tangent, r1), after_first);
  const int count = clip_segment(after_first, first_count, tangent, dot(tangent, r2), clipped);
  // Slot order keeps the two records of a manifold in a stable order.
  if (count == 2 && clipped[0].slot > clipped[1].slot)
  {
    std::swap(clipped[0], clipped[1]);
  }
  m.normal = n;
  for (int i = 0; i < count; ++i)
  {
    const ClipPoint& p = clipped[i];
    const double depth = -dot(n, p.point - r1);
    if (within_reach(depth, touch_tolerance))
    {
      add_point(m, p.point + n * (0.5 * depth), depth,
                pack_feature(FeatureKind::PolygonPolygon, second_is_reference, face, edge, p.slot));
    }
  }
}

/// Last resort when clipping keeps no point although SAT found an overlap
/// (the incident edge ends at or beyond a side plane of the reference face): the incident polygon's
/// deepest vertex against the reference face, at the SAT depth.
void deepest_vertex_point(const PosedPolygon& reference, std::size_t face, const PosedPolygon& incident,
                          bool second_is_reference, double separation, Manifold& m)
{
  const Vec2 n = reference.normals[face];
  const Vec2 r1 = reference.vertices[face];
  std::size_t deepest = 0;
  for (std::size_t j = 1; j < incident.body->vertex_count(); ++j)
  {
    if (dot(n, incident.vertices[j] - r1) < dot(n, incident.vertices[deepest] - r1))
    {
      deepest = j;
    }
  }
  m.normal = n;
  add_point(m, incident.vertices[deepest] - n * (0.5 * separation), -separation,
            pack_feature(FeatureKind::PolygonPolygon, second_is_reference, face, deepest, 0));
}

bool polygon_polygon(const PosedPolygon& a, const PosedPolygon& b, Manifold& m, double touch_tolerance)
{
  const FaceQuery query_a = max_face_separation(a, *b.body);
  if (!within_reach(-query_a.separation, touch_tolerance))
  {
    return false;
  }
  const FaceQuery query_b = max_face_separation(b, *a.body);
  if (!within_reach(-query_b.separation, touch_tolerance))
  {
    return false;
  }
  const double bias =
      kReferenceRelative * std::abs(query_a.separation) + kReferenceHysteresis * (a.body->radius() + b.body->radius());
  const bool b_is_reference = query_b.separation > query_a.separation + bias;
  const PosedPolygon& reference = b_is_reference ? b : a;
  const PosedPolygon& incident = b_is_reference ? a : b;
  const FaceQuery& query = b_is_reference ? query_b : query_a;
  clip_incident_edge(reference, query.face, incident, b_is_reference, touch_tolerance, m);
  if (m.count == 0)
  {
    deepest_vertex_point(reference, query.face, incident, b_is_reference, query.separation, m);
  }
  if (b_is_reference)
  {
    m.normal = -m.normal;  // reference normal points from b to a
  }
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
void pose_polygon(const Body& polygon, Vec2* vertices, Vec2* normals)
{
  for (std::size_t i = 0; i < polygon.vertex_count(); ++i)
  {
    vertices[i] = world_vertex_of(polygon, i);
    normals[i] = world_normal_of(polygon, i);
  }
}

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
