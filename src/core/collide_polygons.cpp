// Narrow phase, polygon against polygon: separating axes on both polygons'
// face normals, then the incident edge clipped to the reference face (the
// feature ids are those of collide.cpp). Both polygons come posed: their
// world outlines worked out once (posed_polygon.h).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "collide_features.h"
#include "posed_polygon.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// The second polygon's face becomes the reference only when it is better by
/// more than this fraction of the first one's separation plus this fraction of
/// the pair's size (m/m). A box resting on a box has two equally good faces;
/// a slight tilt must not swap them, or the contact's features change and
/// warm starting (which matches by feature) starts the contact cold.
constexpr double kReferenceRelative = 1e-3;
constexpr double kReferenceHysteresis = 2e-3;

/// (i + 1) % count without the division (the narrow phase's hot path).
std::size_t next_vertex(std::size_t i, std::size_t count) { return i + 1 == count ? 0 : i + 1; }

struct FaceQuery
{
  double separation = -std::numeric_limits<double>::infinity();
  std::size_t face = 0;
};

/// Two doubles, one per face: GCC and Clang vector extensions, so SSE2 or
/// NEON computes two faces at once with each lane's IEEE operations exactly
/// those of the one-face loop below (contraction is off for the build).
typedef double Pair __attribute__((vector_size(2 * sizeof(double))));

/// Largest over the reference's faces of the smallest signed distance of the
/// other polygon's vertices to that face plane (SAT on the reference normals).
/// Faces go two at a time, then one; the faces are compared in order, so the
/// result is that of one face at a time.
FaceQuery max_face_separation(const PosedPolygon& reference, const Body& other)
{
  FaceQuery best;
  const auto& other_vertices = other.local_vertices();
  const std::size_t faces = reference.body->vertex_count();
  const double c = other.cos_theta();
  const double s = other.sin_theta();
  const Vec2 centre = other.position();
  std::size_t i = 0;
  for (; i + 2 <= faces; i += 2)
  {
    const Vec2* n = reference.normals + i;
    const Vec2* r = reference.vertices + i;
    const Pair nx = {n[0].x, n[1].x};
    const Pair ny = {n[0].y, n[1].y};
    // rotate_inv(n, c, s) and dot(n, centre - r) of the one-face loop.
    const Pair ox = c * nx + s * ny;
    const Pair oy = -s * nx + c * ny;
    const Pair offset = nx * (centre.x - Pair{r[0].x, r[1].x}) + ny * (centre.y - Pair{r[0].y, r[1].y});
    Pair deepest = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    for (const Vec2& v : other_vertices)
    {
      const Pair d = ox * v.x + oy * v.y;
      deepest = d < deepest ? d : deepest;  // std::min(deepest, d) per lane
    }
    const Pair separation = deepest + offset;
    for (std::size_t lane = 0; lane < 2; ++lane)
    {
      if (separation[lane] > best.separation)
      {
        best = {separation[lane], i + lane};
      }
    }
  }
  for (; i < faces; ++i)
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
  double lowest = dot(normals[0], n_local);
  for (std::size_t k = 1; k < normals.size(); ++k)
  {
    const double along = dot(normals[k], n_local);
    if (along < lowest)
    {
      best = k;
      lowest = along;
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
  const Vec2 r2 = reference.vertices[next_vertex(face, reference.body->vertex_count())];
  const std::size_t edge = incident_edge(*incident.body, n);
  const ClipPoint segment[2] = {{incident.vertices[edge], 0},
                                {incident.vertices[next_vertex(edge, incident.body->vertex_count())], 1}};
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

}  // namespace

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

void pose_polygon(const Body& polygon, Vec2* vertices, Vec2* normals)
{
  for (std::size_t i = 0; i < polygon.vertex_count(); ++i)
  {
    vertices[i] = world_vertex_of(polygon, i);
    normals[i] = world_normal_of(polygon, i);
  }
}

}  // namespace detail
}  // namespace collision2d
