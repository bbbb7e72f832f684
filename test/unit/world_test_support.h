// Helpers shared by the World tests: measurements taken while stepping.
#pragma once

#include <algorithm>
#include <limits>

#include "collision2d/world.h"

namespace collision2d
{
namespace test
{
/// Steps `world` one frame at a time until body `id`, having bounced (moved
/// up), starts to fall again, and returns the highest centre height it reached
/// on that first rebound; -infinity if it did not bounce within max_frames.
inline double first_rebound_apex(World& world, BodyId id, int max_frames)
{
  double apex = -std::numeric_limits<double>::infinity();
  bool bounced = false;
  for (int f = 0; f < max_frames; ++f)
  {
    world.step();
    const Body& b = world.body(id);
    bounced = bounced || b.velocity().y > 0.0;
    if (bounced)
    {
      apex = std::max(apex, b.position().y);
      if (b.velocity().y < 0.0)
      {
        break;  // past the first apex
      }
    }
  }
  return apex;
}

}  // namespace test
}  // namespace collision2d
