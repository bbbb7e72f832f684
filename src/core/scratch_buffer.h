// Internal to the core: sizing a per-frame buffer whose every element the
// caller writes again before reading it.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace collision2d
{
namespace detail
{
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

/// Makes `v` hold n elements, to be overwritten. When it must grow, the old
/// block is freed before the new one is taken, so the two are never resident
/// together and nothing stale is copied; the new block has room for twice n,
/// so a count that creeps up reallocates rarely (untouched room costs no
/// resident memory).
template <typename T, typename Allocator>
void resize_to_overwrite(std::vector<T, Allocator>& v, std::size_t n)
{
  if (n > v.capacity())
  {
    std::vector<T, Allocator>().swap(v);
    v.reserve(2 * n);
  }
  v.resize(n);
}

}  // namespace detail
}  // namespace collision2d
