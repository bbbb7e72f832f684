// Soft step: a contact on a disk's round side whose other side is a
// polygon's vertex or another disk (a parcel's corner crossing a roller, a
// wheel meeting a kerb's edge, two balls passing). A frame's contact keeps
// its normal from prepare, and its gap follows the bodies along that normal
// only; where the two centres of curvature (the disk's centre, the vertex or
// the other centre) slide past each other, the true gap opens by the slide
// squared over twice their distance, which the straight line misses: a
// corner sliding over a round peg reads as sinking into it and is thrown
// up. These points follow their gap exactly instead, as the distance between
// the centres less the radii; a disk that slides off its vertex follows the
// polygon's feature nearest it (iterative mode). They stay on the kernel's
// point verbs, so no other contact pays for them.
// A point that can bounce pushes along the line between the centres too, or
// the pair's angular momentum changes by the impulse times the line's turn
// (two glancing disks lost up to 88% of theirs). Its normal is aimed once a
// substep, before its Newton target, and kept through the substep's passes
// and restitution: one normal a substep keeps an elastic pair's kinetic
// energy exactly. The exact mode leaves such points on their prepared
// normals.

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
/// A point that can bounce is followed once its centres slide past each
/// other by more than this fraction of their distance in a frame: a head-on
/// meeting (no slide but round-off) keeps its normal and its bits.
constexpr double kBounceSlideFraction = 1e-12;
/// A point that can bounce is aimed in a substep only while its centres
/// slide past each other by at most this fraction of their distance in it:
/// farther, the relax at the substep's end finds them apart and undoes the
/// stop, and the pair passes through (a disk past a plank's end at 51 m/s).
constexpr double kBounceAimSlide = 0.25;

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

/// Whether round point p, whose centres of curvature are `reach` apart and
/// slide at `slide`, is followed this frame (round_points_).
bool WorldImpl::round_point_followed(const ContactPoint& p, Vec2 slide, double reach) const
{
  const double frame = settings_.dt;
  const double across = dot(slide, perp(p.normal)) * frame;
  if (p.restitution <= 0.0)
  {
    return std::abs(across) > kRoundSlideFraction * reach;
  }
  // A bouncing pair whose approach cannot close its gap in twice the frame
  // meets only if another contact sends one of them its way: it keeps its
  // row (most of a gas's contacts, found a frame ahead).
  const double closing = std::max(0.0, -dot(slide, p.normal)) + std::max(0.0, closing_gravity(p)) * frame;
  return std::abs(across) > kBounceSlideFraction * reach && 2.0 * closing * frame >= p.separation;
}

/// Round contacts whose centres slide past each other by more than
/// kRoundSlideFraction of their distance in a frame (the straight gap would
/// err), and those that can bounce and may meet this frame.
void WorldImpl::list_round_points()
{
  if (round_points_.capacity() < points_.size())
  {
    round_points_.reserve(2 * points_.size());  // room to grow: a warmed-up world allocates nothing
  }
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    const ContactPoint& p = points_[k];
    if (!p.active || p.count != 1 || !round_kind(p.feature))
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
    if (!round_point_followed(p, slide, reach))
    {
      continue;
    }
    round_points_.push_back(RoundPoint{k, p.normal, p.r_a, p.r_b, p.anchor_drift, p.base_separation, arm_a, arm_b,
                                       reach, radius_a, radius_b});
    if (rows_on())
    {
      soft_rows_.keep_on_point_verbs(k);
    }
  }
}

/// The centres of curvature of a round point now (a vertex turns with its
/// body): their arms from the bodies' centres, and b's less a's.
RoundPlace WorldImpl::round_place(const RoundPoint& r) const
{
  const ContactPoint& p = points_[r.point];
  const BodyVelocity& a = velocity_[p.a];
  const BodyVelocity& b = velocity_[p.b];
  RoundPlace place;
  place.arm_a = rotate(r.arm_a, a.turned_cos, a.turned_sin);
  place.arm_b = rotate(r.arm_b, b.turned_cos, b.turned_sin);
  place.apart = r.reach * r.normal + (b.moved + place.arm_b - r.arm_b) - (a.moved + place.arm_a - r.arm_a);
  place.reach = length(place.apart);
  place.gap = place.reach - (r.radius_a + r.radius_b);
  if (r.radius_a == 0.0 || r.radius_b == 0.0)
  {
    to_nearest_feature(p, r, place);
  }
  place.slide = (b.v + cross(b.omega, place.arm_b)) - (a.v + cross(a.omega, place.arm_a));
  return place;
}

