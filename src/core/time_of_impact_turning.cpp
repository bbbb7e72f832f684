// Time of impact for bodies that turn as they move (a kinematic link that
// spins). A turning outline has no closed-form sweep, so the pair is
// advanced in steps that no point's move can carry through the other body:
// each step is the gap plus the two inner radii over a bound on how fast any
// point closes. The first step that ends overlapping brackets the touch,
// which a regula falsi search then pins to the touch tolerance.
#include <algorithm>
#include <cmath>
#include <limits>

#include "collision2d/time_of_impact.h"
#include "collision2d/touch_tolerance.h"
#include "outline_gap.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Steps of the advance at most: a pair whose points move more than this
/// many summed inner radii in the sweep takes steps of 1/kMaxAdvances.
constexpr int kMaxAdvances = 1024;
/// Regula falsi iterations at most; it converges in a handful.
constexpr int kMaxRefinements = 100;

Vec2 vertex(const PosedOutline& o, std::size_t i)
{
  return o.position + rotate(o.body->local_vertices()[i], o.cos_theta, o.sin_theta);
}

Vec2 face_normal(const PosedOutline& o, std::size_t i)
{
  return rotate(o.body->local_face_normals()[i], o.cos_theta, o.sin_theta);
}

/// Largest separation of `other`'s vertices from one of `faces`' faces.
double face_separation(const PosedOutline& faces, const PosedOutline& other)
{
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < faces.body->vertex_count(); ++i)
  {
    const Vec2 v = vertex(faces, i);
    const Vec2 n = face_normal(faces, i);
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < other.body->vertex_count(); ++j)
    {
      nearest = std::min(nearest, dot(vertex(other, j) - v, n));
    }
    best = std::max(best, nearest);
  }
  return best;
}

/// Signed distance from point q to a polygon's outline (negative inside).
double point_gap(const PosedOutline& polygon, Vec2 q)
{
  const std::size_t count = polygon.body->vertex_count();
  double outside = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i)
  {
    outside = std::max(outside, dot(q - vertex(polygon, i), face_normal(polygon, i)));
  }
  if (outside <= 0.0)
  {
    return outside;
  }
  double nearest_sq = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec2 a = vertex(polygon, i);
    const Vec2 edge = vertex(polygon, (i + 1) % count) - a;
    const double along = std::clamp(dot(q - a, edge) / length_sq(edge), 0.0, 1.0);
    nearest_sq = std::min(nearest_sq, length_sq(q - (a + along * edge)));
  }
  return std::sqrt(nearest_sq);
}

/// Speed bound (m per unit of t) of any point of a body moving `d` and
/// turning `turn` over the sweep.
double point_speed(const Body& b, Vec2 d, double turn)
{
  return length(d) + (b.shape() == Shape::Polygon ? std::abs(turn) * b.radius() : 0.0);
}

class TurningPair
{
public:
  TurningPair(const Body& a, Vec2 da, double turn_a, const Body& b, Vec2 db, double turn_b)
      : a_(a), b_(b), da_(da), db_(db), turn_a_(turn_a), turn_b_(turn_b)
  {
  }

  /// outline_gap with both bodies moved and turned by fraction t.
  double gap(double t) const { return outline_gap(posed(a_, da_, turn_a_, t), posed(b_, db_, turn_b_, t)); }

private:
  static PosedOutline posed(const Body& body, Vec2 d, double turn, double t)
  {
    const double theta = body.theta() + t * turn;
    return PosedOutline{&body, body.position() + t * d, std::cos(theta), std::sin(theta)};
  }

  const Body& a_;
  const Body& b_;
  Vec2 da_;
  Vec2 db_;
  double turn_a_;
  double turn_b_;
};

/// A t in [lo, hi] at which the gap is within half the tolerance of 0,
/// given gap(lo) > 0 > gap(hi) (regula falsi, Illinois variant).
double refine_touch(const TurningPair& pair, double lo, double gap_lo, double hi, double gap_hi, double tolerance)
{
  int kept_side = 0;
  for (int k = 0; k < kMaxRefinements && hi - lo > 0.0; ++k)
  {
    const double t = std::clamp(lo + (hi - lo) * gap_lo / (gap_lo - gap_hi), lo, hi);
    const double g = pair.gap(t);
    if (std::abs(g) <= 0.5 * tolerance)
    {
      return t;
    }
    // Halving the end that stayed keeps the search from creeping.
    if (g > 0.0)
    {
      lo = t;
      gap_lo = g;
      gap_hi *= kept_side == 1 ? 0.5 : 1.0;
      kept_side = 1;
    }
    else
    {
      hi = t;
      gap_hi = g;
      gap_lo *= kept_side == -1 ? 0.5 : 1.0;
      kept_side = -1;
    }
  }
  return lo;
}

}  // namespace

double inner_radius(const Body& b)
{
  if (b.shape() == Shape::Disk)
  {
    return b.radius();
  }
  double inner = std::numeric_limits<double>::infinity();
  const std::vector<Vec2>& vertices = b.local_vertices();
  const std::vector<Vec2>& normals = b.local_face_normals();
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    inner = std::min(inner, dot(vertices[i], normals[i]));
  }
  return inner;
}

double outline_gap(const PosedOutline& a, const PosedOutline& b)
{
  const bool disk_a = a.body->shape() == Shape::Disk;
  const bool disk_b = b.body->shape() == Shape::Disk;
  if (disk_a && disk_b)
  {
    return length(b.position - a.position) - a.body->radius() - b.body->radius();
  }
  if (disk_a || disk_b)
  {
    const PosedOutline& disk = disk_a ? a : b;
    return point_gap(disk_a ? b : a, disk.position) - disk.body->radius();
  }
  return std::max(face_separation(a, b), face_separation(b, a));
}

}  // namespace detail

double time_of_impact(const Body& a, Vec2 da, double turn_a, const Body& b, Vec2 db, double turn_b)
{
  if (turn_a == 0.0 && turn_b == 0.0)
  {
    return time_of_impact(a, da, b, db);
  }
  const detail::TurningPair pair(a, da, turn_a, b, db, turn_b);
  // As the closed form: an overlap shallower than this is a touch.
  const double tolerance = kRelativeTouchTolerance * (a.radius() + b.radius());
  // A step whose points close by less than the gap plus this cannot carry
  // one outline past the other: that takes twice the inner radii.
  const double no_skip = detail::inner_radius(a) + detail::inner_radius(b);
  const double speed = detail::point_speed(a, da, turn_a) + detail::point_speed(b, db, turn_b);
  double t = 0.0;
  double gap = pair.gap(0.0);
  if (gap < -tolerance)
  {
    return 0.0;
  }
  for (int k = 0; k < detail::kMaxAdvances && speed > 0.0; ++k)
  {
    const double next = std::min(1.0, t + std::max((gap + tolerance + no_skip) / speed, 1.0 / detail::kMaxAdvances));
    const double next_gap = pair.gap(next);
    if (next_gap < -tolerance)
    {
      // Touching within the tolerance already, or the touch lies between.
      return gap <= tolerance ? t : detail::refine_touch(pair, t, gap, next, next_gap, tolerance);
    }
    if (next >= 1.0)
    {
      return 1.0;
    }
    t = next;
    gap = next_gap;
  }
  return 1.0;
}

}  // namespace collision2d
