// Mapping a frame buffer's pages ahead of their first write (scratch_buffer.h).
#include "scratch_buffer.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace collision2d
{
namespace detail
{
void prefault_pages(const void* begin, const void* end)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::uintptr_t kPageBytes = 4096;
  constexpr std::uintptr_t kMinPages = 4;  // fewer fault about as cheaply
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + kPageBytes - 1) & ~(kPageBytes - 1);
  const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(end) & ~(kPageBytes - 1);
  if (last >= first + kMinPages * kPageBytes)
  {
    // A refusal only leaves the faults to the writes.
    static_cast<void>(madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE));
  }
#else
  static_cast<void>(begin);
  static_cast<void>(end);
#endif
}

}  // namespace detail
}  // namespace collision2d
