// Exact time of impact for translating convex shapes, orientation held fixed.
//
// Every shape is a convex core rounded by a radius: a polygon is its own core
// with radius 0, a disk is its centre point rounded by its radius. Two shapes
// translated by t*da and t*db touch when t*(db - da) lies in the Minkowski
// difference A - B, which is the Minkowski sum of core(A) and the reflected
// core(B), rounded by the sum of the radii. The first touch is therefore where
// a ray from the origin along the relative displacement enters that set: a
// closed form per boundary feature (a line for a straight edge, a quadratic for
// a vertex circle), no sampling, so nothing tunnels.
#include "collision2d/time_of_impact.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "collision2d/touch_tolerance.h"

namespace collision2d
{
namespace
{
constexpr double kNever = std::numeric_limits<double>::infinity();

/// One body's core in world coordinates, scaled by `sign` (-1 reflects the
/// second body of a pair through the origin, which keeps counter-clockwise
/// order). A disk's core is its centre: one vertex, no edges.
class Core
{
public:
  Core(const Body& body, double sign) : body_(body), sign_(sign) {}

  bool is_point() const { return body_.shape() == Shape::Disk; }
  std::size_t size() const { return is_point() ? 1 : body_.vertex_count(); }
  std::size_t edge_count() const { return is_point() ? 0 : body_.vertex_count(); }
  double rounding() const { return is_point() ? body_.radius() : 0.0; }

  /// Vertex i, wrapping around.
  Vec2 vertex(std::size_t i) const
  {
    return sign_ * (is_point() ? body_.position() : body_.world_vertex(i % body_.vertex_count()));
  }
  Vec2 edge(std::size_t i) const { return vertex(i + 1) - vertex(i); }

  /// Index of the lowest vertex (leftmost among equals). Walking the outline
  /// counter-clockwise from there, edge directions sweep [0, 2 pi) in order,
  /// which is what the edge merge relies on.
  std::size_t lowest_vertex() const
  {
    std::size_t best = 0;
    Vec2 lowest = vertex(0);
    for (std::size_t i = 1; i < size(); ++i)
    {
      const Vec2 v = vertex(i);
      if (v.y < lowest.y || (v.y == lowest.y && v.x < lowest.x))
      {
        best = i;
        lowest = v;
      }
    }
    return best;
  }

private:
  const Body& body_;
  double sign_;
};

/// 0 for directions with angle in [0, pi), 1 for [pi, 2 pi).
int half_turn(Vec2 v) { return (v.y < 0.0 || (v.y == 0.0 && v.x < 0.0)) ? 1 : 0; }

/// Orders directions by angle in [0, 2 pi) exactly: by half turn, then by the
/// sign of the cross product (no atan2 round-off between nearly parallel edges).
bool angle_less(Vec2 u, Vec2 v)
{
  const int hu = half_turn(u);
  const int hv = half_turn(v);
  if (hu != hv)
  {
    return hu < hv;
  }
  return cross(u, v) > 0.0;
}

/// Streams the counter-clockwise edges of core(a) + core(b) to `visitor` by
/// merging the two edge sequences in angle order: O(n + m) and nothing stored.
/// Parallel edges of the same direction merge into one. When both cores are
/// points the sum is a point, passed to visitor.point().
template <typename Visitor>
void for_each_sum_edge(const Core& a, const Core& b, Visitor& visitor)
{
  const std::size_t a0 = a.lowest_vertex();
  const std::size_t b0 = b.lowest_vertex();
  const std::size_t na = a.edge_count();
  const std::size_t nb = b.edge_count();
  Vec2 corner = a.vertex(a0) + b.vertex(b0);
  if (na + nb == 0)
  {
    visitor.point(corner);
    return;
  }
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < na || j < nb)
  {
    const Vec2 ea = i < na ? a.edge(a0 + i) : Vec2{};
    const Vec2 eb = j < nb ? b.edge(b0 + j) : Vec2{};
    const bool take_a = i < na && (j == nb || !angle_less(eb, ea));
    const bool take_b = j < nb && (i == na || !angle_less(ea, eb));
    const Vec2 e = (take_a ? ea : Vec2{}) + (take_b ? eb : Vec2{});
    visitor.edge(corner, e);
    corner += e;
    i += take_a ? 1 : 0;
    j += take_b ? 1 : 0;
  }
}

/// Outward unit normal of a counter-clockwise edge (zero for a zero edge).
Vec2 outward_normal(Vec2 e)
{
  const double len = length(e);
  return len > 0.0 ? Vec2{e.y / len, -e.x / len} : Vec2{};
}

/// First t >= 0 at which the ray t*d enters core + disk(radius), radius > 0:
/// 0 when the origin is already inside, kNever when the ray misses. Its
/// boundary is the edges pushed out by the radius joined by arcs of the vertex
/// circles; from outside, the earliest hit over those features is the entry.
class RoundedRayCast
{
public:
  RoundedRayCast(Vec2 d, double radius) : d_(d), radius_(radius) {}

