// Internal to the narrow phase (collide.cpp, collide_polygons.cpp): the
// feature ids its points carry (encoding described in collide.cpp) and the
// small helpers both files use.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "collision2d/body.h"
#include "collision2d/collide.h"

namespace collision2d
{
namespace detail
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

inline std::uint32_t pack_feature(FeatureKind kind, bool second_is_reference, std::size_t reference,
                           std::size_t incident, int slot)
{
  return (static_cast<std::uint32_t>(kind) << kKindShift) |
         (static_cast<std::uint32_t>(second_is_reference) << kSecondIsReferenceShift) |
         (static_cast<std::uint32_t>(slot) << kSlotShift) |
         ((static_cast<std::uint32_t>(reference) & kIndexMask) << kReferenceShift) |
         (static_cast<std::uint32_t>(incident) & kIndexMask);
}

/// Which body of a pair holds the face a point's normal is fixed to: 1 the
/// first, 2 the second, 0 neither (two disks, or a disk on a polygon's vertex).
inline int reference_side(std::uint32_t feature)
{
  const auto kind = static_cast<FeatureKind>(feature >> kKindShift);
  if (kind != FeatureKind::PolygonFaceDisk && kind != FeatureKind::PolygonPolygon)
  {
    return 0;
  }
  return ((feature >> kSecondIsReferenceShift) & 1u) != 0 ? 2 : 1;
}

/// The reference face's (or vertex's) index in the reference polygon.
inline std::size_t reference_index(std::uint32_t feature) { return (feature >> kReferenceShift) & kIndexMask; }

/// The polygon feature nearest a disk, in the polygon's frame: the normal
/// from the polygon toward the disk's centre, the polygon's closest point,
/// the overlap depth (negative apart) and the face's or vertex's index.
struct DiskFeature
{
  Vec2 normal;
  Vec2 closest;
  double depth = 0.0;
  FeatureKind kind = FeatureKind::PolygonFaceDisk;
  std::size_t index = 0;
};

/// The feature of `polygon` nearest a disk centred at `centre` (polygon
/// frame); false when the disk is farther than `touch_tolerance` from it.
bool nearest_feature_to_disk(const Body& polygon, Vec2 centre, double radius, double touch_tolerance,
                             DiskFeature& f);

/// Body::world_vertex and Body::world_face_normal with the same arithmetic,
/// but visible to the compiler (pose_polygon calls them per vertex).
inline Vec2 world_vertex_of(const Body& b, std::size_t i)
{
  return b.position() + rotate(b.local_vertices()[i], b.cos_theta(), b.sin_theta());
}

inline Vec2 world_normal_of(const Body& b, std::size_t i)
{
  return rotate(b.local_face_normals()[i], b.cos_theta(), b.sin_theta());
}

/// Strict overlap without a tolerance (exact touching is not a contact);
/// with one, gaps up to the tolerance count.
inline bool within_reach(double depth, double touch_tolerance)
{
  return touch_tolerance > 0.0 ? depth >= -touch_tolerance : depth > -touch_tolerance;
}

inline void add_point(Manifold& m, Vec2 point, double depth, std::uint32_t feature)
{
  ManifoldPoint& p = m.points[m.count++];
  p.point = point;
  p.penetration = std::max(0.0, depth);
  p.separation = -depth;
  p.feature = feature;
}

}  // namespace detail
}  // namespace collision2d
