// Field checks with messages that say where a request went wrong.
#include "collision2d/ros/validation.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>

namespace collision2d
{
namespace ros_interface
{
namespace
{
constexpr std::size_t kMinPolygonVertices = 3;
/// Relative to the outline's squared extent: an edge or area this small is
/// round-off of coincident or collinear input, not a real shape.
constexpr double kRelativeDegeneracy = 1e-12;
/// A convex outline turns by exactly 2 pi; more means it winds around twice.
constexpr double kFullTurn = 2.0 * M_PI;
constexpr double kTurnTolerance = 1e-6;  // rad
/// Longest shortest-round-trip double: sign, 17 digits, point, exponent.
constexpr std::size_t kNumberChars = 32;

std::string vertex_name(std::size_t i)
{
  return "vertices[" + std::to_string(i) + "]";
}

}  // namespace

void reject(const std::string& where, const std::string& problem)
{
  throw InvalidRequest(where + ": " + problem);
}

std::string body_label(std::size_t index, std::uint32_t id)
{
  return "bodies[" + std::to_string(index) + "] (id " + std::to_string(id) + ")";
}

std::string format_number(double value)
{
  if (std::isnan(value))
  {
    return "nan";  // to_chars writes "-nan" for a NaN with the sign bit set
  }
  // Shortest text that reads back exactly: "0.1", not "0.10000000000000001".
  char text[kNumberChars];
  const std::to_chars_result end = std::to_chars(text, text + kNumberChars, value);
  return std::string(text, end.ptr);
}

void require_finite(double value, const std::string& where, const std::string& field)
{
  if (!std::isfinite(value))
  {
    reject(where, field + " = " + format_number(value) + " is not finite");
  }
}

void require_positive(double value, const std::string& where, const std::string& field)
{
  require_finite(value, where, field);
  if (!(value > 0.0))
  {
    reject(where, field + " = " + format_number(value) + " must be > 0");
  }
}

void require_non_negative(double value, const std::string& where, const std::string& field)
{
  require_finite(value, where, field);
  if (value < 0.0)
  {
    reject(where, field + " = " + format_number(value) + " must be >= 0");
  }
}

void require_in_range(double value, double lo, double hi, const std::string& where, const std::string& field)
{
  require_finite(value, where, field);
  if (value < lo || value > hi)
  {
    reject(where, field + " = " + format_number(value) + " must be in [" + format_number(lo) + ", " +
                      format_number(hi) + "]");
  }
}

void check_polygon_outline(const std::vector<Vec2>& v, const std::string& where)
{
  const std::size_t n = v.size();
  if (n < kMinPolygonVertices)
  {
    reject(where, "vertices: " + std::to_string(n) + " given, a POLYGON needs at least 3");
  }
  double extent_sq = 0.0;
  for (const Vec2& p : v)
  {
    extent_sq = std::max(extent_sq, length_sq(p - v[0]));
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t next = (i + 1) % n;
    if (length_sq(v[next] - v[i]) <= kRelativeDegeneracy * extent_sq)
    {
      reject(where, vertex_name(next) + " repeats " + vertex_name(i));
    }
  }
  // Twice the signed area, taken about v[0] to keep round-off relative.
  double twice_area = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i)
  {
    twice_area += cross(v[i] - v[0], v[i + 1] - v[0]);
  }
  if (std::abs(twice_area) <= kRelativeDegeneracy * extent_sq)
  {
    reject(where, "vertices enclose zero area");
  }
  if (twice_area < 0.0)
  {
    reject(where, "vertices are clockwise (signed area " + format_number(0.5 * twice_area) +
                      " m^2); list them counter-clockwise");
  }
  double turning = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec2 in = v[i] - v[(i + n - 1) % n];
    const Vec2 out = v[(i + 1) % n] - v[i];
    const double turn = cross(in, out);
    if (turn < -kRelativeDegeneracy * std::sqrt(length_sq(in) * length_sq(out)))
    {
      reject(where, vertex_name(i) + ": the outline turns clockwise here, so it is not convex");
    }
    turning += std::atan2(turn, dot(in, out));
  }
  if (turning > kFullTurn + kTurnTolerance)
  {
    reject(where, "vertices wind around more than once (self-intersecting), so the outline is not convex");
  }
}

void check_distinct_centres(const std::vector<Vec2>& centres, const std::vector<std::string>& labels)
{
  std::vector<std::size_t> order(centres.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto before = [&centres](std::size_t i, std::size_t j) {
    return centres[i].x < centres[j].x || (centres[i].x == centres[j].x && centres[i].y < centres[j].y);
  };
  std::sort(order.begin(), order.end(), before);
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    const std::size_t i = std::min(order[k - 1], order[k]);
    const std::size_t j = std::max(order[k - 1], order[k]);
    if (centres[i] == centres[j])
    {
      reject(labels[i] + " and " + labels[j],
             "centres coincide at (" + format_number(centres[i].x) + ", " + format_number(centres[i].y) +
                 "); overlapping bodies with one centre have no contact normal");
    }
  }
}

}  // namespace ros_interface
}  // namespace collision2d
