// The eight-lane path of the soft step's rows (soft_rows_kernel.h) on
// AVX-512 doubles: two neighbouring batches of one colour at once, lanes 0-3
// from the first and 4-7 from the second. A colour's batches share no body,
// so solving two together is solving them one after the other, and each lane
// rounds as the scalar path does (no fused multiply-adds): the same bits as
// every other path. Built with -mavx512f -mavx512dq where the compiler
// targets x86-64 (CMake sets it for this file only) and run only where the
// CPU has both (row_lanes_available).
#include "soft_rows.h"

#if defined(__AVX512F__) && defined(__AVX512DQ__)
// GCC 12's casts, inserts and extracts of AVX-512 vectors start from an
// "undefined" vector that it then warns is used uninitialised: not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop

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
constexpr int kLanes = 2 * kRowLanes;
constexpr __mmask8 kFirstHalf = 0x0F;  ///< lanes of the first batch

struct W8
{
  __m512d v;
  W8() = default;
  explicit W8(double x) : v(_mm512_set1_pd(x)) {}
  explicit W8(__m512d x) : v(x) {}
};

/// A lane mask: bit j for lane j, as AVX-512's comparisons give.
struct M8
{
  __mmask8 m;
};

inline W8 operator+(W8 a, W8 b) { return W8(_mm512_add_pd(a.v, b.v)); }
inline W8 operator-(W8 a, W8 b) { return W8(_mm512_sub_pd(a.v, b.v)); }
inline W8 operator*(W8 a, W8 b) { return W8(_mm512_mul_pd(a.v, b.v)); }
inline W8 operator/(W8 a, W8 b) { return W8(_mm512_div_pd(a.v, b.v)); }
inline M8 operator<(W8 a, W8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline M8 operator>=(W8 a, W8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GE_OQ)}; }
inline M8 operator==(W8 a, W8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_EQ_OQ)}; }
inline M8 operator!=(W8 a, W8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_NEQ_UQ)}; }
inline M8 operator&(M8 a, M8 b) { return {static_cast<__mmask8>(a.m & b.m)}; }
inline M8 operator|(M8 a, M8 b) { return {static_cast<__mmask8>(a.m | b.m)}; }
inline W8 sel(M8 m, W8 a, W8 b) { return W8(_mm512_mask_blend_pd(m.m, b.v, a.v)); }
inline W8 neg(W8 a) { return W8(_mm512_xor_pd(a.v, _mm512_set1_pd(-0.0))); }
inline W8 abs(W8 a) { return W8(_mm512_andnot_pd(_mm512_set1_pd(-0.0), a.v)); }

/// Four lanes of a batch and four of the batch after it in the colour's
/// array: the kernel names a field of the first, and the same field of the
/// second lies sizeof(Batch) bytes further on (a constant, so the address
/// costs nothing).
template <class Batch>
struct PairOps
{
  template <class T>
  static T* next(T* f)
  {
    return reinterpret_cast<T*>(reinterpret_cast<std::uintptr_t>(f) + sizeof(Batch));
  }

  W8 load(const double* f) const { return join(_mm256_load_pd(f), _mm256_load_pd(next(f))); }
  /// Four lanes and four more side by side.
  static W8 join(__m256d first, __m256d second)
  {
    return W8(_mm512_insertf64x4(_mm512_castpd256_pd512(first), second, 1));
  }
  void store(double* f, W8 v) const
  {
    _mm256_store_pd(f, _mm512_castpd512_pd256(v.v));
    _mm256_store_pd(next(f), _mm512_extractf64x4_pd(v.v, 1));
  }
  M8 flag(const std::uint8_t* f) const
  {
    std::uint32_t first = 0;
    std::uint32_t second = 0;
    std::memcpy(&first, f, sizeof first);
    std::memcpy(&second, next(f), sizeof second);
    const std::uint64_t bytes = first | static_cast<std::uint64_t>(second) << 32;
    const __m512i lanes = _mm512_cvtepu8_epi64(_mm_cvtsi64_si128(static_cast<long long>(bytes)));
    return {_mm512_test_epi64_mask(lanes, lanes)};
  }
  void set_flag(std::uint8_t* f, M8 where, M8 value) const
  {
    rows::write_flag_bits(f, kRowLanes, where.m & kFirstHalf, value.m & kFirstHalf);
    rows::write_flag_bits(next(f), kRowLanes, where.m >> kRowLanes, value.m >> kRowLanes);
  }
  bool any(const std::uint8_t* f) const { return rows::any_lane(f) || rows::any_lane(next(f)); }
  void gather(const std::vector<BodyVelocity>& state, const std::uint32_t* index, rows::Side<W8>& side) const
  {
    // Each batch's bodies as the four-lane path loads them, then joined.
    __m256d first[8];
    __m256d second[8];
    gather_four_bodies(state, index, first);
    gather_four_bodies(state, next(index), second);
    side.v = {join(first[0], second[0]), join(first[1], second[1])};
    side.w = join(first[2], second[2]);
    side.moved = {join(first[3], second[3]), join(first[4], second[4])};
    side.c = join(first[5], second[5]);
    side.s = join(first[6], second[6]);
  }
  void scatter(std::vector<BodyVelocity>& state, const std::uint32_t* index, const rows::Side<W8>& side) const
  {
    alignas(64) double vx[kLanes];
    alignas(64) double vy[kLanes];
    alignas(64) double w[kLanes];
    _mm512_store_pd(vx, side.v.x.v);
    _mm512_store_pd(vy, side.v.y.v);
    _mm512_store_pd(w, side.w.v);
    scatter_four_bodies(state, index, vx, vy, w);
    scatter_four_bodies(state, next(index), vx + kRowLanes, vy + kRowLanes, w + kRowLanes);
  }
};

}  // namespace

bool eight_lanes_compiled() { return true; }

template <class Batch>
void warm_start_batches_eight(Batch& first, std::vector<BodyVelocity>& velocity)
{
  rows::warm_start_rows<W8>(PairOps<Batch>{}, first, velocity);
}

template <class Batch>
void solve_batches_eight(Batch& first, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  rows::solve_rows<W8>(PairOps<Batch>{}, first, velocity, pass);
}

}  // namespace detail
}  // namespace collision2d

#else  // no AVX-512 in this build: never chosen, the four-lane path stands in

namespace collision2d
{
namespace detail
{
bool eight_lanes_compiled() { return false; }
template <class Batch>
void warm_start_batches_eight(Batch& first, std::vector<BodyVelocity>& velocity)
{
  warm_start_batch_four(first, velocity);
  warm_start_batch_four((&first)[1], velocity);
}
template <class Batch>
void solve_batches_eight(Batch& first, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  solve_batch_four(first, velocity, pass);
  solve_batch_four((&first)[1], velocity, pass);
}
}  // namespace detail
}  // namespace collision2d

#endif

namespace collision2d
{
namespace detail
{
COLLISION2D_ROW_BATCH_VERBS(warm_start_batches_eight, std::vector<BodyVelocity>&);
COLLISION2D_ROW_BATCH_VERBS(solve_batches_eight, std::vector<BodyVelocity>&, const RowPass&);
}  // namespace detail
}  // namespace collision2d