/// A disk on a polygon's vertex may slide past it within a frame onto a
/// face, or on past the face's far vertex; the vertex's gap would then read
/// the distance to the corner while the disk closes on the polygon (a disk
/// skimming over a box's corner sank 20 mm into its top face). The place
/// follows the polygon's feature nearest the disk's centre now: the
/// polygon's centre of curvature becomes that feature's closest point, and
/// the line to the disk's centre runs along its normal. The same in the
/// exact mode.
void WorldImpl::to_nearest_feature(const ContactPoint& p, const RoundPoint& r, RoundPlace& place) const
{
  const bool polygon_first = r.radius_a == 0.0;
  const double radius = polygon_first ? r.radius_b : r.radius_a;
  const DiskFeature nearest = polygon_first ? nearest_feature_now(p.a, p.b) : nearest_feature_now(p.b, p.a);
  const double distance = radius - nearest.depth;
  const bool same_vertex =
      nearest.kind == FeatureKind::PolygonVertexDisk && nearest.index == reference_index(p.feature);
  if (same_vertex || !(distance > 0.0))
  {
    return;  // the vertex stands (or the disk's centre is inside the polygon)
  }
  (polygon_first ? place.arm_a : place.arm_b) = nearest.closest;
  place.apart = (polygon_first ? distance : -distance) * nearest.normal;
  place.reach = distance;
  place.gap = distance - radius;
  place.on_face = nearest.kind == FeatureKind::PolygonFaceDisk;
}

namespace
{
/// The gap the solver may close along p's normal in a substep of h seconds:
/// along the centres' path they may close later than along the normal, or
/// not at all (a corner passing over a peg's top).
double round_speculative_gap(const ContactPoint& p, const RoundPoint& r, const RoundPlace& place, double h)
{
  const double closing = -dot(place.slide, p.normal);
  if (place.gap > 0.0 && closing > 0.0)
  {
    return std::max(place.gap, closing * touch_time(place.apart, place.slide, r.radius_a + r.radius_b, h));
  }
  return place.gap;
}

/// Puts p back on the normal and lever arms it was prepared with; returns its
/// slip along the tangent of prepare, which friction goes on reading (m).
double back_to_prepared(ContactPoint& p, const RoundPoint& r, const std::vector<BodyVelocity>& velocity)
{
  p.normal = r.normal;
  p.r_a = r.r_a;
  p.r_b = r.r_b;
  return slip_at(p, anchor_offset(p, velocity));
}

/// Puts p back on the row it was prepared with: its normal, lever arms,
/// masses and the straight gap along that normal.
void keep_prepared_row(ContactPoint& p, const RoundPoint& r, const std::vector<BodyVelocity>& velocity)
{
  back_to_prepared(p, r, velocity);
  prepare_masses(p, p.restitution);
  p.base_separation = r.base_separation;
  p.anchor_drift = r.anchor_drift;
}

/// Pushes p along `normal` from the middle of a gap of `gap` (m) between the surfaces.
void aim_round_point(ContactPoint& p, const RoundPoint& r, const RoundPlace& place, Vec2 normal, double gap)
{
  p.normal = normal;
  p.r_a = place.arm_a + (r.radius_a + 0.5 * gap) * normal;
  p.r_b = place.arm_b - (r.radius_b + 0.5 * gap) * normal;
  prepare_masses(p, p.restitution);
}

/// Aims bouncing point p along `normal` for a substep (aim_round_point),
/// its gap followed from `place` along it.
void aim_for_substep(ContactPoint& p, RoundPoint& r, const RoundPlace& place, Vec2 normal, double gap,
                     const std::vector<BodyVelocity>& velocity)
{
  const double slip = back_to_prepared(p, r, velocity);
  aim_round_point(p, r, place, normal, gap);
  set_followed(p, anchor_offset(p, velocity), place.gap, r.anchor_drift + slip);
  r.aimed = true;
}

/// Whether a bouncing round point off any face is aimed this substep of h
/// seconds along the line between its centres (else it keeps its prepared
/// row, its gap followed along the path). Not in the exact mode: aimed so, a
/// disk squeezed under a heavy one and against a plank was let go of by its
/// island's solve and the world gained energy. Not when the centres slide
/// across by more than kBounceAimSlide of their distance in the substep.
/// Not when the path passes wide: the pair meets only if its path touches
/// within two substeps (its passes if it closes its gap, else the relax at
/// the substep's end if it is left within a substep's approach of
/// touching), so no ghost bounce.
bool aims_along_line(const RoundPlace& place, double radius, Vec2 across, double h, bool exact)
{
  if (exact || length(across) * h > kBounceAimSlide * place.reach)
  {
    return false;
  }
  return place.gap <= 0.0 || touch_time(place.apart, place.slide, radius, 2.0 * h) < 2.0 * h;
}
}  // namespace

