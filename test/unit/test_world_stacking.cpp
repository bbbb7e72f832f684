// Resting contact over 10 s with the default settings: a box on the ground,
// the base-20 pyramid and the 20-box column. Every quantity is recomputed
// from the bodies' poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "collision2d/scenes/standard_scenes.h"

namespace collision2d
{
namespace
{
constexpr double kSeconds = 10.0;

int frames_for(const World& world, double seconds)
{
  return static_cast<int>(std::lround(seconds / world.settings().dt));
}

double lowest_point(const Body& b)
{
  double lowest = INFINITY;
  for (std::size_t i = 0; i < b.vertex_count(); ++i)
  {
    lowest = std::min(lowest, b.world_vertex(i).y);
  }
  return lowest;
}

/// Largest displacement and tilt of the dynamic bodies from their start poses.
struct Drift
{
  double distance = 0.0;  // m
  double lateral = 0.0;   // m, |dx|
  double tilt = 0.0;      // rad
};

Drift drift_from(const World& world, const std::vector<Body>& start)
{
  Drift d;
  const std::vector<BodyId> ids = world.body_ids();
  for (std::size_t k = 0; k < ids.size(); ++k)
  {
    const Body& b = world.body(ids[k]);
    if (b.type() != BodyType::Dynamic)
    {
      continue;
    }
    const Vec2 moved = b.position() - start[k].position();
    d.distance = std::max(d.distance, length(moved));
    d.lateral = std::max(d.lateral, std::abs(moved.x));
    d.tilt = std::max(d.tilt, std::abs(b.theta() - start[k].theta()));
  }
  return d;
}

std::vector<Body> snapshot(const World& world)
{
  std::vector<Body> bodies;
  for (BodyId id : world.body_ids())
  {
    bodies.push_back(world.body(id));
  }
  return bodies;
}

TEST(WorldStacking, RestingBoxStaysWithinSlop)
{
  World world = make_world(scenes::resting_box());
  const std::vector<BodyId> ids = world.body_ids();
  const BodyId ground = ids.front();
  const BodyId box = ids.back();
  const double ground_top = world.body(ground).aabb().hi.y;
  const double slop = world.settings().slop;
  // The first frame lets the box settle onto its slop; from then on it must
  // not move by more than slop, and never sink deeper than twice the slop.
  world.step();
  const Body settled = world.body(box);
  double worst_sink = 0.0;
  double worst_shift = 0.0;
  for (int f = 0; f < frames_for(world, kSeconds); ++f)
  {
    world.step();
    const Body& b = world.body(box);
    worst_sink = std::max(worst_sink, ground_top - lowest_point(b));
    worst_shift = std::max(worst_shift, length(b.position() - settled.position()));
    ASSERT_LE(std::abs(b.theta()), 1e-9);
  }
  std::printf("resting box: deepest sink %.3g m, largest move after settling %.3g m\n", worst_sink, worst_shift);
  EXPECT_LE(worst_shift, slop);
  EXPECT_LE(worst_sink, 2.0 * slop);
  EXPECT_GE(worst_sink, 0.0);
}

TEST(WorldStacking, Base20PyramidStandsTenSeconds)
{
  World world = make_world(scenes::pyramid(20));
  const std::vector<Body> start = snapshot(world);
  world.step(frames_for(world, kSeconds));
  const Drift d = drift_from(world, start);
  double energy = 0.0;
  for (BodyId id : world.body_ids())
  {
    energy += world.body(id).kinetic_energy();
  }
  // Measured with the defaults (4 substeps, 2 iterations): about 0.056 m,
  // almost all of it the pyramid settling into its contacts.
  std::printf("pyramid(20): largest drift %.3g m (lateral %.3g m), tilt %.3g rad, kinetic energy %.3g J\n", d.distance,
              d.lateral, d.tilt, energy);
  EXPECT_LT(d.distance, 0.1);
  EXPECT_LT(d.lateral, 0.02);
  EXPECT_LT(d.tilt, 0.02);
  EXPECT_LT(energy, 1e-3);
}

TEST(WorldStacking, TwentyBoxColumnStandsTenSeconds)
{
  World world = make_world(scenes::column(20));
  const std::vector<Body> start = snapshot(world);
  world.step(frames_for(world, kSeconds));
  const Drift d = drift_from(world, start);
  // The column does not topple or slide; it sinks into its 20 contacts by the
  // per-substep gravity sag each correction leaves: about 0.15 m at the top
  // with the defaults (4 substeps), less with more substeps.
  std::printf("column(20): largest drift %.3g m (lateral %.3g m), tilt %.3g rad\n", d.distance, d.lateral, d.tilt);
  EXPECT_LT(d.distance, 0.2);
  EXPECT_LT(d.lateral, 1e-6);
  EXPECT_LT(d.tilt, 1e-6);
}

}  // namespace
}  // namespace collision2d
