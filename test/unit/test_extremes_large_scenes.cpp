// Large scenes: 1e4 and 1e5 bodies (disks and boxes in a static
// container, gravity on) step without error and stay finite, and the
// process's peak resident memory (VmHWM from /proc/self/status) stays below
// a stated bound: a fixed allowance for the test process plus a budget per
// body. The ContactSolver path (detect_contacts + resolve) is run on the
// same bodies too.
//
// Known cost (reported to the world's owner): World::add_body refreshes every
// body's inner radius, so building a world of n bodies is O(n^2); at 1e5
// bodies make_world takes about half a minute of this test's time, the three
// frames well under a second.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "extremes_support.h"

namespace collision2d
{
namespace
{
/// Peak memory allowed: the test process itself (gtest, libraries) plus a
/// budget per body covering the scene, the world (bodies, materials, contact
/// rows, caches), its copy made by make_world and the solver's buffers.
constexpr long kBaseKib = 64 * 1024;
constexpr long kKibPerBody = 2;  // KiB per body (about 0.8 measured)
/// Under AddressSanitizer memory is shadowed and freed blocks are kept in
/// quarantine, so the bound there is multiplied.
constexpr long kSanitizerMemoryFactor = 8;
constexpr int kFrames = 3;
constexpr double kRadius = 0.1;  // m
constexpr double kSpacing = 0.3;  // m of container per body along each axis

Scene large_scene(long n)
{
  Scene scene;
  const double side = std::ceil(std::sqrt(static_cast<double>(n))) * kSpacing;
  scenes::ContainerParams box;
  box.upper = {side, side};
  scenes::add_container(scene, box);
  // Nine in ten bodies are disks from the gas builder, the rest boxes placed
  // on a coarse grid over it (overlapping some disks: they push apart).
  scenes::GasParams gas;
  gas.count = static_cast<int>(n - n / 10);
  gas.radius = kRadius;
  gas.upper = box.upper;
  scenes::add_gas(scene, gas);
  const long boxes = n / 10;
  const long per_row = static_cast<long>(std::ceil(std::sqrt(static_cast<double>(boxes))));
  for (long k = 0; k < boxes; ++k)
  {
    const Vec2 at{(0.5 + static_cast<double>(k % per_row)) * side / per_row,
                  (0.5 + static_cast<double>(k / per_row)) * side / per_row};
    scene.bodies.push_back(SceneBody{scenes::make_box(1.0, 0.15, 0.1, at, 0.3 * k), scenes::rough_material(), ""});
  }
  return scene;
}

void check_large_scene(long full, long reduced)
{
  const long n = test::sized(full, reduced, "large scene bodies");
  const Scene scene = large_scene(n);
  World world = make_world(scene);
  const StepReport report = world.step(kFrames);
  ASSERT_TRUE(test::all_finite(world));
  EXPECT_EQ(report.frames, kFrames);
  EXPECT_EQ(world.body_count(), scene.bodies.size());

  std::vector<Body> bodies;
  bodies.reserve(scene.bodies.size());
  for (const SceneBody& b : scene.bodies)
  {
    bodies.push_back(b.body);
  }
  const SolveReport solve = ContactSolver(0.5, 0.3).resolve(bodies);
  ASSERT_TRUE(test::all_finite(bodies));

  const long peak = test::peak_rss_kib();
  ASSERT_GT(peak, 0) << "VmHWM unreadable";
  const long bound = (kBaseKib + kKibPerBody * static_cast<long>(scene.bodies.size())) *
                     (test::sanitizer_build() ? kSanitizerMemoryFactor : 1);
  EXPECT_LE(peak, bound);
  std::printf("%zu bodies: %d frames, %zu world contacts, %zu solver contacts in %zu islands\n",
              scene.bodies.size(), kFrames, report.contact_count, solve.contact_count, solve.island_count);
  test::print_figure("peak resident memory so far, VmHWM (KiB)", static_cast<double>(peak),
                     static_cast<double>(bound));
}

// In this order: VmHWM only grows, so each bound covers everything before it.
TEST(ExtremesLargeScenes, TenThousandBodies) { check_large_scene(10000, 10000); }
TEST(ExtremesLargeScenes, HundredThousandBodies) { check_large_scene(100000, 20000); }

}  // namespace
}  // namespace collision2d
