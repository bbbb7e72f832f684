// A warmed-up World steps without allocating: every buffer of the step
// (contacts, points, broad-phase cells, velocities, the saved state a failed
// step puts back) is kept across steps and only grows. Counted over frames
// after a warm-up, in both pipelines, with sleeping and with the Auto effects.
// The exact mode builds each island's LCP per solve and is not covered.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>
#include <string>

#include "collision2d/scene.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/world.h"

#include "allocation_counter.h"

namespace collision2d
{
namespace
{
/// Frames that let every buffer reach its largest size: impacts settle and
/// the contact count stops growing.
constexpr int kWarmUpFrames = 600;
constexpr int kCountedFrames = 120;

struct AllocationCase
{
  const char* name;
  std::function<Scene()> scene;
  bool soft_step;
};

void PrintTo(const AllocationCase& c, std::ostream* os) { *os << c.name; }

class WorldAllocation : public ::testing::TestWithParam<AllocationCase>
{
};

TEST_P(WorldAllocation, WarmedUpStepsAllocateNothing)
{
  const AllocationCase& c = GetParam();
  Scene scene = c.scene();
  scene.settings.soft_step = c.soft_step;
  World world = make_world(scene);
  for (int f = 0; f < kWarmUpFrames; ++f)
  {
    world.step();  // as counted below: a step of several frames saves its state once
  }
  const long before = test::g_allocations.load();
  for (int f = 0; f < kCountedFrames; ++f)
  {
    world.step();
  }
  const long allocations = test::g_allocations.load() - before;
  std::printf("%s: %ld allocations in %d frames after %d of warm-up\n", c.name, allocations, kCountedFrames,
              kWarmUpFrames);
  EXPECT_EQ(allocations, 0) << c.name;
}

Scene sleeping_pyramid()
{
  Scene scene = scenes::pyramid(10);
  scene.settings.sleeping = Toggle::On;
  scene.settings.sleep_time = 0.1;
  return scene;
}

/// The sleeping pyramid while one kinematic disk slides past, far from it:
/// the frames step only the movers.
Scene stirred_pyramid()
{
  Scene scene = sleeping_pyramid();
  Body disk(1.0, 0.5, {-30.0, 3.0}, {0.5, 0.0});
  disk.set_type(BodyType::Kinematic);
  scene.bodies.push_back(SceneBody{disk, Material{}, "stirrer"});
  return scene;
}

/// Large enough that two workers share every stage they can take.
Scene shared_pyramid()
{
  Scene scene = scenes::pyramid(65);
  scene.settings.workers = 2;
  return scene;
}

/// The Fx2D step detects every substep: a smaller pyramid (its contact
/// points are still shared, its bodies not) keeps the test short.
Scene shared_small_pyramid()
{
  Scene scene = scenes::pyramid(46);
  scene.settings.workers = 2;
  return scene;
}

const AllocationCase kCases[] = {
    {"pyramid_soft_step", [] { return scenes::pyramid(20); }, true},
    {"pyramid_fx2d", [] { return scenes::pyramid(20); }, false},
    {"sleeping_pyramid_soft_step", sleeping_pyramid, true},
    {"stirred_pyramid_soft_step", stirred_pyramid, true},
    {"stirred_pyramid_fx2d", stirred_pyramid, false},
    {"gas_soft_step", [] { return scenes::elastic_gas(300); }, true},
    {"gas_fx2d", [] { return scenes::elastic_gas(300); }, false},
    {"demo_soft_step", [] { return scenes::demo(); }, true},
    {"bullet_soft_step", [] { return scenes::bullet_wall(); }, true},
    {"shared_pyramid_soft_step", shared_pyramid, true},
    {"shared_pyramid_fx2d", shared_small_pyramid, false},
};

INSTANTIATE_TEST_SUITE_P(Scenes, WorldAllocation, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<AllocationCase>& info) { return std::string(info.param.name); });

TEST(WorldAllocation, TheCounterSeesAllocations)
{
  // The control: building a world allocates, so a zero above is a measurement.
  const long before = test::g_allocations.load();
  World world = make_world(scenes::pyramid(3));
  EXPECT_GT(test::g_allocations.load() - before, 0);
}

TEST(WorldAllocation, TheCounterSeesAlignedAllocations)
{
  // The soft rows ask for over-aligned blocks (four lanes of doubles).
  const long before = test::g_allocations.load();
  const std::align_val_t alignment{32};
  ::operator delete(::operator new(96, alignment), alignment);
  EXPECT_EQ(test::g_allocations.load() - before, 1);
}

}  // namespace
}  // namespace collision2d
