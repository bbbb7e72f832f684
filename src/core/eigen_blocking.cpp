#include "eigen_blocking.h"

#include <cstddef>
#include <mutex>

#include <Eigen/Core>

namespace collision2d
{
namespace detail
{
namespace
{
// The sizes Eigen reads on the machine the golden hashes were pinned on.
constexpr std::ptrdiff_t kL1Bytes = 32 * 1024;
constexpr std::ptrdiff_t kL2Bytes = 1024 * 1024;
constexpr std::ptrdiff_t kL3Bytes = 32 * 1024 * 1024;
}  // namespace

void pin_eigen_blocking()
{
  static std::once_flag once;
  std::call_once(once, [] { Eigen::setCpuCacheSizes(kL1Bytes, kL2Bytes, kL3Bytes); });
}

}  // namespace detail
}  // namespace collision2d
