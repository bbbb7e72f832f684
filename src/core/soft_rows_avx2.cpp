// The four-lane path of the soft step's rows (soft_rows_kernel.h) on AVX2
// doubles. Built with -mavx2 where the compiler targets x86-64 (CMake sets
// it for this file only) and run only where the CPU has AVX2
// (row_lanes_available). No fused multiply-adds: every lane rounds as the scalar
// path does.
#include "soft_rows.h"

#if defined(__AVX2__)
#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "soft_rows_four_bodies.h"
#include "soft_rows_kernel.h"

namespace collision2d
{
namespace detail
{
namespace
{
struct W4
{
  __m256d v;
  W4() = default;
  explicit W4(double x) : v(_mm256_set1_pd(x)) {}
  explicit W4(__m256d x) : v(x) {}
};

inline W4 operator+(W4 a, W4 b) { return W4(_mm256_add_pd(a.v, b.v)); }
inline W4 operator-(W4 a, W4 b) { return W4(_mm256_sub_pd(a.v, b.v)); }
inline W4 operator*(W4 a, W4 b) { return W4(_mm256_mul_pd(a.v, b.v)); }
inline W4 operator/(W4 a, W4 b) { return W4(_mm256_div_pd(a.v, b.v)); }
// Masks are all-ones or all-zeros lanes, as the ordered comparisons give.
inline W4 operator<(W4 a, W4 b) { return W4(_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)); }
inline W4 operator>=(W4 a, W4 b) { return W4(_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)); }
inline W4 operator==(W4 a, W4 b) { return W4(_mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ)); }
inline W4 operator!=(W4 a, W4 b) { return W4(_mm256_cmp_pd(a.v, b.v, _CMP_NEQ_UQ)); }
inline W4 operator&(W4 a, W4 b) { return W4(_mm256_and_pd(a.v, b.v)); }
inline W4 operator|(W4 a, W4 b) { return W4(_mm256_or_pd(a.v, b.v)); }
inline W4 sel(W4 m, W4 a, W4 b) { return W4(_mm256_blendv_pd(b.v, a.v, m.v)); }
inline W4 neg(W4 a) { return W4(_mm256_xor_pd(a.v, _mm256_set1_pd(-0.0))); }
inline W4 abs(W4 a) { return W4(_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)); }

struct WideOps
{
  W4 load(const double* f) const { return W4(_mm256_load_pd(f)); }
  void store(double* f, W4 v) const { _mm256_store_pd(f, v.v); }
  W4 flag(const std::uint8_t* f) const
  {
    std::int32_t bytes = 0;
    std::memcpy(&bytes, f, sizeof bytes);
    const __m256i lanes = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(bytes));
    return W4(_mm256_castsi256_pd(_mm256_cmpgt_epi64(lanes, _mm256_setzero_si256())));
  }
  void set_flag(std::uint8_t* f, W4 where, W4 value) const
  {
    rows::write_flag_bits(f, kRowLanes, _mm256_movemask_pd(where.v), _mm256_movemask_pd(value.v));
  }
  bool any(const std::uint8_t* f) const { return rows::any_lane(f); }
  void gather(const std::vector<BodyVelocity>& state, const std::uint32_t* index, rows::Side<W4>& side) const
  {
    __m256d column[8];
    gather_four_bodies(state, index, column);
    side.v = {W4(column[0]), W4(column[1])};
    side.w = W4(column[2]);
    side.moved = {W4(column[3]), W4(column[4])};
    side.c = W4(column[5]);
    side.s = W4(column[6]);
  }
  void scatter(std::vector<BodyVelocity>& state, const std::uint32_t* index, const rows::Side<W4>& side) const
  {
    alignas(32) double vx[kRowLanes];
    alignas(32) double vy[kRowLanes];
    alignas(32) double w[kRowLanes];
    _mm256_store_pd(vx, side.v.x.v);
    _mm256_store_pd(vy, side.v.y.v);
    _mm256_store_pd(w, side.w.v);
    scatter_four_bodies(state, index, vx, vy, w);
  }
};

}  // namespace

bool four_lanes_compiled() { return true; }

template <class Batch>
void warm_start_batch_four(Batch& batch, std::vector<BodyVelocity>& velocity)
{
  rows::warm_start_rows<W4>(WideOps{}, batch, velocity);
}

template <class Batch>
void solve_batch_four(Batch& batch, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  rows::solve_rows<W4>(WideOps{}, batch, velocity, pass);
}

}  // namespace detail
}  // namespace collision2d

#else  // no AVX2 in this build: never chosen, the scalar path stands in

namespace collision2d
{
namespace detail
{
bool four_lanes_compiled() { return false; }
template <class Batch>
void warm_start_batch_four(Batch& batch, std::vector<BodyVelocity>& velocity)
{
  warm_start_batch_scalar(batch, kRowLanes, velocity);
}
template <class Batch>
void solve_batch_four(Batch& batch, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  solve_batch_scalar(batch, kRowLanes, velocity, pass);
}
}  // namespace detail
}  // namespace collision2d

#endif

namespace collision2d
{
namespace detail
{
COLLISION2D_ROW_BATCH_VERBS(warm_start_batch_four, std::vector<BodyVelocity>&);
COLLISION2D_ROW_BATCH_VERBS(solve_batch_four, std::vector<BodyVelocity>&, const RowPass&);
}  // namespace detail
}  // namespace collision2d
