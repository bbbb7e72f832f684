// The two-lane path of the soft step's rows (soft_rows_kernel.h): a batch of
// four as two halves, on SSE2 (x86-64) or NEON (aarch64) doubles. Both are
// baseline on their targets, so no compiler flag and no CPU check. No fused
// multiply-adds (the build passes -ffp-contract=off): every lane rounds as
// the scalar path does.
#include "soft_rows.h"

#if defined(__SSE2__) || (defined(__aarch64__) && defined(__ARM_NEON))
#define COLLISION2D_TWO_LANES 1
#endif

#if defined(COLLISION2D_TWO_LANES)
#if defined(__SSE2__)
#include <emmintrin.h>
#else
#include <arm_neon.h>
#endif

#include "soft_rows_kernel.h"

namespace collision2d
{
namespace detail
{
namespace
{
#if defined(__SSE2__)
/// Two doubles; a mask is a W2 of all-ones or all-zeros lanes.
struct W2
{
  __m128d v;
  W2() = default;
  explicit W2(double x) : v(_mm_set1_pd(x)) {}
  explicit W2(__m128d x) : v(x) {}
};
using M2 = W2;

inline W2 make2(double lo, double hi) { return W2(_mm_setr_pd(lo, hi)); }
inline W2 load2(const double* f) { return W2(_mm_load_pd(f)); }
inline void store2(double* f, W2 a) { _mm_store_pd(f, a.v); }
inline W2 operator+(W2 a, W2 b) { return W2(_mm_add_pd(a.v, b.v)); }
inline W2 operator-(W2 a, W2 b) { return W2(_mm_sub_pd(a.v, b.v)); }
inline W2 operator*(W2 a, W2 b) { return W2(_mm_mul_pd(a.v, b.v)); }
inline W2 operator/(W2 a, W2 b) { return W2(_mm_div_pd(a.v, b.v)); }
// Ordered < >= ==, unordered != (true for NaN), as on doubles.
inline M2 operator<(W2 a, W2 b) { return W2(_mm_cmplt_pd(a.v, b.v)); }
inline M2 operator>=(W2 a, W2 b) { return W2(_mm_cmpge_pd(a.v, b.v)); }
inline M2 operator==(W2 a, W2 b) { return W2(_mm_cmpeq_pd(a.v, b.v)); }
inline M2 operator!=(W2 a, W2 b) { return W2(_mm_cmpneq_pd(a.v, b.v)); }
inline M2 operator&(M2 a, M2 b) { return W2(_mm_and_pd(a.v, b.v)); }
inline M2 operator|(M2 a, M2 b) { return W2(_mm_or_pd(a.v, b.v)); }
// SSE2 has no blend: (m & a) | (~m & b).
inline W2 sel(M2 m, W2 a, W2 b) { return W2(_mm_or_pd(_mm_and_pd(m.v, a.v), _mm_andnot_pd(m.v, b.v))); }
inline W2 neg(W2 a) { return W2(_mm_xor_pd(a.v, _mm_set1_pd(-0.0))); }
inline W2 abs(W2 a) { return W2(_mm_andnot_pd(_mm_set1_pd(-0.0), a.v)); }
/// The mask of two flags, and a mask's lanes as bits (lane 0 the lowest).
inline M2 mask2(bool lo, bool hi) { return W2(_mm_castsi128_pd(_mm_set_epi64x(hi ? -1 : 0, lo ? -1 : 0))); }
inline int bits2(M2 m) { return _mm_movemask_pd(m.v); }
#else
struct W2
{
  float64x2_t v;
  W2() = default;
  explicit W2(double x) : v(vdupq_n_f64(x)) {}
  explicit W2(float64x2_t x) : v(x) {}
};
/// All-ones or all-zeros lanes, as NEON's comparisons give.
struct M2
{
  uint64x2_t m;
};

inline W2 make2(double lo, double hi) { return W2(vcombine_f64(vdup_n_f64(lo), vdup_n_f64(hi))); }
inline W2 load2(const double* f) { return W2(vld1q_f64(f)); }
inline void store2(double* f, W2 a) { vst1q_f64(f, a.v); }
inline W2 operator+(W2 a, W2 b) { return W2(vaddq_f64(a.v, b.v)); }
inline W2 operator-(W2 a, W2 b) { return W2(vsubq_f64(a.v, b.v)); }
inline W2 operator*(W2 a, W2 b) { return W2(vmulq_f64(a.v, b.v)); }
inline W2 operator/(W2 a, W2 b) { return W2(vdivq_f64(a.v, b.v)); }
inline M2 operator<(W2 a, W2 b) { return {vcltq_f64(a.v, b.v)}; }
inline M2 operator>=(W2 a, W2 b) { return {vcgeq_f64(a.v, b.v)}; }
inline M2 operator==(W2 a, W2 b) { return {vceqq_f64(a.v, b.v)}; }
// Not equal, true for NaN as on doubles: the complement of ==.
inline M2 operator!=(W2 a, W2 b)
{
  return {vreinterpretq_u64_u32(vmvnq_u32(vreinterpretq_u32_u64(vceqq_f64(a.v, b.v))))};
}
inline M2 operator&(M2 a, M2 b) { return {vandq_u64(a.m, b.m)}; }
inline M2 operator|(M2 a, M2 b) { return {vorrq_u64(a.m, b.m)}; }
inline W2 sel(M2 m, W2 a, W2 b) { return W2(vbslq_f64(m.m, a.v, b.v)); }
inline W2 neg(W2 a) { return W2(vnegq_f64(a.v)); }
inline W2 abs(W2 a) { return W2(vabsq_f64(a.v)); }
inline M2 mask2(bool lo, bool hi)
{
  return {vcombine_u64(vcreate_u64(lo ? ~std::uint64_t{0} : 0), vcreate_u64(hi ? ~std::uint64_t{0} : 0))};
}
inline int bits2(M2 m)
{
  return (vgetq_lane_u64(m.m, 0) != 0 ? 1 : 0) | (vgetq_lane_u64(m.m, 1) != 0 ? 2 : 0);
}
#endif

/// Lanes offset and offset + 1 of a batch (offset 0 or 2).
struct HalfOps
{
  int offset = 0;
  W2 load(const double* f) const { return load2(f + offset); }
  void store(double* f, W2 v) const { store2(f + offset, v); }
  M2 flag(const std::uint8_t* f) const { return mask2(f[offset] != 0, f[offset + 1] != 0); }
  bool any(const std::uint8_t* f) const { return rows::any_lane(f); }  // the whole batch, as the other paths
  void set_flag(std::uint8_t* f, M2 where, M2 value) const
  {
    rows::write_flag_bits(f + offset, 2, bits2(where), bits2(value));
  }
  void gather(const std::vector<BodyVelocity>& state, const std::uint32_t* index, rows::Side<W2>& side) const
  {
    const BodyVelocity& s0 = state[body_of(index[offset])];
    const BodyVelocity& s1 = state[body_of(index[offset + 1])];
    side.v = {make2(s0.v.x, s1.v.x), make2(s0.v.y, s1.v.y)};
    side.w = make2(s0.omega, s1.omega);
    side.moved = {make2(s0.moved.x, s1.moved.x), make2(s0.moved.y, s1.moved.y)};
    side.c = make2(s0.turned_cos, s1.turned_cos);
    side.s = make2(s0.turned_sin, s1.turned_sin);
  }
  void scatter(std::vector<BodyVelocity>& state, const std::uint32_t* index, const rows::Side<W2>& side) const
  {
    double vx[2], vy[2], w[2];
    store_unaligned(vx, side.v.x);
    store_unaligned(vy, side.v.y);
    store_unaligned(w, side.w);
    BodyVelocity discard;
    for (int j = 0; j < 2; ++j)
    {
      BodyVelocity& s = written_body(state, index[offset + j], discard);
      s.v = Vec2{vx[j], vy[j]};
      s.omega = w[j];
    }
  }

private:
  static void store_unaligned(double* f, W2 a)
  {
#if defined(__SSE2__)
    _mm_storeu_pd(f, a.v);
#else
    store2(f, a);
#endif
  }
};

}  // namespace

bool two_lanes_compiled() { return true; }

// A half of padding lanes only is skipped: the scalar path never runs them.
template <class Batch>
void warm_start_batch_two(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity)
{
  for (int offset = 0; offset < lanes; offset += 2)
  {
    rows::warm_start_rows<W2>(HalfOps{offset}, batch, velocity);
  }
}

template <class Batch>
void solve_batch_two(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  for (int offset = 0; offset < lanes; offset += 2)
  {
    rows::solve_rows<W2>(HalfOps{offset}, batch, velocity, pass);
  }
}

}  // namespace detail
}  // namespace collision2d

#else  // neither SSE2 nor NEON in this build: never chosen, the scalar path stands in

namespace collision2d
{
namespace detail
{
bool two_lanes_compiled() { return false; }
template <class Batch>
void warm_start_batch_two(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity)
{
  warm_start_batch_scalar(batch, lanes, velocity);
}
template <class Batch>
void solve_batch_two(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  solve_batch_scalar(batch, lanes, velocity, pass);
}
}  // namespace detail
}  // namespace collision2d

#endif

namespace collision2d
{
namespace detail
{
COLLISION2D_ROW_BATCH_VERBS(warm_start_batch_two, int, std::vector<BodyVelocity>&);
COLLISION2D_ROW_BATCH_VERBS(solve_batch_two, int, std::vector<BodyVelocity>&, const RowPass&);
}  // namespace detail
}  // namespace collision2d
