// Rigid body construction and validation (polygons recentred on their centroid, their own inertia).
//
// Polygon outlines are cleaned before use: repeated vertices and vertices on a
// straight line between their neighbours are DROPPED (not rejected), because a
// box given with a mid-edge vertex is still a valid convex box and keeping the
// 180-degree vertex would give a zero-length face-normal jump that the narrow
// phase would have to special-case. What is left must turn left at every vertex
// and wind exactly once, otherwise the outline is rejected as non-convex.
#include "collision2d/body.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>

namespace collision2d
{
namespace
{
/// |sin| of the turn below which a vertex counts as collinear with its
/// neighbours (dimensionless): far below any deliberate corner, well above
/// the round-off of coordinates that are exactly on a line.
constexpr double kCollinearSine = 1e-10;
/// A repeated vertex: closer to its predecessor than this fraction of the
/// outline's size.
constexpr double kDuplicateRelative = 1e-12;
/// Allowed error in the total turning of a convex outline (rad).
constexpr double kWindingTolerance = 1e-6;
constexpr double kTwoPi = 6.283185307179586;

std::string number(double v)
{
  std::ostringstream out;
  out << v;
  return out.str();
}

void require_positive_finite(double value, const char* field)
{
  if (!(std::isfinite(value) && value > 0.0))
  {
    throw std::invalid_argument(std::string("Body: ") + field + " must be positive and finite (got " +
                                number(value) + ")");
  }
}

void require_finite(double value, const char* field)
{
  if (!std::isfinite(value))
  {
    throw std::invalid_argument(std::string("Body: ") + field + " must be finite (got " + number(value) + ")");
  }
}

void require_finite(Vec2 value, const char* field)
{
  if (!is_finite(value))
  {
    throw std::invalid_argument(std::string("Body: ") + field + " must be finite (got " + number(value.x) + ", " +
                                number(value.y) + ")");
  }
}

/// Largest coordinate magnitude relative to the first vertex: the length scale
/// the relative tolerances refer to.
double outline_scale(const std::vector<Vec2>& v)
{
  double scale = 0.0;
  for (const Vec2& p : v)
  {
    scale = std::max(scale, length(p - v.front()));
  }
  return scale;
}

/// Removes repeated vertices and vertices lying on the line between their
/// neighbours (see the file comment). Repeats until nothing changes because
/// dropping one vertex can make its neighbour collinear.
std::vector<Vec2> drop_redundant_vertices(std::vector<Vec2> v)
{
  const double min_edge = kDuplicateRelative * outline_scale(v);
  bool changed = true;
  while (changed && v.size() >= 3)
  {
    changed = false;
    for (std::size_t i = 0; i < v.size() && v.size() >= 3; ++i)
    {
      const Vec2 prev = v[(i + v.size() - 1) % v.size()];
      const Vec2 next = v[(i + 1) % v.size()];
      const Vec2 in = v[i] - prev;
      const Vec2 out = next - v[i];
      const bool repeated = length(in) <= min_edge;
      // Only a straight continuation is dropped; a 180-degree reversal is a
      // spike, which the convexity check must see and reject.
      const bool straight = std::abs(cross(in, out)) <= kCollinearSine * length(in) * length(out) && dot(in, out) > 0.0;
      if (repeated || straight)
      {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  return v;
}

double signed_area(const std::vector<Vec2>& v)
{
  double twice_area = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    twice_area += cross(v[i], v[(i + 1) % v.size()]);
  }
  return 0.5 * twice_area;
}

/// Convex and simple: turns left at every vertex and the turns add up to one
/// full revolution (a star or a doubly wound outline also turns left
/// everywhere, but turns 4 pi or more).
void require_convex(const std::vector<Vec2>& v)
{
  double turning = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    const Vec2 in = v[i] - v[(i + v.size() - 1) % v.size()];
    const Vec2 out = v[(i + 1) % v.size()] - v[i];
    // A reversal (cross 0, dot < 0) must fail here too, hence cross, not atan2.
    if (!(cross(in, out) > 0.0))
    {
      throw std::invalid_argument("Body: vertices must outline a convex polygon (vertex " + std::to_string(i) +
                                  " is reflex or reverses direction)");
    }
    turning += std::atan2(cross(in, out), dot(in, out));
  }
  if (std::abs(turning - kTwoPi) > kWindingTolerance)
  {
    throw std::invalid_argument("Body: vertices must outline a simple convex polygon (outline winds " +
                                number(turning / kTwoPi) + " times)");
  }
}

/// Area centroid of a polygon. Computed relative to the first vertex so that
/// outlines far from the body-frame origin keep their precision.
Vec2 area_centroid(const std::vector<Vec2>& v, double area)
{
  const Vec2 origin = v.front();
  Vec2 sum;
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    const Vec2 p = v[i] - origin;
    const Vec2 q = v[(i + 1) % v.size()] - origin;
    sum += cross(p, q) * (p + q);
  }
  return origin + sum / (6.0 * area);
}

/// Polar second moment of area about the body-frame origin (m^4): the sum over
/// the fan of triangles (origin, p, q).
double polar_moment_of_area(const std::vector<Vec2>& v)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    const Vec2 p = v[i];
    const Vec2 q = v[(i + 1) % v.size()];
    sum += cross(p, q) * (dot(p, p) + dot(p, q) + dot(q, q));
  }
  return sum / 12.0;
}

