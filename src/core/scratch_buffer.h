// Internal to the core: sizing a per-frame buffer whose every element the
// caller writes again before reading it.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

#include "worker_pool.h"

namespace collision2d
{
namespace detail
{
/// A frame buffer that must grow takes room for this many times what it was
/// asked for: a count that creeps up reallocates rarely, and room never
/// written costs no resident memory.
constexpr std::size_t kGrowthRoom = 2;

/// An outgrown block of at least this many bytes gives its pages back to
/// the system before it is freed (give_back_pages, free_outgrown).
constexpr std::size_t kGiveBackFrom = std::size_t{256} * 1024;

/// Gives the whole pages inside [begin, begin + bytes) back to the system,
/// for a block about to be freed whose contents are dead: the heap keeps a
/// freed block resident for reuse, and one that a buffer growing with its
/// scene has outgrown is seldom reused whole. Blocks below kGiveBackFrom
/// are left to the heap (scratch_buffer.cpp).
void give_back_pages(void* begin, std::size_t bytes) noexcept;

/// An allocator whose vector leaves new elements as the memory holds them
/// when it grows by resize(): for the per-frame buffers that a stage writes
/// in full before any reads them. Their pages are then first touched by
/// that stage's writes, on the workers that share it, and not by a
/// value-initialising pass on the calling thread first.
template <typename T>
struct FrameAllocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    using other = FrameAllocator<U>;
  };
  FrameAllocator() = default;
  template <typename U>
  FrameAllocator(const FrameAllocator<U>& /*other*/) noexcept
  {
  }
  /// resize()'s new elements: left as they are (plain data only). Copies
  /// and other constructions go through std::allocator_traits' placement new.
  template <typename U>
  void construct(U* /*p*/) noexcept
  {
    static_assert(std::is_trivially_copyable<U>::value && std::is_trivially_destructible<U>::value,
                  "a frame buffer holds plain data");
  }
};

/// A per-frame buffer: see FrameAllocator.
template <typename T>
using FrameBuffer = std::vector<T, FrameAllocator<T>>;

/// Maps the whole pages of [begin, end) writable in one call, where the
/// caller is about to write all of it: the kernel's fault on each page's
/// first write costs more than the same work in one request. Where the
/// kernel cannot (before Linux 5.14, another system), nothing happens and
/// the writes fault as before.
void prefault_pages(const void* begin, const void* end);  // scratch_buffer.cpp

/// Frees the block `v` has outgrown, whose contents are dead, its pages
/// given back first. Only growth gives pages back: a block freed with its
/// owner (a World copied and dropped) stays in the heap for the next one.
template <typename T, typename Allocator>
void free_outgrown(std::vector<T, Allocator>& v)
{
  give_back_pages(v.data(), v.capacity() * sizeof(T));
  std::vector<T, Allocator>().swap(v);
}

/// Room for n elements in `v`, whose contents are dead: an outgrown block is
/// freed first (free_outgrown), and the new one holds exactly n.
template <typename T, typename Allocator>
void reserve_to_overwrite(std::vector<T, Allocator>& v, std::size_t n)
{
  if (n > v.capacity())
  {
    free_outgrown(v);
    v.reserve(n);
  }
}

/// Makes `v` hold n elements, to be overwritten. When it must grow, the old
/// block is freed before the new one is taken, so the two are never resident
/// together and nothing stale is copied; the new block has room for kGrowthRoom n,
/// so a count that creeps up reallocates rarely (untouched room costs no
/// resident memory). The pages the caller is about to write for the first
/// time are mapped in one request (prefault_pages).
template <typename T, typename Allocator>
void resize_to_overwrite(std::vector<T, Allocator>& v, std::size_t n)
{
  std::size_t written = v.size();  // these elements' pages are mapped already
  if (n > v.capacity())
  {
    free_outgrown(v);
    v.reserve(kGrowthRoom * n);
    written = 0;
  }
  if (n > written)
  {
    prefault_pages(v.data() + written, v.data() + n);
  }
  v.resize(n);
}

/// One block of memory that per-frame buffers whose lives never overlap
/// take in turn (the pair stage's buffers, dead once the bodies are
/// prepared after detection, then the soft step's rows): resident once, at
/// the larger one's size, not at their sum. Each user places its FrameSpan in the block
/// again before each use; a block that must grow frees the old one first,
/// which leaves the other users' spans pointing at freed memory, so they
/// must be dead by then. A copy starts empty (its users place their spans
/// again before they read them), so a copied World does not copy scratch.
class FrameBlock
{
public:
  FrameBlock() = default;
  FrameBlock(const FrameBlock& /*other*/) {}
  FrameBlock& operator=(const FrameBlock& /*other*/) { return *this; }
  FrameBlock(FrameBlock&& other) noexcept;
  FrameBlock& operator=(FrameBlock&& other) noexcept;
  ~FrameBlock();
  /// At least `bytes` bytes, aligned for any frame buffer; the bytes held
  /// before stay where the block does not grow. As resize_to_overwrite:
  /// room for kGrowthRoom `bytes` when it grows, and the pages not yet written
  /// mapped in one request (prefault_pages).
  unsigned char* take(std::size_t bytes);
  std::size_t capacity() const { return capacity_; }

private:
  void release() noexcept;
  unsigned char* data_ = nullptr;
  std::size_t capacity_ = 0;
  std::size_t mapped_ = 0;  ///< bytes from the start already mapped
};

