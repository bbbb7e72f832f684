// Internal to the vector paths of the soft rows (soft_rows_avx2.cpp,
// soft_rows_avx512.cpp): one batch's four bodies gathered into lanes, and
// their velocities written back. Each file builds these with its own
// instructions, so they have internal linkage: no copy built for AVX-512
// can stand in for the AVX2 file's.
#pragma once

#if defined(__AVX2__)
#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "soft_rows.h"

namespace collision2d
{
namespace detail
{
namespace
{
// gather_four_bodies' two loads of four doubles per body.
static_assert(offsetof(BodyVelocity, v) == 0 && offsetof(BodyVelocity, omega) == 2 * sizeof(double) &&
                  offsetof(BodyVelocity, moved) == 3 * sizeof(double) &&
                  offsetof(BodyVelocity, turned_cos) == 5 * sizeof(double) &&
                  offsetof(BodyVelocity, turned_sin) == 6 * sizeof(double) && sizeof(BodyVelocity) >= 8 * sizeof(double),
              "BodyVelocity's layout is what gather_four_bodies loads");

/// Rows r0..r3 of a 4x4 matrix into its columns.
inline void transpose_four(__m256d r0, __m256d r1, __m256d r2, __m256d r3, __m256d column[4])
{
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1);  // r0[0] r1[0] r0[2] r1[2]
  const __m256d t1 = _mm256_unpackhi_pd(r0, r1);  // r0[1] r1[1] r0[3] r1[3]
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3);
  const __m256d t3 = _mm256_unpackhi_pd(r2, r3);
  column[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
  column[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
  column[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
  column[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
}

/// The four bodies `index` names, each's first eight doubles as two loads of
/// four, transposed into lanes: v.x v.y omega moved.x, then moved.y cos sin
/// (and one unused).
inline void gather_four_bodies(const std::vector<BodyVelocity>& state, const std::uint32_t* index,
                               __m256d column[8])
{
  const double* b[kRowLanes];
  for (int j = 0; j < kRowLanes; ++j)
  {
    b[j] = &state[body_of(index[j])].v.x;
  }
  transpose_four(_mm256_loadu_pd(b[0]), _mm256_loadu_pd(b[1]), _mm256_loadu_pd(b[2]), _mm256_loadu_pd(b[3]),
                 column);
  transpose_four(_mm256_loadu_pd(b[0] + 4), _mm256_loadu_pd(b[1] + 4), _mm256_loadu_pd(b[2] + 4),
                 _mm256_loadu_pd(b[3] + 4), column + 4);
}

/// Writes the velocities of lanes [0, 4) of vx, vy and w back to the four
/// bodies `index` names (not to a fixed body: written_body).
inline void scatter_four_bodies(std::vector<BodyVelocity>& state, const std::uint32_t* index, const double* vx,
                                const double* vy, const double* w)
{
  BodyVelocity discard;
  for (int j = 0; j < kRowLanes; ++j)
  {
    BodyVelocity& s = written_body(state, index[j], discard);
    s.v = Vec2{vx[j], vy[j]};
    s.omega = w[j];
  }
}

}  // namespace
}  // namespace detail
}  // namespace collision2d

#endif
