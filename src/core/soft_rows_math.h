// Internal to soft_rows*.cpp: the arithmetic the soft step's row verbs
// (soft_rows_kernel.h) are written in, for every lane type V: the one-lane
// type's selects, maxima and minima as selects, and two-vectors of lanes;
// and the vector paths' writes of a batch's byte flags from their masks.
#pragma once

#include <cmath>
#include <cstdint>

namespace collision2d
{
namespace detail
{
namespace rows
{
// The one-lane type's operations; the wide type's are found by argument lookup.
inline double sel(bool m, double a, double b) { return m ? a : b; }
inline double neg(double a) { return -a; }
inline double abs(double a) { return std::abs(a); }

/// set_flag of the vector paths, from their masks as bits (lane j is bit j):
/// f[j] = bit j of `set` wherever bit j of `written` is set.
inline void write_flag_bits(std::uint8_t* f, int lanes, int written, int set)
{
  for (int j = 0; j < lanes; ++j)
  {
    if ((written >> j & 1) != 0)
    {
      f[j] = static_cast<std::uint8_t>(set >> j & 1);
    }
  }
}

/// std::max(a, b) and std::min(a, b) as selects, so zeros keep their sign alike.
template <class V>
V vmax(V a, V b)
{
  return sel(a < b, b, a);
}
template <class V>
V vmin(V a, V b)
{
  return sel(b < a, b, a);
}

template <class V>
struct V2
{
  V x;
  V y;
};
template <class V>
V2<V> operator+(V2<V> a, V2<V> b) { return {a.x + b.x, a.y + b.y}; }
template <class V>
V2<V> operator-(V2<V> a, V2<V> b) { return {a.x - b.x, a.y - b.y}; }
template <class V>
V2<V> scale(V2<V> a, V s) { return {a.x * s, a.y * s}; }
template <class V>
V dot(V2<V> a, V2<V> b) { return a.x * b.x + a.y * b.y; }
template <class V>
V cross(V2<V> a, V2<V> b) { return a.x * b.y - a.y * b.x; }
/// cross(w, v) of vec2.h: (-w v.y, w v.x).
template <class V>
V2<V> cross(V w, V2<V> v) { return {neg(w) * v.y, w * v.x}; }
template <class V>
V2<V> rotate(V2<V> v, V c, V s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

}  // namespace rows
}  // namespace detail
}  // namespace collision2d
