// Soft step: a disk on the face of a kinematic body that turns this frame (a
// robot's turning link pushing a round part). A frame's contact keeps its
// normal and lever arms from prepare. On a turning face that pushes along the
// face's old normal and aims at the face's speed where the disk touched it at
// prepare, so a disk sliding along the face sinks into it by about the turn
// times the slide. These points follow the face instead: before each pass
// their normal turns with the face, the face's anchor moves under the disk's
// nearest point, and the gap is that point's distance from the face's plane,
// exactly. The slip since a point stuck carries on. They stay on the kernel's
// point verbs, so no other contact pays for them. A polygon lying on a
// turning face keeps the frame's contact: followed this way, a box sliding
// with friction pitched into the face more (docs/performance.md).
// The face's plane stands for the face only while the disk's centre is
// nearest that face. Once the turn carries the disk past the face's end, or
// the face past the disk, the point follows the polygon's nearest feature
// now (a vertex or another face) without the lead below: read off the
// plane, a disk beside a turning bar's tip sat deep in the face and was
// struck at the speed the plane would have there, far out along the bar.
#include <algorithm>
#include <cmath>
#include <limits>

#include "collide_features.h"
#include "turn.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Every feature is within reach: the nearest is wanted however far.
constexpr double kAnyDistance = std::numeric_limits<double>::infinity();
}  // namespace

void WorldImpl::list_turning_faces()
{
  for (std::size_t k = 0; k < points_.size(); k += points_[k].count == 2 ? 2 : 1)
  {
    const ContactPoint& p = points_[k];
    const int side = reference_side(p.feature);  // a manifold's points share their face
    if (!p.active || side == 0)
    {
      continue;
    }
    const Body& face = bodies_[side == 1 ? p.a : p.b];
    const Body& other = bodies_[side == 1 ? p.b : p.a];
    if (face.type() != BodyType::Kinematic || face.omega() == 0.0 || other.type() != BodyType::Dynamic ||
        other.shape() != Shape::Disk)
    {
      continue;
    }
    // A disk meets a face at one point: no pair block to follow.
    turning_faces_.push_back(TurningFacePoint{k, side == 1, p.normal, p.r_a, p.r_b, p.separation, p.anchor_drift});
    if (rows_on())
    {
      soft_rows_.keep_on_point_verbs(k);
    }
  }
}

/// Disks on turning faces: their normals turned with their faces, their
/// face anchors moved under the disk's nearest point, their gaps and slips
/// measured on the turned faces.
void WorldImpl::follow_turning_points(double h, bool as_prepared)
{
  for (const TurningFacePoint& t : turning_faces_)
  {
    follow_turning_point(t, h, as_prepared);
  }
}

void WorldImpl::follow_turning_point(const TurningFacePoint& t, double h, bool as_prepared)
{
  ContactPoint& p = points_[t.point];
  const BodyVelocity& a = velocity_[p.a];
  const BodyVelocity& b = velocity_[p.b];
  const BodyVelocity& face = t.face_on_a ? a : b;
  // Both anchors as prepared, carried by their bodies' moves since and
  // turned with the face: the disk's stays its point nearest the face
  // however it rolls.
  const Vec2 arm_a = rotate(t.r_a, face.turned_cos, face.turned_sin);
  const Vec2 arm_b = rotate(t.r_b, face.turned_cos, face.turned_sin);
  const Vec2 centres = prepared_position_[p.b] - prepared_position_[p.a];
  const Vec2 apart_then = centres + t.r_b - t.r_a;  // anchor b less anchor a
  const Vec2 apart = centres + b.moved - a.moved + arm_b - arm_a;
  const Vec2 normal = rotate(t.normal, face.turned_cos, face.turned_sin);
  const double gap = t.separation + dot(normal, apart) - dot(t.normal, apart_then);
  // The slip is the disk's material point's, which a rolling disk turns away
  // (as every point's anchor turns with its body); the face turns with itself.
  const Vec2 material = centres + b.moved - a.moved + rotate(t.r_b, b.turned_cos, b.turned_sin) -
                        rotate(t.r_a, a.turned_cos, a.turned_sin);
  const double slip = dot(perp(normal), material) - dot(perp(t.normal), apart_then);
  DiskFeature nearest;
  if (!nearest_is_followed_face(t, nearest))
  {
    follow_nearest_feature(t, nearest, slip, h, as_prepared);
    return;
  }
  if (as_prepared)
  {
    p.normal = t.normal;
    p.r_a = t.r_a;
    p.r_b = t.r_b;
  }
  else
  {
    // The next move's velocity is solved for its middle: the face's normal
    // turned on by half a substep, and its lever arm to where the disk's
    // point will be then. Solved at its start, a disk sliding along the face
    // would run into it by the turn times the slide each substep.
    double lead_cos = 1.0;
    double lead_sin = 0.0;
    turn_of(0.5 * h * face.omega, lead_cos, lead_sin);
    p.normal = rotate(normal, lead_cos, lead_sin);
    // The disk's arm reaches its nearest point, on its rim along the
    // normal, so the push passes through its centre and friction turns it
    // by its radius. (The arm as prepared ran to the face, as long as the
    // gap then: a disk the bar struck spun up to 200 times faster than
    // its friction can turn it.)
    const Vec2 ahead = 0.5 * h * ((t.face_on_a ? b : a).v - face.v);
    const double radius = bodies_[t.face_on_a ? p.b : p.a].radius();
    const Vec2 disk_arm = (t.face_on_a ? -radius : radius) * p.normal;
    const Vec2 centres_now = centres + b.moved - a.moved;
    p.r_a = t.face_on_a ? centres_now + disk_arm + ahead : disk_arm;
    p.r_b = t.face_on_a ? disk_arm : disk_arm - centres_now + ahead;
    prepare_masses(p, p.restitution);
  }
  // The gap and the slip the point verbs read from the anchors' offset are
  // the ones above at these poses (no pass moves a body).
  set_followed(p, anchor_offset(p, velocity_), gap, t.anchor_drift + slip);
}

