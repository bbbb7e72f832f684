// Internal to soft_rows*.cpp: the soft step's verbs on a batch of two-point
// or of one-point manifolds, written once for a lane type V: double (one
// lane, the scalar path), a two-wide vector (soft_rows_lanes2.cpp), a
// four-wide one (soft_rows_avx2.cpp) or an eight-wide one over two batches
// (soft_rows_avx512.cpp). Every branch of the point verbs
// (contact_kernel_soft.cpp, contact_kernel.cpp) is computed and selected, in
// every type, so the vector paths have exactly the scalar path's bits. The
// lane type provides + - * /, comparisons giving a mask M, mask and/or,
// sel(mask, if_true, if_false), neg, abs, and Ops<V> to load, store, gather
// and scatter, to read a batch's byte flags as a mask (flag), to write them
// where a mask is set (set_flag) and to ask whether any is set (any).
#pragma once

#include <cstdint>
#include <vector>

#include "soft_rows.h"
#include "soft_rows_math.h"

namespace collision2d
{
namespace detail
{
namespace rows
{
/// One side of every lane's manifold: a body's velocity and pose change.
template <class V>
struct Side
{
  V2<V> v;
  V w;
  V2<V> moved;
  V c;
  V s;
};

/// A lane's two bodies, loaded once per pass, and its fixed data, read from
/// the batch where used: the passes never write it, and a copy would not fit
/// in the registers beside the bodies (it went through the stack).
template <class V, class Ops, class Batch>
struct Lane
{
  const Ops& ops;
  const Batch& r;
  Side<V> a;
  Side<V> b;
  V2<V> n() const { return {ops.load(r.nx), ops.load(r.ny)}; }
  V2<V> t() const { return {neg(ops.load(r.ny)), ops.load(r.nx)}; }  // perp(n), exactly the prepared tangent
  V2<V> ra1() const { return {ops.load(r.point[0].ra_x), ops.load(r.point[0].ra_y)}; }
  V2<V> rb1() const { return {ops.load(r.point[0].rb_x), ops.load(r.point[0].rb_y)}; }
  V2<V> ra2() const { return {ops.load(r.point[1].ra_x), ops.load(r.point[1].ra_y)}; }  // two-point batches only
  V2<V> rb2() const { return {ops.load(r.point[1].rb_x), ops.load(r.point[1].rb_y)}; }
  V inv_ma() const { return ops.load(r.inv_mass_a); }
  V inv_mb() const { return ops.load(r.inv_mass_b); }
  V inv_ia() const { return ops.load(r.inv_inertia_a); }
  V inv_ib() const { return ops.load(r.inv_inertia_b); }
};

/// The lanes' bodies, gathered once per pass from a batch of either kind.
template <class V, class Ops, class Batch>
Lane<V, Ops, Batch> load_lane(const Ops& ops, const Batch& r, const std::vector<BodyVelocity>& state)
{
  Lane<V, Ops, Batch> l{ops, r, {}, {}};
  ops.gather(state, r.a, l.a);
  ops.gather(state, r.b, l.b);
  return l;
}

/// relative_velocity_at: b's velocity at r_b less a's at r_a.
template <class V, class L>
V2<V> relative_velocity(const L& l, V2<V> ra, V2<V> rb)
{
  return ((l.b.v + cross(l.b.w, rb)) - l.a.v) - cross(l.a.w, ra);
}

/// apply_impulse_at: p on b, -p on a; a body with no inverse mass is untouched.
template <class V, class L>
__attribute__((always_inline)) inline void apply(L& l, V2<V> ra, V2<V> rb, V2<V> p)
{
  const V zero = V(0.0);
  const auto moves_a = l.inv_ma() != zero;
  const auto moves_b = l.inv_mb() != zero;
  const V2<V> va = l.a.v - scale(p, l.inv_ma());
  const V wa = l.a.w - l.inv_ia() * cross(ra, p);
  const V2<V> vb = l.b.v + scale(p, l.inv_mb());
  const V wb = l.b.w + l.inv_ib() * cross(rb, p);
  l.a.v = {sel(moves_a, va.x, l.a.v.x), sel(moves_a, va.y, l.a.v.y)};
  l.a.w = sel(moves_a, wa, l.a.w);
  l.b.v = {sel(moves_b, vb.x, l.b.v.x), sel(moves_b, vb.y, l.b.v.y)};
  l.b.w = sel(moves_b, wb, l.b.w);
}

/// apply on the lanes where `where` is set; the others keep their velocities.
template <class V, class M, class L>
__attribute__((always_inline)) inline void apply_where(L& l, M where, V2<V> ra, V2<V> rb, V2<V> p)
{
  auto pushed = l;
  apply(pushed, ra, rb, p);
  l.a.v = {sel(where, pushed.a.v.x, l.a.v.x), sel(where, pushed.a.v.y, l.a.v.y)};
  l.a.w = sel(where, pushed.a.w, l.a.w);
  l.b.v = {sel(where, pushed.b.v.x, l.b.v.x), sel(where, pushed.b.v.y, l.b.v.y)};
  l.b.w = sel(where, pushed.b.w, l.b.w);
}

/// The pose change between a point's anchors since prepare (m): the common
/// part of a point's gap and slip (separation_at, slip_at).
template <class V, class L>
V2<V> anchor_offset(const L& l, V2<V> ra, V2<V> rb)
{
  return ((l.b.moved - l.a.moved) + rotate(rb, l.b.c, l.b.s)) - rotate(ra, l.a.c, l.a.s);
}

template <class V, class Ops, class L>
__attribute__((always_inline)) inline void warm_start_point(const Ops& ops, L& l, V2<V> ra, V2<V> rb,
                                                           RowPoint& point)
{
  const V ln = ops.load(point.normal);
  const V lt = ops.load(point.tangent);
  const V zero = V(0.0);
  apply_where(l, (ln != zero) | (lt != zero), ra, rb, scale(l.n(), ln) + scale(l.t(), lt));
}

template <class V, class Ops, class Batch>
void warm_start_rows(const Ops& ops, Batch& r, std::vector<BodyVelocity>& state)
{
  auto l = load_lane<V>(ops, r, state);
  warm_start_point(ops, l, l.ra1(), l.rb1(), r.point[0]);
  if constexpr (sizeof(r.point) / sizeof(r.point[0]) == 2)
  {
    warm_start_point(ops, l, l.ra2(), l.rb2(), r.point[1]);
  }
  ops.scatter(state, r.a, l.a);
  ops.scatter(state, r.b, l.b);
}

/// soft_terms: a speculative gap may close within the substep; an overlap is
/// pushed out through the softness (biased pass only), at most max_push.
template <class V>
void soft_terms(V s, V rate, V mass_scale, const RowPass& pass, V& bias, V& scale_out)
{
  const V zero = V(0.0);
  const auto open = zero < s;
  const V push = vmax((mass_scale * rate) * s, neg(V(pass.max_push)));
  const V closed_bias = pass.use_bias ? push : zero;
  const V closed_scale = pass.use_bias ? mass_scale : V(1.0);
  bias = sel(open, s * V(pass.inv_h), closed_bias);
  scale_out = sel(open, V(1.0), closed_scale);
}

/// solve_lcp2: the 2x2 normal LCP by its four cases, all computed.
template <class V>
void lcp2(V k11, V k12, V k22, V q1, V q2, V& y1, V& y2)
{
  const V zero = V(0.0);
  const V det = k11 * k22 - k12 * k12;
  const V both1 = (k12 * q2 - k22 * q1) / det;
  const V both2 = (k12 * q1 - k11 * q2) / det;
  const auto both = (both1 >= zero) & (both2 >= zero);
  const V first = vmax(zero, neg(q1) / k11);
  const auto first_only = (k12 * first + q2) >= zero;
  const V second_raw = vmax(zero, neg(q2) / k22);
  const V second = sel((k12 * second_raw + q1) >= zero, second_raw, zero);
  y1 = sel(both, both1, sel(first_only, first, zero));
  y2 = sel(both, both2, sel(first_only, zero, second));
}

/// set_soft_impulse: the new accumulated normal impulse and its change applied.
/// Always inlined, as apply: left out of line, its lanes went through the stack.
template <class V, class Ops, class L>
__attribute__((always_inline)) inline void set_normal(const Ops& ops, L& l, V2<V> ra, V2<V> rb, RowPoint& point,
                                                      V total)
{
  const V applied = total - ops.load(point.normal);
  ops.store(point.normal, total);
  apply(l, ra, rb, scale(l.n(), applied));
}

/// The manifold's two normals as one block (solve_soft_normal_block).
template <class V, class Ops, class L>
void solve_normals(const Ops& ops, L& l, RowBatch& r, const RowPass& pass, V s1, V s2)
{
  const V rate = ops.load(r.bias_rate);
  const V mass_scale = ops.load(r.mass_scale);
  V bias1, bias2, scale1, scale2;
  soft_terms(s1, rate, mass_scale, pass, bias1, scale1);
  soft_terms(s2, rate, mass_scale, pass, bias2, scale2);
  const V k11 = ops.load(r.k11);
  const V k12 = ops.load(r.k12);
  const V k22 = ops.load(r.k22);
  const V x1 = ops.load(r.point[0].normal);
  const V x2 = ops.load(r.point[1].normal);
  // The relax pass's scales are exactly 1, and x / 1 is x: no division there.
  const V speed1 = pass.use_bias ? bias1 / scale1 : bias1;
  const V speed2 = pass.use_bias ? bias2 / scale2 : bias2;
  const V q1 = (dot(relative_velocity(l, l.ra1(), l.rb1()), l.n()) + speed1) - (k11 * x1 + k12 * x2);
  const V q2 = (dot(relative_velocity(l, l.ra2(), l.rb2()), l.n()) + speed2) - (k12 * x1 + k22 * x2);
  V y1, y2;
  lcp2(k11, k12, k22, q1, q2, y1, y2);
  set_normal(ops, l, l.ra1(), l.rb1(), r.point[0], scale1 * y1);
  set_normal(ops, l, l.ra2(), l.rb2(), r.point[1], scale2 * y2);
}

/// Whether any of a batch's kRowLanes byte flags is set (the lane types'
/// Ops::any over one batch).
inline bool any_lane(const std::uint8_t* f)
{
  for (int j = 0; j < kRowLanes; ++j)
  {
    if (f[j] != 0)
    {
      return true;
    }
  }
  return false;
}

/// Whether friction acts in any lane the Ops reads: a frictionless batch
/// skips its friction rows, which would leave every lane as it is.
template <class Ops, class Batch>
bool any_rough(const Ops& ops, const Batch& r)
{
  return ops.any(r.flags.rough);
}

/// Coulomb's cone on the `needed` tangential impulse (coulomb): its first
/// point's sliding flag set, the change from `old_total` applied where the
/// lane's friction acts. Returns the clamped total.
template <class V, class Ops, class Batch, class L>
V clamp_friction(const Ops& ops, L& l, Batch& r, V2<V> ra, V2<V> rb, V needed, V normal, V old_total)
{
  const V cone = sel(ops.flag(r.flags.kinetic[0]), ops.load(r.mu_k), ops.load(r.mu_s));
  const V limit = cone * normal;
  const auto rough = ops.flag(r.flags.rough);
  ops.set_flag(r.flags.sliding[0], rough, limit < abs(needed));
  const V total = vmax(neg(limit), vmin(limit, needed));
  apply_where(l, rough, ra, rb, scale(l.t(), total - old_total));
  return total;
}

/// The manifold's friction as one row at its midpoint (solve_friction_pair),
/// pulled back toward the sticking anchors by `pull` (m/s).
template <class V, class Ops, class L>
void solve_friction(const Ops& ops, L& l, RowBatch& r, V pull)
{
  const V zero = V(0.0);
  const V half = V(0.5);
  const V2<V> ra = scale(l.ra1() + l.ra2(), half);
  const V2<V> rb = scale(l.rb1() + l.rb2(), half);
  const V slip = dot(relative_velocity(l, ra, rb), l.t());
  const V vt = sel(pull == zero, slip, slip + pull);
  const V n1 = ops.load(r.point[0].normal);
  const V normal_sum = n1 + ops.load(r.point[1].normal);
  const V old_total = ops.load(r.point[0].tangent) + ops.load(r.point[1].tangent);
  const V needed = old_total - vt * ops.load(r.pair_tangent_mass);
  const auto rough = ops.flag(r.flags.rough);
  const V total = clamp_friction(ops, l, r, ra, rb, needed, normal_sum, old_total);
  ops.set_flag(r.flags.sliding[1], rough, ops.flag(r.flags.sliding[0]));
  const V share = sel(zero < normal_sum, n1 / normal_sum, half);
  const V first = share * total;
  ops.store(r.point[0].tangent, sel(rough, first, ops.load(r.point[0].tangent)));
  ops.store(r.point[1].tangent, sel(rough, total - first, ops.load(r.point[1].tangent)));
}

/// A point's slip since it stuck (anchor_drift): 0 once it has slid (`kinetic`, its batch's flags).
template <class V, class Ops, class L>
V point_drift(const Ops& ops, const L& l, const RowPoint& point, const std::uint8_t* kinetic, V2<V> d,
              V2<V> ra, V2<V> rb)
{
  const V slip = dot(d - (rb - ra), l.t());
  return sel(ops.flag(kinetic), V(0.0), ops.load(point.anchor) + slip);
}

/// The biased pass's pull back to the anchors (anchor_pull): `drift` at the
/// contact's rate, capped at max_push.
template <class V, class Ops, class Batch>
V capped_pull(const Ops& ops, const Batch& r, V drift, const RowPass& pass)
{
  const V pull = (ops.load(r.mass_scale) * ops.load(r.bias_rate)) * drift;
  const V max_push = V(pass.max_push);
  return vmax(neg(max_push), vmin(max_push, pull));
}

/// The anchor pull of a two-point manifold: the mean slip of its points.
template <class V, class Ops, class L>
V anchor_pull(const Ops& ops, const L& l, const RowBatch& r, V2<V> d1, V2<V> d2, const RowPass& pass)
{
  const V drift1 = point_drift(ops, l, r.point[0], r.flags.kinetic[0], d1, l.ra1(), l.rb1());
  const V drift2 = point_drift(ops, l, r.point[1], r.flags.kinetic[1], d2, l.ra2(), l.rb2());
  return capped_pull(ops, r, V(0.5) * (drift1 + drift2), pass);
}

template <class V, class Ops>
void solve_rows(const Ops& ops, RowBatch& r, std::vector<BodyVelocity>& state, const RowPass& pass)
{
  auto l = load_lane<V>(ops, r, state);
  const V2<V> d1 = anchor_offset(l, l.ra1(), l.rb1());
  const V2<V> d2 = anchor_offset(l, l.ra2(), l.rb2());
  solve_normals(ops, l, r, pass, ops.load(r.point[0].base) + dot(d1, l.n()), ops.load(r.point[1].base) + dot(d2, l.n()));
  if (any_rough(ops, r))
  {
    const V pull = pass.use_bias ? anchor_pull(ops, l, r, d1, d2, pass) : V(0.0);
    solve_friction(ops, l, r, pull);
  }
  ops.scatter(state, r.a, l.a);
  ops.scatter(state, r.b, l.b);
}

/// A one-point manifold's normal (solve_soft_normal) at gap s.
template <class V, class Ops, class L>
void solve_single_normal(const Ops& ops, L& l, RowSingle& r, const RowPass& pass, V s)
{
  V bias, mass_scale;
  soft_terms(s, ops.load(r.bias_rate), ops.load(r.mass_scale), pass, bias, mass_scale);
  const V vn = dot(relative_velocity(l, l.ra1(), l.rb1()), l.n());
  // The relax pass's scale is exactly 1, and x / 1 is x: no division there.
  const V speed = pass.use_bias ? bias / mass_scale : bias;
  const V rigid = ops.load(r.point[0].normal) - (vn + speed) * ops.load(r.normal_mass);
  set_normal(ops, l, l.ra1(), l.rb1(), r.point[0], mass_scale * vmax(V(0.0), rigid));
}

/// A one-point manifold's friction (solve_friction), pulled back toward its
/// anchor by `pull` (m/s).
template <class V, class Ops, class L>
void solve_single_friction(const Ops& ops, L& l, RowSingle& r, V pull)
{
  const V slip = dot(relative_velocity(l, l.ra1(), l.rb1()), l.t());
  const V vt = sel(pull == V(0.0), slip, slip + pull);
  const V old = ops.load(r.point[0].tangent);
  const V total = clamp_friction(ops, l, r, l.ra1(), l.rb1(), old - vt * ops.load(r.tangent_mass),
                                 ops.load(r.point[0].normal), old);
  ops.store(r.point[0].tangent, sel(ops.flag(r.flags.rough), total, old));
}

template <class V, class Ops>
void solve_rows(const Ops& ops, RowSingle& r, std::vector<BodyVelocity>& state, const RowPass& pass)
{
  auto l = load_lane<V>(ops, r, state);
  const V2<V> d = anchor_offset(l, l.ra1(), l.rb1());
  solve_single_normal(ops, l, r, pass, ops.load(r.point[0].base) + dot(d, l.n()));
  if (any_rough(ops, r))
  {
    // The relax pass has no pull, and no drift to compute.
    const V pull =
        pass.use_bias ? capped_pull(ops, r, point_drift(ops, l, r.point[0], r.flags.kinetic[0], d, l.ra1(), l.rb1()), pass)
                      : V(0.0);
    solve_single_friction(ops, l, r, pull);
  }
  ops.scatter(state, r.a, l.a);
  ops.scatter(state, r.b, l.b);
}

}  // namespace rows
}  // namespace detail
}  // namespace collision2d