  void point(Vec2 p) { hit_vertex(p); }

  void edge(Vec2 start, Vec2 e)
  {
    ++edges_;
    hit_vertex(start);
    const Vec2 n = outward_normal(e);
    if (length_sq(n) == 0.0)
    {
      return;
    }
    if (dot(n, start) < 0.0)
    {
      origin_in_core_ = false;
    }
    const double len_sq = length_sq(e);
    const double along = std::clamp(dot(-start, e) / len_sq, 0.0, 1.0);
    if (length_sq(start + along * e) <= radius_ * radius_)
    {
      origin_in_rounding_ = true;
    }
    // The pushed-out edge line n.x = offset, entered only while moving against n.
    const double offset = dot(n, start) + radius_;
    const double approach = dot(n, d_);
    if (offset < 0.0 && approach < 0.0)
    {
      const double t = offset / approach;
      const double s = dot(t * d_ - start, e);
      if (s >= 0.0 && s <= len_sq)
      {
        first_hit_ = std::min(first_hit_, t);
      }
    }
  }

  double entry_time() const
  {
    const bool inside = origin_in_rounding_ || (edges_ > 0 && origin_in_core_);
    return inside ? 0.0 : first_hit_;
  }

private:
  /// |t d - c|^2 = r^2, smaller root in the cancellation-free form c'/(b + sqrt).
  void hit_vertex(Vec2 c)
  {
    const double a = length_sq(d_);
    const double b = dot(d_, c);
    const double c_term = length_sq(c) - radius_ * radius_;
    if (c_term <= 0.0)
    {
      origin_in_rounding_ = true;
      return;
    }
    const double discriminant = b * b - a * c_term;
    if (b <= 0.0 || discriminant < 0.0)
    {
      return;  // moving away from the circle, or passing beside it
    }
    first_hit_ = std::min(first_hit_, c_term / (b + std::sqrt(discriminant)));
  }

  Vec2 d_;
  double radius_;
  std::size_t edges_ = 0;
  bool origin_in_core_ = true;
  bool origin_in_rounding_ = false;
  double first_hit_ = kNever;
};

/// First t >= 0 at which the ray t*d enters the polygonal core shrunk by
/// `erosion` >= 0 (every edge moved inward): a clip of the ray against the
/// edges' half-planes. A point core shrunk by anything is empty.
class SharpRayCast
{
public:
  SharpRayCast(Vec2 d, double erosion) : d_(d), erosion_(erosion) {}

  void point(Vec2 /*p*/) { missed_ = true; }

  void edge(Vec2 start, Vec2 e)
  {
    const Vec2 n = outward_normal(e);
    if (length_sq(n) == 0.0)
    {
      return;
    }
    // Inside means t * dot(n, d) <= offset.
    const double offset = dot(n, start) - erosion_;
    const double approach = dot(n, d_);
    if (approach < 0.0)
    {
      t_enter_ = std::max(t_enter_, offset / approach);
    }
    else if (approach > 0.0)
    {
      t_exit_ = std::min(t_exit_, offset / approach);
    }
    else if (offset < 0.0)
    {
      missed_ = true;  // parallel to the edge and outside it
    }
  }

  double entry_time() const { return (missed_ || t_enter_ > t_exit_) ? kNever : t_enter_; }

private:
  Vec2 d_;
  double erosion_;
  bool missed_ = false;
  double t_enter_ = 0.0;
  double t_exit_ = kNever;
};

/// First t >= 0 at which t*d enters core(a) + core(b) grown by `rounding`
/// (shrunk when it is negative).
double first_entry(const Core& a, const Core& b, Vec2 d, double rounding)
{
  if (rounding > 0.0)
  {
    RoundedRayCast cast(d, rounding);
    for_each_sum_edge(a, b, cast);
    return cast.entry_time();
  }
  SharpRayCast cast(d, -rounding);
  for_each_sum_edge(a, b, cast);
  return cast.entry_time();
}

}  // namespace

double time_of_impact(const Body& a, Vec2 da, const Body& b, Vec2 db)
{
  const Core core_a(a, 1.0);
  const Core core_b(b, -1.0);
  const Vec2 d = db - da;
  const double rounding = core_a.rounding() + core_b.rounding();
  // An overlap shallower than this is round-off at a contact just resolved,
  // not an impact; only pairs that get deeper than it within the step count.
  const double tolerance = kRelativeTouchTolerance * (a.radius() + b.radius());
  const double deep = first_entry(core_a, core_b, d, rounding - tolerance);
  if (deep > 1.0)
  {
    return 1.0;
  }
  return std::min(first_entry(core_a, core_b, d, rounding), deep);
}

}  // namespace collision2d
