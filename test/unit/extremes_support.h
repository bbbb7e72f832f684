// Helpers shared by the test_extremes_* suites: sizes that shrink under the
// sanitizer build (always announced, never silent), finiteness checks over
// bodies and worlds, the process's peak memory, and one-line figure printing.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace test
{
/// True when scripts/sanitize.sh runs the tests (it sets this variable).
inline bool sanitizer_build()
{
  const char* flag = std::getenv("COLLISION2D_SANITIZER_BUILD");
  return flag != nullptr && std::string(flag) != "0" && !std::string(flag).empty();
}

/// `full` normally; `reduced` under the sanitizer build, printed so a reader
/// of the log knows the test ran smaller.
inline long sized(long full, long reduced, const char* what)
{
  if (!sanitizer_build())
  {
    return full;
  }
  std::printf("[sanitizer build] %s reduced from %ld to %ld\n", what, full, reduced);
  return reduced;
}

/// Prints one measured figure next to the bound the test holds it to.
inline void print_figure(const std::string& what, double measured, double bound)
{
  std::printf("  %-58s %12.4g  (bound %.3g)\n", what.c_str(), measured, bound);
}

inline bool is_finite_body(const Body& b)
{
  return non_finite_state_field(b) == nullptr;
}

inline bool all_finite(const std::vector<Body>& bodies)
{
  for (const Body& b : bodies)
  {
    if (!is_finite_body(b))
    {
      return false;
    }
  }
  return true;
}

inline bool all_finite(const World& world)
{
  for (BodyId id : world.body_ids())
  {
    if (!is_finite_body(world.body(id)))
    {
      return false;
    }
  }
  return true;
}

/// Peak resident set size of this process (VmHWM, kB); -1 when unreadable.
inline long peak_rss_kib()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == "VmHWM:")
    {
      long kib = -1;
      status >> kib;
      return kib;
    }
    std::getline(status, key);
  }
  return -1;
}

}  // namespace test
}  // namespace collision2d
