// Plain 2D vector used throughout the core. Kept an aggregate (no user
// constructors) so `Vec2{1.0, 2.0}` works and it stays trivially copyable.
#pragma once

#include <cmath>

namespace collision2d
{
struct Vec2
{
  double x = 0.0;
  double y = 0.0;

  Vec2& operator+=(const Vec2& o)
  {
    x += o.x;
    y += o.y;
    return *this;
  }
  Vec2& operator-=(const Vec2& o)
  {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  Vec2& operator*=(double s)
  {
    x *= s;
    y *= s;
    return *this;
  }
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
inline Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
inline Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
inline Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Vec2 a, Vec2 b) { return !(a == b); }

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z-component of the 3D cross product.
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// Angular velocity (about z) times a lever arm: w x v = (-w v.y, w v.x).
inline Vec2 cross(double w, Vec2 v) { return {-w * v.y, w * v.x}; }
/// v x w = (w v.y, -w v.x).
inline Vec2 cross(Vec2 v, double w) { return {w * v.y, -w * v.x}; }
inline double length_sq(Vec2 v) { return dot(v, v); }
inline double length(Vec2 v) { return std::sqrt(dot(v, v)); }

namespace detail
{
/// Beyond these magnitudes x*x overflows or loses bits to underflow; scaling
/// by a power of two is exact, so the result only rounds in the operations.
constexpr double kHypotBig = 0x1p500;
constexpr double kHypotSmall = 0x1p-500;
constexpr double kHypotScale = 0x1p600;
}  // namespace detail

/// sqrt(x^2 + y^2) without overflow or underflow to a false zero, built only
/// from correctly rounded operations: the same bits on every IEEE target,
/// which std::hypot (its last bit differs between libms) is not.
inline double portable_hypot(double x, double y)
{
  const double m = std::fmax(std::fabs(x), std::fabs(y));
  if (std::isinf(x) || std::isinf(y))
  {
    return HUGE_VAL;
  }
  if (m > detail::kHypotBig)
  {
    const double xs = x / detail::kHypotScale;
    const double ys = y / detail::kHypotScale;
    return std::sqrt(xs * xs + ys * ys) * detail::kHypotScale;
  }
  if (m < detail::kHypotSmall)
  {
    const double xs = x * detail::kHypotScale;
    const double ys = y * detail::kHypotScale;
    return std::sqrt(xs * xs + ys * ys) / detail::kHypotScale;
  }
  return std::sqrt(x * x + y * y);
}
/// Counter-clockwise perpendicular.
inline Vec2 perp(Vec2 v) { return {-v.y, v.x}; }
/// Rotate v by the angle whose cosine and sine are c and s.
inline Vec2 rotate(Vec2 v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
/// Rotate v by -angle (the inverse of rotate(v, c, s)).
inline Vec2 rotate_inv(Vec2 v, double c, double s) { return {c * v.x + s * v.y, -s * v.x + c * v.y}; }
inline bool is_finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

}  // namespace collision2d
