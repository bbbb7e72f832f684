// Internal to the core: sizing a per-frame buffer whose every element the
// caller writes again before reading it.
#pragma once

#include <cstddef>
#include <vector>

namespace collision2d
{
namespace detail
{
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
