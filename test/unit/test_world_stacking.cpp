// Resting contact over 10 s: a box on the ground at the defaults; the base-20
// pyramid and the 20-box column in the Fx2D pipeline at its defaults and, for the record, over the
// substep and position-pass knobs. Every quantity is recomputed from the
// bodies' poses.
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

/// Drift of a stack over kSeconds with the given knobs, from the start poses
/// and from the poses after kSettleSeconds (the stack has sunk onto its slop
/// by then; what follows is creep).
struct StackRun
{
  Drift from_start;
  Drift since_settled;
  double kinetic_energy = 0.0;  // J, at the end
};

constexpr double kSettleSeconds = 1.0;

StackRun run_stack(Scene scene, int substeps, int position_iterations, bool position_block)
{
  scene.settings.soft_step = false;  // the position passes are the Fx2D pipeline's
  scene.settings.substeps = substeps;
  scene.settings.position_iterations = position_iterations;
  scene.settings.position_block = position_block;
  World world = make_world(scene);
  const std::vector<Body> start = snapshot(world);
  world.step(frames_for(world, kSettleSeconds));
  const std::vector<Body> settled = snapshot(world);
  world.step(frames_for(world, kSeconds - kSettleSeconds));
  StackRun run;
  run.from_start = drift_from(world, start);
  run.since_settled = drift_from(world, settled);
  for (BodyId id : world.body_ids())
  {
    run.kinetic_energy += world.body(id).kinetic_energy();
  }
  std::printf("%-12s substeps %2d, position passes %d%s: drift %.4f m (lateral %.2g m, tilt %.2g rad), "
              "after settling %.5f m\n",
              scene.name.c_str(), substeps, position_iterations, position_block ? " (block)" : "        ",
              run.from_start.distance, run.from_start.lateral, run.from_start.tilt, run.since_settled.distance);
  return run;
}

TEST(WorldStacking, Fx2dBase20PyramidStandsTenSeconds)
{
  const WorldSettings defaults;
  const Scene pyramid = scenes::pyramid(20);
  // One pass (the plain Fx2D order), for the record; each pyramid run costs about a second,
  // so the substep sweep is left to the benchmark (8 substeps, 4 passes:
  // 0.024 m, 0.0003 m after settling).
  const StackRun spec_pass = run_stack(pyramid, defaults.substeps, 1, false);
  const StackRun run = run_stack(pyramid, defaults.substeps, defaults.position_iterations, defaults.position_block);
  // Measured at the defaults (4 substeps, 4 position passes): 0.029 m, most of
  // it the first second's settling onto slop-deep contacts (20 rows); 0.0015 m
  // after it. One pass (plain Fx2D): 0.056 m, 0.006 m after settling.
  EXPECT_LT(run.from_start.distance, 0.04);
  EXPECT_LT(run.since_settled.distance, 0.003);
  EXPECT_LT(run.from_start.lateral, 0.015);
  EXPECT_LT(run.from_start.tilt, 0.005);
  EXPECT_LT(run.kinetic_energy, 1e-3);
  EXPECT_LT(run.from_start.distance, spec_pass.from_start.distance);
}

TEST(WorldStacking, Fx2dTwentyBoxColumnStandsTenSeconds)
{
  const WorldSettings defaults;
  const Scene column = scenes::column(20);
  for (int substeps : {8, 16})
  {
    for (int passes : {1, defaults.position_iterations})
    {
      run_stack(column, substeps, passes, false);
    }
  }
  const StackRun block = run_stack(column, defaults.substeps, 1, true);
  const StackRun spec_pass = run_stack(column, defaults.substeps, 1, false);
  const StackRun run = run_stack(column, defaults.substeps, defaults.position_iterations, defaults.position_block);
  // Each of the 20 contacts keeps up to slop (1 mm) of penetration by design,
  // so the top box sinks about 20 mm even when every correction converges. One
  // position pass per substep (plain Fx2D) leaves part of each substep's gravity sag
  // g h^2 in every contact: 0.15 m. Four passes (default): 0.054 m, 0.008 m of
  // it after the first second; a 2x2 block per manifold: 0.052 m in one pass.
  EXPECT_LT(run.from_start.distance, 0.07);
  EXPECT_LT(run.since_settled.distance, 0.012);
  EXPECT_LT(run.from_start.lateral, 1e-6);
  EXPECT_LT(run.from_start.tilt, 1e-6);
  EXPECT_LT(run.from_start.distance, 0.5 * spec_pass.from_start.distance);
  EXPECT_LT(block.from_start.distance, 0.5 * spec_pass.from_start.distance);
}

}  // namespace
}  // namespace collision2d
