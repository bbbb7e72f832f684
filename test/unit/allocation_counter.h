// Counts every allocation of the test binary that includes this header, so a
// test can check that warmed-up code allocates nothing, and can fail one
// armed allocation, so a test can check what running out of memory leaves.
// Replacement operators new and delete cannot be inline: include this from
// exactly one file of a binary (each test_*.cpp is its own binary). GCC
// cannot tell these replacements pair malloc with free and warns at every
// inlined delete.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace collision2d
{
namespace test
{
/// Allocations made so far by this binary.
inline std::atomic<long> g_allocations{0};
/// Allocations left before the armed one throws std::bad_alloc (then it
/// disarms itself); negative: none armed.
inline std::atomic<long> g_allocations_until_failure{-1};

inline void* counted_allocation(std::size_t size, std::size_t align)
{
  ++g_allocations;
  if (g_allocations_until_failure.load(std::memory_order_relaxed) >= 0 &&
      g_allocations_until_failure.fetch_sub(1) == 0)
  {
    throw std::bad_alloc();
  }
  // Over-aligned blocks (the soft rows) need aligned_alloc, which wants a multiple of the alignment.
  const std::size_t rounded = (size + align - 1) / align * align;
  void* p = align <= alignof(std::max_align_t) ? std::malloc(size == 0 ? 1 : size)
                                               : std::aligned_alloc(align, rounded == 0 ? align : rounded);
  if (p == nullptr)
  {
    throw std::bad_alloc();
  }
  return p;
}

/// The nothrow forms, for what the library may go without (std::stable_sort's buffer).
inline void* counted_allocation_or_null(std::size_t size, std::size_t align) noexcept
{
  try
  {
    return counted_allocation(size, align);
  }
  catch (const std::bad_alloc&)
  {
    return nullptr;
  }
}
}  // namespace test
}  // namespace collision2d

void* operator new(std::size_t size) { return collision2d::test::counted_allocation(size, alignof(std::max_align_t)); }
void* operator new(std::size_t size, std::align_val_t alignment)
{
  return collision2d::test::counted_allocation(size, static_cast<std::size_t>(alignment));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
  return collision2d::test::counted_allocation_or_null(size, alignof(std::max_align_t));
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept
{
  return collision2d::test::counted_allocation_or_null(size, static_cast<std::size_t>(alignment));
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