/// Whether the polygon's feature nearest the disk's centre now is still the
/// face the point was prepared on; `nearest` is that feature, rotated to the
/// world's axes.
bool WorldImpl::nearest_is_followed_face(const TurningFacePoint& t, DiskFeature& nearest) const
{
  const ContactPoint& p = points_[t.point];
  nearest = nearest_feature_now(t.face_on_a ? p.a : p.b, t.face_on_a ? p.b : p.a);
  return nearest.kind == FeatureKind::PolygonFaceDisk && nearest.index == reference_index(p.feature);
}

/// The feature of the polygon nearest the disk's centre at the poses the
/// substeps have moved them to (from prepare), its normal and closest point
/// (from the polygon's centre) in the world's axes.
DiskFeature WorldImpl::nearest_feature_now(std::size_t polygon, std::size_t disk) const
{
  const BodyVelocity& turn = velocity_[polygon];
  const double prepared_cos = std::cos(prepared_theta_[polygon]);
  const double prepared_sin = std::sin(prepared_theta_[polygon]);
  const Vec2 centre = prepared_position_[disk] + velocity_[disk].moved - (prepared_position_[polygon] + turn.moved);
  const Vec2 local = rotate_inv(rotate_inv(centre, turn.turned_cos, turn.turned_sin), prepared_cos, prepared_sin);
  DiskFeature nearest;
  nearest_feature_to_disk(bodies_[polygon], local, bodies_[disk].radius(), kAnyDistance, nearest);
  nearest.normal = rotate(rotate(nearest.normal, prepared_cos, prepared_sin), turn.turned_cos, turn.turned_sin);
  nearest.closest = rotate(rotate(nearest.closest, prepared_cos, prepared_sin), turn.turned_cos, turn.turned_sin);
  return nearest;
}

/// A disk no longer nearest its face: its gap to the polygon's nearest
/// feature now, pushed along that feature's normal.
void WorldImpl::follow_nearest_feature(const TurningFacePoint& t, const DiskFeature& nearest, double slip,
                                       double h, bool as_prepared)
{
  ContactPoint& p = points_[t.point];
  const double gap = -nearest.depth;
  double speculative = gap;
  p.normal = t.normal;
  p.r_a = t.r_a;
  p.r_b = t.r_b;
  if (!as_prepared)
  {
    const BodyVelocity& face = velocity_[t.face_on_a ? p.a : p.b];
    const BodyVelocity& disk = velocity_[t.face_on_a ? p.b : p.a];
    const double radius = bodies_[t.face_on_a ? p.b : p.a].radius();
    const Vec2 on_disk = -radius * nearest.normal;  // from its centre
    p.normal = t.face_on_a ? nearest.normal : -nearest.normal;
    p.r_a = t.face_on_a ? nearest.closest : on_disk;
    p.r_b = t.face_on_a ? on_disk : nearest.closest;
    prepare_masses(p, p.restitution);
    // As a round point's: a vertex sweeping past the disk closes along the
    // normal only as far as its path reaches the disk within the substep.
    const Vec2 slide = disk.v - (face.v + cross(face.omega, nearest.closest));
    const double closing = -dot(slide, nearest.normal);
    if (nearest.kind == FeatureKind::PolygonVertexDisk && gap > 0.0 && closing > 0.0)
    {
      const Vec2 apart = (radius + gap) * nearest.normal;  // the vertex to the disk's centre
      speculative = std::max(gap, closing * touch_time(apart, slide, radius, h));
    }
  }
  set_followed(p, anchor_offset(p, velocity_), speculative, t.anchor_drift + slip);
}

}  // namespace detail
}  // namespace collision2d
