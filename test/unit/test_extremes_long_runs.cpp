// Long runs: 1e5 frames (about 28 minutes of simulated time) of a
// resting stack and of a small elastic gas, with the world's default
// settings. Sizes are chosen so each run takes a few seconds in Release.
//
// What holds (asserted): no NaN; the stack neither slides, tilts nor keeps
// sinking once settled; no gas disk leaves its container; the gas never
// gains energy. What does not: the gas (e = 1, no friction) is not
// energy-conserving in the world: it loses about a third of its kinetic
// energy over 1e5 frames, in jumps at multi-contact events that the world's
// two velocity passes per substep do not resolve elastically. The test
// bounds that loss and prints it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "extremes_support.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
constexpr long kFrames = 100000;
constexpr long kSanitizerFrames = 10000;

using test::kinetic_energy;

TEST(ExtremesLongRuns, RestingStackDoesNotDrift)
{
  Scene scene;
  scenes::GroundParams ground;
  ground.width = 4.0;
  scenes::add_ground(scene, ground);
  scenes::ColumnParams column;
  column.count = 2;
  scenes::add_column(scene, column);
  World world = make_world(scene);
  constexpr int kSettleFrames = 600;  // 10 s
  world.step(kSettleFrames);
  std::vector<Vec2> settled;
  for (BodyId id : world.body_ids())
  {
    settled.push_back(world.body(id).position());
  }
  const long frames = test::sized(kFrames, kSanitizerFrames, "resting stack frames");
  for (long f = 0; f < frames; ++f)
  {
    world.step();
  }
  ASSERT_TRUE(test::all_finite(world));
  double sideways = 0.0;
  double tilt = 0.0;
  double sinking = 0.0;
  for (BodyId id : world.body_ids())
  {
    const Body& b = world.body(id);
    sideways = std::max(sideways, std::abs(b.position().x - settled[id].x));
    tilt = std::max(tilt, std::abs(b.theta()));
    sinking = std::max(sinking, std::abs(b.position().y - settled[id].y));
  }
  constexpr double kSidewaysBound = 1e-9;  // m
  constexpr double kTiltBound = 1e-9;      // rad
  constexpr double kSinkingBound = 1e-4;   // m: a tenth of the slop
  constexpr double kRestEnergy = 1e-9;     // J: at rest, no jitter
  EXPECT_LE(sideways, kSidewaysBound);
  EXPECT_LE(kinetic_energy(world), kRestEnergy);
  EXPECT_LE(tilt, kTiltBound);
  EXPECT_LE(sinking, kSinkingBound);
  std::printf("2-box stack, %ld frames after %d settling frames:\n", frames, kSettleFrames);
  test::print_figure("sideways drift (m)", sideways, kSidewaysBound);
  test::print_figure("tilt (rad)", tilt, kTiltBound);
  test::print_figure("vertical change (m)", sinking, kSinkingBound);
  test::print_figure("kinetic energy at the end (J)", kinetic_energy(world), kRestEnergy);
}

TEST(ExtremesLongRuns, ElasticGasStaysBoundedAndFinite)
{
  Scene scene;
  scene.settings.gravity = {0.0, 0.0};
  const Vec2 upper{4.0, 4.0};
  scenes::ContainerParams box;
  box.upper = upper;
  scenes::add_container(scene, box);
  scenes::GasParams gas;
  gas.count = 16;
  gas.radius = 0.2;
  gas.upper = upper;
  scenes::add_gas(scene, gas);
  World world = make_world(scene);
  const double start = kinetic_energy(world);
  const long frames = test::sized(kFrames, kSanitizerFrames, "elastic gas frames");
  double highest = start;
  double lowest = start;
  double escape = 0.0;  // m: furthest any disk centre got outside the container
  for (long f = 0; f < frames; ++f)
  {
    world.step();
    const double e = kinetic_energy(world);
    ASSERT_TRUE(std::isfinite(e)) << "frame " << f;
    highest = std::max(highest, e);
    lowest = std::min(lowest, e);
    for (BodyId id : world.body_ids())
    {
      const Body& b = world.body(id);
      if (b.type() == BodyType::Dynamic)
      {
        const Vec2 p = b.position();
        escape = std::max({escape, -p.x, -p.y, p.x - upper.x, p.y - upper.y});
      }
    }
  }
  ASSERT_TRUE(test::all_finite(world));
  constexpr double kRiseTol = 1e-9;       // relative: contacts with e <= 1 add no energy
  constexpr double kLeastKept = 0.5;      // fraction of the start energy still there
  EXPECT_LE((highest - start) / start, kRiseTol);
  EXPECT_GE(lowest / start, kLeastKept);
  EXPECT_LE(escape, 0.0);
  std::printf("16-disk elastic gas, %ld frames:\n", frames);
  test::print_figure("largest energy rise (relative)", (highest - start) / start, kRiseTol);
  test::print_figure("least energy kept (fraction of start)", lowest / start, kLeastKept);
  test::print_figure("furthest escape past a wall (m)", escape, 0.0);
}

}  // namespace
}  // namespace collision2d
