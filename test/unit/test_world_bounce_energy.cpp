// Restitution makes no energy. In a closed box of bodies with no kinematic
// body, e <= 1 and friction, the bodies' kinetic plus potential energy can
// only fall from frame to frame: this recomputes it from the bodies after
// every frame. The worlds are random jumbles of disks, boxes and polygons of
// 0.1 to 100 kg, dropped in a walled box in exact mode; in the two below,
// Newton's rule on a jammed chain of bodies had a fixed point that raised
// the energy by 731 J and 152 J in one frame (before restitution checked
// the energy it gives back, world_soft_bounce_drop.cpp). Other worlds still
// gain energy in exact mode where overlaps are pushed out: not checked here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/world.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
using test::mechanical_energy;

constexpr double kGravity = 9.81;  // m/s^2, WorldSettings' default

/// Uniform in [0, 1) from the engine's raw output: the same on every
/// standard library (<random>'s distributions are not).
struct Draw
{
  std::mt19937_64 rng;
  double operator()() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
  int below(int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); }
};

Material random_material(Draw& u)
{
  Material m;
  m.restitution = u() < 0.3 ? 0.0 : u();
  m.static_friction = u();
  m.kinetic_friction = m.static_friction * u();
  return m;
}

Body random_body(Draw& u, int i)
{
  const Vec2 at{-7.0 + 1.2 * (i % 12) + 0.1 * u(), 1.0 + 1.2 * (i / 12) + 0.1 * u()};
  const Vec2 v{4.0 * (u() - 0.5), 4.0 * (u() - 0.5)};
  const double mass = std::exp(std::log(0.1) + u() * std::log(1000.0));  // 0.1 to 100 kg
  const int kind = u.below(3);
  if (kind == 0)
  {
    const double radius = 0.2 + 0.3 * u();
    return Body(mass, radius, at, v);
  }
  if (kind == 1)
  {
    const double width = 0.3 + 0.7 * u();
    const double height = 0.3 + 0.7 * u();
    const double theta = u();
    return scenes::make_box(mass, width, height, at, theta, v);
  }
  const int corners = 3 + u.below(5);
  const double radius = 0.25 + 0.3 * u();
  std::vector<Vec2> outline;
  for (int j = 0; j < corners; ++j)
  {
    const double angle = 2.0 * M_PI * j / corners;
    outline.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  const double theta = u();
  return Body(mass, outline, at, v, theta);
}

/// World `seed`: a ground, two walls and 20 to 40 random bodies, 1, 2, 4 or
/// 8 substeps, exact mode, sleeping off.
World jumble(std::uint64_t seed)
{
  Draw u{std::mt19937_64(seed)};
  WorldSettings s;
  s.sleeping = Toggle::Off;
  s.substeps = 1 << u.below(4);
  s.solver_mode = SolverMode::Exact;
  World world(s);
  world.add_body(scenes::make_static_box(20.0, 1.0, {0.0, -0.5}), random_material(u));
  world.add_body(scenes::make_static_box(1.0, 20.0, {-8.5, 10.0}), random_material(u));
  world.add_body(scenes::make_static_box(1.0, 20.0, {8.5, 10.0}), random_material(u));
  const int n = 20 + u.below(21);
  for (int i = 0; i < n; ++i)
  {
    const Body body = random_body(u, i);  // drawn before its material
    world.add_body(body, random_material(u));
  }
  return world;
}

/// Steps `frames` frames; the largest rise of the energy in one frame (J).
double largest_energy_rise(World& world, int frames)
{
  double before = mechanical_energy(world, kGravity);
  double largest = 0.0;
  for (int f = 0; f < frames; ++f)
  {
    world.step();
    const double after = mechanical_energy(world, kGravity);
    largest = std::max(largest, after - before);
    before = after;
  }
  return largest;
}

struct JumbleCase
{
  std::uint64_t seed;
  int frames;
};

class BounceEnergy : public ::testing::TestWithParam<JumbleCase>
{
};

TEST_P(BounceEnergy, AJammedChainGainsNoEnergy)
{
  World world = jumble(GetParam().seed);
  const double scale = std::abs(mechanical_energy(world, kGravity));
  const double rise = largest_energy_rise(world, GetParam().frames);
  std::printf("jumble %llu: largest rise in one frame %.3g J (energy %.3g J)\n",
              static_cast<unsigned long long>(GetParam().seed), rise, scale);
  // Round-off of sums of some 40 bodies' energies, nothing more.
  EXPECT_LE(rise, 1e-12 * scale);
}

INSTANTIATE_TEST_SUITE_P(Jumbles, BounceEnergy, ::testing::Values(JumbleCase{130, 60}, JumbleCase{175, 60}));

}  // namespace
}  // namespace collision2d