/// n plain T in a FrameBlock, from `at` (see FrameBlock: placed again
/// before each use; a copy is empty).
template <typename T>
class FrameSpan
{
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
                "a frame span holds plain data");

public:
  FrameSpan() = default;
  FrameSpan(const FrameSpan& /*other*/) {}
  FrameSpan& operator=(const FrameSpan& /*other*/)
  {
    clear();
    return *this;
  }
  FrameSpan(FrameSpan&& other) noexcept = default;
  FrameSpan& operator=(FrameSpan&& other) noexcept = default;
  ~FrameSpan() = default;

  /// Holds n elements from `at` (aligned for T), to be overwritten.
  void place(unsigned char* at, std::size_t n)
  {
    data_ = reinterpret_cast<T*>(at);
    size_ = n;
  }
  void clear()
  {
    data_ = nullptr;
    size_ = 0;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  T& operator[](std::size_t k) { return data_[k]; }
  const T& operator[](std::size_t k) const { return data_[k]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }

private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

/// A FrameBlock's alignment: a cache line, more than any frame buffer's type asks.
constexpr std::size_t kFrameBlockAlignment = 64;

/// A span and how many elements it is to hold, for place_together.
template <typename T>
struct SpanPart
{
  FrameSpan<T>& span;
  std::size_t count;
};
template <typename T>
SpanPart<T> part(FrameSpan<T>& span, std::size_t count)
{
  return SpanPart<T>{span, count};
}

/// Whether the types come from the widest alignment down, the first no
/// wider than a FrameBlock's: then spans placed end to end all start aligned.
template <typename... T>
constexpr bool widest_first()
{
  constexpr std::size_t alignments[] = {alignof(T)...};
  for (std::size_t k = 1; k < sizeof...(T); ++k)
  {
    if (alignments[k] > alignments[k - 1])
    {
      return false;
    }
  }
  return alignments[0] <= kFrameBlockAlignment;
}

/// Places the spans one after another in `block`, in one taking (a second
/// could move the block under the spans placed before it).
template <typename... T>
void place_together(FrameBlock& block, SpanPart<T>... parts)
{
  static_assert(widest_first<T...>(), "spans listed from the widest alignment down");
  unsigned char* at = block.take(((parts.count * sizeof(T)) + ...));
  ((parts.span.place(at, parts.count), at += parts.count * sizeof(T)), ...);
}

/// Room for n elements in `list` without changing what it holds; one that
/// must grow takes room for kGrowthRoom n, so a count that creeps up reallocates
/// rarely. For a change that must not run out of memory halfway: room
/// first, then the change.
template <typename T, typename Allocator>
void make_room(std::vector<T, Allocator>& list, std::size_t n)
{
  if (list.capacity() < n)
  {
    list.reserve(kGrowthRoom * n);
  }
}

/// Maps the pages of [begin, end), storage allocated but not yet holding
/// objects (prefault_pages), then writes a byte to each 4 kB page, shared
/// among the workers. A vector that grows by resize() value-initialises its
/// new elements on the calling thread, and the first write to each page is
/// most of that cost even once it is mapped (on a virtual machine, the host
/// backs the page then); this spreads those writes over every worker before
/// the resize.
template <typename T>
void touch_pages_first(WorkerPool& workers, T* begin, T* end)
{
  prefault_pages(begin, end);
  constexpr std::size_t kPageBytes = 4096;
  constexpr std::size_t kMinSharedPages = 16;  // a few pages fault on the calling thread, as resize() would
  const std::size_t bytes = static_cast<std::size_t>(end - begin) * sizeof(T);
  if (workers.workers() == 1 || bytes == 0)
  {
    return;
  }
  auto* first_byte = reinterpret_cast<unsigned char*>(begin);
  workers.parallel_for((bytes + kPageBytes - 1) / kPageBytes, kMinSharedPages,
                       [&](std::size_t first, std::size_t last) {
                         for (std::size_t page = first; page < last; ++page)
                         {
                           first_byte[page * kPageBytes] = 0;
                         }
                       });
}

}  // namespace detail
}  // namespace collision2d
