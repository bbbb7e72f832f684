// Internal to the core: Eigen sizes the blocks of its matrix products (and so
// the order of their sums) from the CPU's cache sizes, read at run time on
// x86-64 and assumed elsewhere. Fixed sizes make the exact solver's results
// the same bits on every machine, as the golden hashes require.
#pragma once

namespace collision2d
{
namespace detail
{
/// Sets Eigen's cache sizes once per process; call before the first product.
void pin_eigen_blocking();

}  // namespace detail
}  // namespace collision2d
