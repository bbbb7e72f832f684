// The choice of lane path for the soft step's rows (soft_rows.h): the widest
// that is compiled in and that this CPU runs, unless a test forces one.
#include <atomic>

#include "soft_rows.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// The forced path as an int; negative: none forced.
std::atomic<int> g_forced_lanes{-1};

bool cpu_has_avx2()
{
#if defined(__x86_64__) || defined(__i386__)
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

bool cpu_has_avx512()
{
#if defined(__x86_64__) || defined(__i386__)
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  return has;
#else
  return false;
#endif
}

RowLanes widest_available()
{
  static const RowLanes widest = row_lanes_available(RowLanes::Eight)  ? RowLanes::Eight
                                 : row_lanes_available(RowLanes::Four) ? RowLanes::Four
                                 : row_lanes_available(RowLanes::Two)  ? RowLanes::Two
                                                                       : RowLanes::Scalar;
  return widest;
}
}  // namespace

bool row_lanes_available(RowLanes lanes)
{
  switch (lanes)
  {
    case RowLanes::Eight:
      // A colour's last odd batch goes on the four-lane path.
      return eight_lanes_compiled() && cpu_has_avx512() && row_lanes_available(RowLanes::Four);
    case RowLanes::Four:
      return four_lanes_compiled() && cpu_has_avx2();
    case RowLanes::Two:
      // SSE2 and NEON are baseline on x86-64 and aarch64: no CPU check.
      return two_lanes_compiled();
    case RowLanes::Scalar:
      break;
  }
  return true;
}

RowLanes row_lanes()
{
  const int forced = g_forced_lanes.load(std::memory_order_relaxed);
  return forced < 0 ? widest_available() : static_cast<RowLanes>(forced);
}

bool set_row_lanes(RowLanes lanes)
{
  if (!row_lanes_available(lanes))
  {
    return false;
  }
  g_forced_lanes.store(static_cast<int>(lanes), std::memory_order_relaxed);
  return true;
}

void reset_row_lanes() { g_forced_lanes.store(-1, std::memory_order_relaxed); }

template <class Batch>
void warm_start_batch(RowLanes path, Batch& batch, int lanes, std::vector<BodyVelocity>& velocity)
{
  switch (path)
  {
    case RowLanes::Eight:
    case RowLanes::Four:
      return warm_start_batch_four(batch, velocity);
    case RowLanes::Two:
      return warm_start_batch_two(batch, lanes, velocity);
    case RowLanes::Scalar:
      break;
  }
  warm_start_batch_scalar(batch, lanes, velocity);
}

template <class Batch>
void solve_batch(RowLanes path, Batch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  switch (path)
  {
    case RowLanes::Eight:
    case RowLanes::Four:
      return solve_batch_four(batch, velocity, pass);
    case RowLanes::Two:
      return solve_batch_two(batch, lanes, velocity, pass);
    case RowLanes::Scalar:
      break;
  }
  solve_batch_scalar(batch, lanes, velocity, pass);
}

template void warm_start_batch(RowLanes, RowBatch&, int, std::vector<BodyVelocity>&);
template void warm_start_batch(RowLanes, RowSingle&, int, std::vector<BodyVelocity>&);
template void solve_batch(RowLanes, RowBatch&, int, std::vector<BodyVelocity>&, const RowPass&);
template void solve_batch(RowLanes, RowSingle&, int, std::vector<BodyVelocity>&, const RowPass&);

}  // namespace detail
}  // namespace collision2d
