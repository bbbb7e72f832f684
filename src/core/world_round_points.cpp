// Soft step: a contact on a disk's round side whose other side is a
// polygon's vertex or another disk (a parcel's corner crossing a roller, a
// wheel meeting a kerb's edge, two balls passing). A frame's contact keeps
// its normal from prepare, and its gap follows the bodies along that normal
// only; where the two centres of curvature (the disk's centre, the vertex or
// the other centre) slide past each other, the true gap opens by the slide
// squared over twice their distance, which the straight line misses: a
// corner sliding over a round peg reads as sinking into it and is thrown
// up. These points follow their gap exactly instead, as the distance between
// the centres less the radii. They stay on the kernel's point verbs, so no
// other contact pays for them.

#include <algorithm>
#include <cmath>

#include "collide_features.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// A round point is followed only when its centres slide past each other by
/// more than this fraction of their distance in a frame: the straight gap
/// then misses the true one (by the slide squared over twice the distance)
/// by more than 5e-5 of that distance. Slower slides keep the rows.
constexpr double kRoundSlideFraction = 0.01;

bool round_kind(std::uint32_t feature)
{
  const auto kind = static_cast<FeatureKind>(feature >> kKindShift);
  return kind == FeatureKind::DiskDisk || kind == FeatureKind::PolygonVertexDisk;
}

}  // namespace

double touch_time(Vec2 apart, Vec2 slide, double radius, double h)
{
  const double a = length_sq(slide);
  const double half_b = dot(apart, slide);
  const double c = length_sq(apart) - radius * radius;
  const double disc = half_b * half_b - a * c;
  if (a == 0.0 || half_b >= 0.0 || disc < 0.0)
  {
    return h;  // not approaching, or passing wide
  }
  const double t = c / (-half_b + std::sqrt(disc));  // the smaller root, without cancellation
  return std::clamp(t, 0.0, h);
}

/// Round contacts whose centres slide past each other by more than
/// kRoundSlideFraction of their distance in a frame (the straight gap would err).
void WorldImpl::list_round_points()
{
  if (round_points_.capacity() < points_.size())
  {
    round_points_.reserve(points_.size());  // once the world's contacts stop growing, no allocation
  }
  const double frame = settings_.dt;
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    const ContactPoint& p = points_[k];
    // A point that can bounce keeps its normal: its Newton target is aimed
    // along it each substep.
    if (!p.active || p.count != 1 || p.restitution > 0.0 || !round_kind(p.feature))
    {
      continue;
    }
    const double radius_a = disk_[p.a] ? bodies_[p.a].radius() : 0.0;
    const double radius_b = disk_[p.b] ? bodies_[p.b].radius() : 0.0;
    const double reach = radius_a + radius_b + p.separation;  // the centres' distance at prepare
    if (!(reach > 0.0))
    {
      continue;
    }
    // The centres' arms: a disk's is zero; a vertex lies on the normal
    // through the other body's centre, `reach` from it.
    const Vec2 centres = prepared_position_[p.b] - prepared_position_[p.a];
    const Vec2 arm_a = radius_a > 0.0 ? Vec2{0.0, 0.0} : centres - reach * p.normal;
    const Vec2 arm_b = radius_b > 0.0 ? Vec2{0.0, 0.0} : reach * p.normal - centres;
    const BodyVelocity& va = velocity_[p.a];
    const BodyVelocity& vb = velocity_[p.b];
    const Vec2 slide = (vb.v + cross(vb.omega, arm_b)) - (va.v + cross(va.omega, arm_a));
    const double across = dot(slide, perp(p.normal)) * frame;
    if (std::abs(across) <= kRoundSlideFraction * reach)
    {
      continue;
    }
    round_points_.push_back(
        RoundPoint{k, p.normal, p.r_a, p.r_b, p.anchor_drift, arm_a, arm_b, reach, radius_a, radius_b});
    if (rows_on())
    {
      soft_rows_.keep_on_point_verbs(k);
    }
  }
}

/// Round contacts: their normals along the line between their centres now,
/// their gaps the centres' distance less the radii, a speculative gap only
/// as far as their path closes before they touch.
void WorldImpl::follow_round_points(double h, bool as_prepared)
{
  for (const RoundPoint& r : round_points_)
  {
    ContactPoint& p = points_[r.point];
    const BodyVelocity& a = velocity_[p.a];
    const BodyVelocity& b = velocity_[p.b];
    // The centres now (a vertex turns with its body), and the slip along the
    // tangent of prepare, which friction goes on reading.
    const Vec2 arm_a = rotate(r.arm_a, a.turned_cos, a.turned_sin);
    const Vec2 arm_b = rotate(r.arm_b, b.turned_cos, b.turned_sin);
    const Vec2 apart = r.reach * r.normal + (b.moved + arm_b - r.arm_b) - (a.moved + arm_a - r.arm_a);
    const double reach = length(apart);
    const double gap = reach - (r.radius_a + r.radius_b);
    p.normal = r.normal;
    p.r_a = r.r_a;
    p.r_b = r.r_b;
    const double slip = slip_at(p, anchor_offset(p, velocity_));
    double speculative = gap;
    if (!as_prepared && reach > 0.0)
    {
      // The point pushes along the line between the centres, from the
      // middle of the gap between the surfaces.
      p.normal = apart / reach;
      p.r_a = arm_a + (r.radius_a + 0.5 * gap) * p.normal;
      p.r_b = arm_b - (r.radius_b + 0.5 * gap) * p.normal;
      prepare_masses(p, p.restitution);
      // Speculative: the solver lets the point close along its normal by
      // the gap in a substep; along the centres' path they may close later
      // or not at all (a corner passing over a peg's top).
      const Vec2 slide = (b.v + cross(b.omega, arm_b)) - (a.v + cross(a.omega, arm_a));
      const double closing = -dot(slide, p.normal);
      if (gap > 0.0 && closing > 0.0)
      {
        speculative = std::max(gap, closing * touch_time(apart, slide, r.radius_a + r.radius_b, h));
      }
    }
    set_followed(p, anchor_offset(p, velocity_), speculative, r.anchor_drift + slip);
  }
}

}  // namespace detail
}  // namespace collision2d
