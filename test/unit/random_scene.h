// Random mixed disk/polygon scenes for the detection tests (fixed seeds, so a
// failure reproduces).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "collision2d/body.h"

namespace collision2d
{
namespace test
{
constexpr double kTestPi = 3.141592653589793;

/// Convex polygon: 3 to 8 points at sorted random angles on an ellipse (points
/// on an ellipse in angular order are always convex).
inline std::vector<Vec2> random_convex_outline(std::mt19937& rng, double size)
{
  std::uniform_int_distribution<int> count(3, 8);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kTestPi);
  std::uniform_real_distribution<double> aspect(0.3, 1.0);
  const int k = count(rng);
  const double ry = size * aspect(rng);
  std::vector<double> angles;
  // Redraw until no two corners are nearly the same (keeps every edge and turn
  // well conditioned).
  bool well_spread = false;
  while (!well_spread)
  {
    angles.clear();
    for (int i = 0; i < k; ++i)
    {
      angles.push_back(angle(rng));
    }
    std::sort(angles.begin(), angles.end());
    well_spread = 2.0 * kTestPi - (angles.back() - angles.front()) > 0.1;
    for (int i = 1; i < k; ++i)
    {
      well_spread = well_spread && angles[i] - angles[i - 1] > 0.1;
    }
  }
  std::vector<Vec2> outline;
  for (double a : angles)
  {
    outline.push_back({size * std::cos(a), ry * std::sin(a)});
  }
  return outline;
}

/// Sizes spread over two decades (log-uniform), a few bodies ten times larger,
/// about half of them polygons at random orientations.
inline std::vector<Body> random_scene(unsigned seed, int n, Vec2 extent)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Body> bodies;
  for (int i = 0; i < n; ++i)
  {
    double size = 0.05 * std::pow(20.0, unit(rng));
    if (unit(rng) < 0.02)
    {
      size *= 10.0;
    }
    const Vec2 p{extent.x * unit(rng), extent.y * unit(rng)};
    const Vec2 v{unit(rng) - 0.5, unit(rng) - 0.5};
    if (unit(rng) < 0.5)
    {
      bodies.emplace_back(1.0 + unit(rng), size, p, v);
    }
    else
    {
      bodies.emplace_back(1.0 + unit(rng), random_convex_outline(rng, size), p, v, 2.0 * kTestPi * unit(rng));
    }
  }
  return bodies;
}

}  // namespace test
}  // namespace collision2d