/// Finite inputs can still give unusable mass properties: a radius of 1e-200
/// squares to an inertia of 0 (inverse inertia inf, then inf * 0 = NaN in an
/// effective mass), a mass of 1e-320 has an infinite inverse, and outlines of
/// size 1e200 overflow area, radius or inertia to inf (then inf * 0 in the
/// kinetic energy). Such bodies are rejected here instead of producing NaN
/// later.
void require_usable(double mass, double inv_mass, double inertia, double inv_inertia, double radius)
{
  const bool usable = std::isfinite(inv_mass) && inv_mass > 0.0 && std::isfinite(inertia) && inertia > 0.0 &&
                      std::isfinite(inv_inertia) && inv_inertia > 0.0 && std::isfinite(radius) && radius > 0.0;
  if (!usable)
  {
    throw std::invalid_argument("Body: mass " + number(mass) + " and size " + number(radius) +
                                " give unusable mass properties (inverse mass " + number(inv_mass) + ", inertia " +
                                number(inertia) + ", inverse inertia " + number(inv_inertia) +
                                "): mass, size or their product is outside the double range");
  }
}

}  // namespace

Body::Body(double mass, double radius, Vec2 position, Vec2 velocity, double omega)
  : mass_(mass)
  , inv_mass_(0.0)
  , inertia_(0.0)
  , inv_inertia_(0.0)
  , radius_(radius)
  , position_(position)
  , velocity_(velocity)
  , omega_(omega)
  , shape_(Shape::Disk)
{
  require_positive_finite(mass, "mass");
  require_positive_finite(radius, "radius");
  require_finite(position, "position");
  require_finite(velocity, "velocity");
  require_finite(omega, "omega");
  inv_mass_ = 1.0 / mass_;
  inertia_ = 0.5 * mass_ * radius_ * radius_;
  inv_inertia_ = 1.0 / inertia_;
  require_usable(mass_, inv_mass_, inertia_, inv_inertia_, radius_);
}

Body::Body(double mass, const std::vector<Vec2>& local_vertices, Vec2 position, Vec2 velocity, double theta,
           double omega)
  : mass_(mass)
  , inv_mass_(0.0)
  , inertia_(0.0)
  , inv_inertia_(0.0)
  , radius_(0.0)
  , position_(position)
  , velocity_(velocity)
  , omega_(omega)
  , shape_(Shape::Polygon)
{
  require_positive_finite(mass, "mass");
  require_finite(position, "position");
  require_finite(velocity, "velocity");
  require_finite(theta, "theta");
  require_finite(omega, "omega");
  if (local_vertices.size() < 3)
  {
    throw std::invalid_argument("Body: vertices must number at least 3 (got " +
                                std::to_string(local_vertices.size()) + ")");
  }
  for (std::size_t i = 0; i < local_vertices.size(); ++i)
  {
    require_finite(local_vertices[i], ("vertices[" + std::to_string(i) + "]").c_str());
  }
  std::vector<Vec2> outline = drop_redundant_vertices(local_vertices);
  const double area = outline.size() >= 3 ? signed_area(outline) : 0.0;
  if (!(area > 0.0))
  {
    throw std::invalid_argument("Body: vertices must enclose a positive area counter-clockwise (area " +
                                number(area) + ")");
  }
  require_convex(outline);

  const Vec2 centroid = area_centroid(outline, area);
  local_vertices_.reserve(outline.size());
  for (const Vec2& p : outline)
  {
    local_vertices_.push_back(p - centroid);
    radius_ = std::max(radius_, length(local_vertices_.back()));
  }
  local_normals_.reserve(outline.size());
  for (std::size_t i = 0; i < local_vertices_.size(); ++i)
  {
    const Vec2 edge = local_vertices_[(i + 1) % local_vertices_.size()] - local_vertices_[i];
    // Clockwise perpendicular of a counter-clockwise edge points outward.
    local_normals_.push_back(Vec2{edge.y, -edge.x} / length(edge));
  }
  const double density = mass_ / area;
  inv_mass_ = 1.0 / mass_;
  inertia_ = density * polar_moment_of_area(local_vertices_);
  inv_inertia_ = 1.0 / inertia_;
  require_usable(mass_, inv_mass_, inertia_, inv_inertia_, radius_);
  for (std::size_t i = 0; i < local_vertices_.size(); ++i)
  {
    require_finite(local_vertices_[i], "recentred vertex");
    require_finite(local_normals_[i], "face normal");
  }
  set_theta(theta);
}

Vec2 Body::world_face_normal(std::size_t i) const
{
  return rotate(local_normals_[i], cos_, sin_);
}

double Body::kinetic_energy() const
{
  return 0.5 * mass_ * length_sq(velocity_) + 0.5 * inertia_ * omega_ * omega_;
}

double Body::angular_momentum() const
{
  return inertia_ * omega_ + mass_ * cross(position_, velocity_);
}

void Body::set_theta(double theta)
{
  theta_ = theta;
  cos_ = std::cos(theta);
  sin_ = std::sin(theta);
}

}  // namespace collision2d