/// Round contacts: their normals along the line between their centres now
/// (a point that can bounce keeps the one aim_round_bounces gave it this
/// substep), their gaps the centres' distance less the radii, a speculative
/// gap only as far as their path closes before they touch.
void WorldImpl::follow_round_points(double h, bool as_prepared)
{
  for (const RoundPoint& r : round_points_)
  {
    ContactPoint& p = points_[r.point];
    const Vec2 aimed_normal = p.normal;
    const Vec2 aimed_r_a = p.r_a;
    const Vec2 aimed_r_b = p.r_b;
    const RoundPlace place = round_place(r);
    if (!as_prepared && p.restitution > 0.0 && !r.aimed)
    {
      // Not aimed this substep (too fast, or its path passes wide): the
      // prepared row, its gap the true one and as far as the path closes
      // before touching (a corner's prepared line is no wall); its slip
      // goes on from the prepared anchor.
      keep_prepared_row(p, r, velocity_);
      const Vec2 offset = anchor_offset(p, velocity_);
      set_followed(p, offset, round_speculative_gap(p, r, place, 2.0 * h), r.anchor_drift + slip_at(p, offset));
      continue;
    }
    const double slip = back_to_prepared(p, r, velocity_);
    double speculative = place.gap;
    if (!as_prepared && place.reach > 0.0)
    {
      if (p.restitution > 0.0)
      {
        p.normal = aimed_normal;  // and its lever arms: one row all substep
        p.r_a = aimed_r_a;
        p.r_b = aimed_r_b;
      }
      else
      {
        aim_round_point(p, r, place, place.apart / place.reach, place.gap);
        speculative = place.on_face ? place.gap : round_speculative_gap(p, r, place, h);
      }
    }
    set_followed(p, anchor_offset(p, velocity_), speculative, r.anchor_drift + slip);
  }
}

/// Before each substep of h seconds (and before its Newton targets), each
/// round point that can bounce aims its normal for the substep. The push
/// that stops the approach acts where the centres are at the substep's
/// start, the rebound where they are at its end; the angular momentum they
/// add is zero when the normal lies along the sum of the two lines between
/// the centres, each weighted by its impulse (a touching pair's rebound is e
/// times its stop, so the line e / (1 + e) of the way along).
void WorldImpl::aim_round_bounces(double h)
{
  for (RoundPoint& r : round_points_)
  {
    ContactPoint& p = points_[r.point];
    const RoundPlace place = round_place(r);
    r.aimed = false;
    if (p.restitution <= 0.0 || !(place.reach > 0.0))
    {
      continue;
    }
    const Vec2 now = place.apart / place.reach;
    if (place.on_face)
    {
      // Slid off its vertex onto a face: it bounces along the face's normal,
      // which the slide does not turn.
      aim_for_substep(p, r, place, now, place.gap, velocity_);
      continue;
    }
    const Vec2 across = place.slide - dot(place.slide, now) * now;
    const double radius = r.radius_a + r.radius_b;
    if (!aims_along_line(place, radius, across, h, settings_.solver_mode == SolverMode::Exact))
    {
      keep_prepared_row(p, r, velocity_);
      continue;
    }
    const double approach = -dot(place.slide, now);
    const double stop = std::max(0.0, approach - std::max(place.gap, 0.0) / h);
    const double rebound = approach > settings_.restitution_threshold ? p.restitution * approach : 0.0;
    const double share = stop + rebound > 0.0 ? rebound / (stop + rebound) : 0.0;
    // The line between where the centres are at the push and at the
    // rebound, weighted by the two: in the substep the pair slides on and
    // closes by at most its gap.
    const double closes = std::min(std::max(approach, 0.0) * h, std::max(place.gap, 0.0));
    const Vec2 line = place.apart + share * (h * across - closes * now);
    const double turned = length(line);
    if (!(turned > 0.0))
    {
      continue;
    }
    // The lever arms reach the surfaces where that line puts them, so
    // friction acts at one point of both bodies too.
    aim_for_substep(p, r, place, line / turned, turned - radius, velocity_);
  }
}

}  // namespace detail
}  // namespace collision2d
