// A kinematic bar tilted a little closes on a disk that lies on the ground:
// the two surfaces make a wedge of that angle around the disk. With friction
// whose angle (atan mu) is wider than the wedge's, the wedge jams: no
// sliding lets the disk out, so it is crushed, and nothing may throw it out
// faster than the bar that presses it. Restitution leaves friction out, and
// without friction the disk's only way out is sideways at the bar's speed
// over the wedge's tangent: its passes, looking for that bounce, threw the
// disk at 82 and 55 m/s (4 and 8 substeps; 2260 m/s in a random world). A
// bounce whose passes find no fixed point is now dropped for the bodies it
// joins, and a pair bouncing elsewhere in the same substep still bounces by
// Newton's rule. The exact mode's relax added normal impulses only, so it
// found the frictionless way out too (86.6 m/s here, and 26 m/s under a bar
// at 3 m/s without restitution); in an island a moving kinematic body
// touches it now solves the substep's impulses again with their cones, and
// the same checks hold in both modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/world.h"
#include "extremes_support.h"

namespace collision2d
{
namespace
{
constexpr double kRadius = 0.39;        // m, the disk
constexpr double kTilt = 0.115;         // rad, the wedge's angle (6.6 degrees)
constexpr double kBarSpeed = 10.0;      // m/s, down
constexpr double kBarHalfLength = 1.5;  // m
constexpr double kBarHalfThickness = 0.1;  // m
constexpr double kBarGap = 0.01;        // m, between the bar and the disk at the start
constexpr double kPairSpeed = 2.0;      // m/s, each disk of the far pair
constexpr double kPairGap = 0.01;       // m, between them at the start
constexpr int kFrames = 30;
// Friction at 0.5 has an angle of 26.6 degrees, wider than the wedge's.
const Material kBouncyRough{0.5, 0.5, 0.5};

struct WedgeRun
{
  double fastest_disk = 0.0;  ///< m/s, the wedged disk over the run
  double closing_before = 0.0;  ///< m/s, the far pair
  double closing_after = 0.0;
  Vec2 pair_momentum_before;
  Vec2 pair_momentum_after;
};

WedgeRun run_wedge(int substeps, SolverMode mode)
{
  WorldSettings s;
  s.solver_mode = mode;
  s.gravity = Vec2{0.0, 0.0};  // the bar alone presses
  s.sleeping = Toggle::Off;
  s.substeps = substeps;
  World world(s);
  Body ground = scenes::make_box(1.0, 40.0, 1.0, {0.0, -0.5});
  ground.set_type(BodyType::Static);
  world.add_body(ground, kBouncyRough);
  const BodyId disk = world.add_body(Body(1.0, kRadius, {0.0, kRadius}, {0.0, 0.0}), kBouncyRough);
  // The bar's lower face, tilted by kTilt, just above the disk's top.
  const Vec2 down{std::sin(kTilt), -std::cos(kTilt)};
  const double reach = kRadius + kBarHalfThickness + kBarGap;
  Body bar = scenes::make_box(1.0, 2.0 * kBarHalfLength, 2.0 * kBarHalfThickness,
                              {-down.x * reach, kRadius - down.y * reach}, kTilt, {0.0, -kBarSpeed});
  bar.set_type(BodyType::Kinematic);
  world.add_body(bar, kBouncyRough);
  // Far away, two disks closing head on: they meet in the first frame.
  const BodyId left = world.add_body(Body(1.0, 0.2, {10.0, 5.0}, {kPairSpeed, 0.0}), kBouncyRough);
  const BodyId right = world.add_body(Body(3.0, 0.2, {10.4 + kPairGap, 5.0}, {-kPairSpeed, 0.0}), kBouncyRough);
  WedgeRun run;
  const auto pair_momentum = [&] { return world.body(left).momentum() + world.body(right).momentum(); };
  run.closing_before = world.body(left).velocity().x - world.body(right).velocity().x;
  run.pair_momentum_before = pair_momentum();
  for (int f = 0; f < kFrames; ++f)
  {
    world.step();
    run.fastest_disk = std::max(run.fastest_disk, length(world.body(disk).velocity()));
  }
  run.closing_after = world.body(left).velocity().x - world.body(right).velocity().x;
  run.pair_momentum_after = pair_momentum();
  return run;
}

void expect_jammed_and_pair_bounces(int substeps, SolverMode mode = SolverMode::Iterative)
{
  const WedgeRun run = run_wedge(substeps, mode);
  test::print_figure("wedged disk's fastest speed (m/s)", run.fastest_disk, kBarSpeed);
  EXPECT_LT(run.fastest_disk, kBarSpeed);
  // Newton's rule on the pair: its closing speed reversed and halved, its momentum kept.
  EXPECT_NEAR(run.closing_after, -kBouncyRough.restitution * run.closing_before, 1e-9);
  EXPECT_NEAR(run.pair_momentum_after.x, run.pair_momentum_before.x, 1e-12);
  EXPECT_NEAR(run.pair_momentum_after.y, run.pair_momentum_before.y, 1e-12);
}

TEST(ExtremesKinematicWedge, AJammedBouncyDiskIsNotThrownOutAtFourSubsteps)
{
  expect_jammed_and_pair_bounces(4);
}

TEST(ExtremesKinematicWedge, AJammedBouncyDiskIsNotThrownOutAtEightSubsteps)
{
  expect_jammed_and_pair_bounces(8);
}

TEST(ExtremesKinematicWedge, AJammedBouncyDiskIsNotThrownOutInExactMode)
{
  expect_jammed_and_pair_bounces(4, SolverMode::Exact);
  expect_jammed_and_pair_bounces(8, SolverMode::Exact);
}

}  // namespace
}  // namespace collision2d
