// Counts every allocation of the test binary that includes this header, so a
// test can check that warmed-up code allocates nothing. Replacement operators
// new and delete cannot be inline: include this from exactly one file of a
// binary (each test_*.cpp is its own binary). GCC cannot tell these
// replacements pair malloc with free and warns at every inlined delete.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace collision2d
{
namespace test
{
/// Allocations made so far by this binary.
inline std::atomic<long> g_allocations{0};
}  // namespace test
}  // namespace collision2d

void* operator new(std::size_t size)
{
  ++collision2d::test::g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size))
  {
    return p;
  }
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
// Over-aligned blocks (the soft rows) come through these.
void* operator new(std::size_t size, std::align_val_t alignment)
{
  ++collision2d::test::g_allocations;
  const auto align = static_cast<std::size_t>(alignment);
  const std::size_t rounded = (size + align - 1) / align * align;  // aligned_alloc wants a multiple
  if (void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded))
  {
    return p;
  }
  throw std::bad_alloc();
}
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
