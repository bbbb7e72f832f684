// The four-lane path of the soft step's rows (soft_rows_kernel.h) on AVX2
// doubles. Built with -mavx2 where the compiler targets x86-64 (CMake sets
// it for this file only) and run only where the CPU has AVX2
// (row_lanes_available). No fused multiply-adds: every lane rounds as the scalar
// path does.
#include "soft_rows.h"

#if defined(__AVX2__)
#include <immintrin.h>

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
  void gather(const std::vector<BodyVelocity>& state, const std::uint32_t* index, rows::Side<W4>& side) const
  {
    const BodyVelocity& s0 = state[index[0]];
    const BodyVelocity& s1 = state[index[1]];
    const BodyVelocity& s2 = state[index[2]];
    const BodyVelocity& s3 = state[index[3]];
    side.v = {W4(_mm256_setr_pd(s0.v.x, s1.v.x, s2.v.x, s3.v.x)), W4(_mm256_setr_pd(s0.v.y, s1.v.y, s2.v.y, s3.v.y))};
    side.w = W4(_mm256_setr_pd(s0.omega, s1.omega, s2.omega, s3.omega));
    side.moved = {W4(_mm256_setr_pd(s0.moved.x, s1.moved.x, s2.moved.x, s3.moved.x)),
                  W4(_mm256_setr_pd(s0.moved.y, s1.moved.y, s2.moved.y, s3.moved.y))};
    side.c = W4(_mm256_setr_pd(s0.turned_cos, s1.turned_cos, s2.turned_cos, s3.turned_cos));
    side.s = W4(_mm256_setr_pd(s0.turned_sin, s1.turned_sin, s2.turned_sin, s3.turned_sin));
  }
  void scatter(std::vector<BodyVelocity>& state, const std::uint32_t* index, const rows::Side<W4>& side) const
  {
    alignas(32) double vx[kRowLanes];
    alignas(32) double vy[kRowLanes];
    alignas(32) double w[kRowLanes];
    _mm256_store_pd(vx, side.v.x.v);
    _mm256_store_pd(vy, side.v.y.v);
    _mm256_store_pd(w, side.w.v);
    for (int j = 0; j < kRowLanes; ++j)
    {
      BodyVelocity& s = state[index[j]];
      s.v = Vec2{vx[j], vy[j]};
      s.omega = w[j];
    }
  }
};

}  // namespace

bool four_lanes_compiled() { return true; }

void warm_start_batch_four(RowBatch& batch, std::vector<BodyVelocity>& velocity)
{
  rows::warm_start_rows<W4>(WideOps{}, batch, velocity);
}

void solve_batch_four(RowBatch& batch, std::vector<BodyVelocity>& velocity, const RowPass& pass)
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
void warm_start_batch_four(RowBatch& batch, std::vector<BodyVelocity>& velocity)
{
  warm_start_batch_scalar(batch, kRowLanes, velocity);
}
void solve_batch_four(RowBatch& batch, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  solve_batch_scalar(batch, kRowLanes, velocity, pass);
}
}  // namespace detail
}  // namespace collision2d

#endif
