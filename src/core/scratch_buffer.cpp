// Mapping a frame buffer's pages ahead of their first write (scratch_buffer.h).
#include "scratch_buffer.h"

#include <cstdint>
#include <new>
#include <utility>

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

void give_back_pages(void* begin, std::size_t bytes) noexcept
{
#if defined(__linux__)
  constexpr std::uintptr_t kPageBytes = 4096;
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + kPageBytes - 1) & ~(kPageBytes - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(begin) + bytes) & ~(kPageBytes - 1);
  if (bytes >= kGiveBackFrom && last > first)
  {
    // The pages read as zeros if the heap hands them out again; a refusal
    // only leaves them resident, as free() would.
    static_cast<void>(madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED));
  }
#else
  static_cast<void>(begin);
  static_cast<void>(bytes);
#endif
}

namespace
{
constexpr std::align_val_t kBlockAlignment{kFrameBlockAlignment};
}  // namespace

FrameBlock::FrameBlock(FrameBlock&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      capacity_(std::exchange(other.capacity_, 0)),
      mapped_(std::exchange(other.mapped_, 0))
{
}

FrameBlock& FrameBlock::operator=(FrameBlock&& other) noexcept
{
  if (this != &other)
  {
    release();
    data_ = std::exchange(other.data_, nullptr);
    capacity_ = std::exchange(other.capacity_, 0);
    mapped_ = std::exchange(other.mapped_, 0);
  }
  return *this;
}

FrameBlock::~FrameBlock() { release(); }

void FrameBlock::release() noexcept
{
  if (data_ != nullptr)
  {
    ::operator delete[](data_, kBlockAlignment);
  }
  data_ = nullptr;
  capacity_ = 0;
  mapped_ = 0;
}

unsigned char* FrameBlock::take(std::size_t bytes)
{
  if (bytes > capacity_)
  {
    give_back_pages(data_, capacity_);  // outgrown (release() alone keeps the pages in the heap)
    release();                          // the old block goes first: the two are never resident together
    data_ = static_cast<unsigned char*>(::operator new[](kGrowthRoom * bytes, kBlockAlignment));
    capacity_ = kGrowthRoom * bytes;
  }
  if (bytes > mapped_)
  {
    prefault_pages(data_ + mapped_, data_ + bytes);
    mapped_ = bytes;
  }
  return data_;
}

}  // namespace detail
}  // namespace collision2d
