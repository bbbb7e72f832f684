// A world rebuilt from its scene, ids, clock and step state (what a snapshot
// keeps) steps on bit for bit like the world it was taken from.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/scene.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/world.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
struct ResumeCase
{
  const char* name;
  std::function<Scene()> scene;
  std::function<void(WorldSettings&)> tweak;
};

class WorldResume : public ::testing::TestWithParam<ResumeCase>
{
};

void PrintTo(const ResumeCase& c, std::ostream* os) { *os << c.name; }

TEST_P(WorldResume, RebuiltWorldStepsOnBitForBit)
{
  Scene scene = GetParam().scene();
  GetParam().tweak(scene.settings);
  World original = make_world(scene);
  // Remove one body so the ids have a gap the rebuilt world must keep.
  original.step(30);
  original.remove_body(original.body_ids().back());
  original.step(30);
  World resumed = test::rebuilt(original);
  ASSERT_EQ(test::state_hash(resumed), test::state_hash(original)) << "the rebuild itself differs";
  for (int frame = 0; frame < 60; ++frame)
  {
    original.step();
    resumed.step();
    ASSERT_EQ(test::state_hash(resumed), test::state_hash(original)) << "frame " << frame << " after the restore";
  }
  EXPECT_EQ(resumed.frame_count(), original.frame_count());
  const BodyId added = resumed.add_body(Body(1.0, 0.5, Vec2{0.0, 50.0}, Vec2{0.0, 0.0}));
  EXPECT_EQ(added, original.add_body(Body(1.0, 0.5, Vec2{0.0, 50.0}, Vec2{0.0, 0.0})));
}

void defaults(WorldSettings&) {}

INSTANTIATE_TEST_SUITE_P(
    Scenes, WorldResume,
    ::testing::Values(ResumeCase{"pyramid", [] { return scenes::pyramid(8); }, defaults},
                      ResumeCase{"pyramid_sleeping", [] { return scenes::pyramid(8); },
                                 [](WorldSettings& s) {
                                   s.sleeping = Toggle::On;
                                   s.sleep_time = 0.1;
                                 }},
                      ResumeCase{"demo", [] { return scenes::demo(); }, defaults},
                      ResumeCase{"incline_sliding", [] { return scenes::incline(0.6, 0.5, 0.3); }, defaults},
                      ResumeCase{"pyramid_soft_step", [] { return scenes::pyramid(8); },
                                 [](WorldSettings& s) { s.soft_step = true; }},
                      ResumeCase{"heavy_on_light_exact", [] { return scenes::heavy_on_light(1e6); },
                                 [](WorldSettings& s) { s.solver_mode = SolverMode::Exact; }}),
    [](const ::testing::TestParamInfo<ResumeCase>& info) { return std::string(info.param.name); });

TEST(WorldResume, ContactsInAnyOrderResumeBitForBitOnSeveralWorkers)
{
  // A step state's pairs may come in any order (each pair's points in the
  // order they were published); the world keeps its contacts in (a, b)
  // order, which the workers' cache lookups rely on. A pyramid large enough
  // that they place the pairs in parts, restored from its pairs reversed,
  // steps on like the original.
  Scene scene = scenes::pyramid(50);
  scene.settings.workers = 2;
  World original = make_world(scene);
  original.step(20);
  StepState state = original.step_state();
  ASSERT_GT(state.contacts.size(), 2000u);
  std::vector<WorldContact> reversed;
  for (auto end = state.contacts.end(); end != state.contacts.begin();)
  {
    auto begin = end - 1;
    while (begin != state.contacts.begin() && begin[-1].a == begin->a && begin[-1].b == begin->b)
    {
      --begin;
    }
    reversed.insert(reversed.end(), begin, end);
    end = begin;
  }
  ASSERT_NE(reversed.front().a, state.contacts.front().a);
  state.contacts = reversed;
  World resumed = original;
  resumed.set_step_state(state);
  for (int frame = 0; frame < 10; ++frame)
  {
    original.step();
    resumed.step();
    ASSERT_EQ(test::state_hash(resumed), test::state_hash(original)) << "frame " << frame << " after the restore";
  }
}

TEST(WorldResume, WithoutTheStepStateTheRunDiffers)
{
  // The step state is what makes the difference: a rebuild without it (cold
  // warm start) departs from the original run.
  World original = make_world(scenes::pyramid(8));
  original.step(30);
  const Scene scene = to_scene(original);
  World cold = make_world(scene);
  cold.set_clock(original.time(), original.frame_count());
  original.step(5);
  cold.step(5);
  EXPECT_NE(test::state_hash(cold), test::state_hash(original));
}

TEST(WorldResume, BadStepStateIsRefusedNamingTheEntryAndChangesNothing)
{
  World world = make_world(scenes::pyramid(4));
  world.step(10);
  const std::uint64_t before = test::state_hash(world);
  StepState state = world.step_state();
  state.contacts.at(0).b = 999;
  try
  {
    world.set_step_state(state);
    ADD_FAILURE() << "an unknown body was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("contacts[0]"), std::string::npos) << e.what();
  }
  state = world.step_state();
  state.rest_time.pop_back();
  EXPECT_THROW(world.set_step_state(state), std::invalid_argument);
  // Only a dynamic body sleeps; the ground is static.
  state = world.step_state();
  const BodyId ground = world.body_ids().front();
  ASSERT_EQ(world.body(ground).type(), BodyType::Static);
  state.asleep.push_back(ground);
  try
  {
    world.set_step_state(state);
    ADD_FAILURE() << "a static body was put to sleep";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("body " + std::to_string(ground)), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not dynamic"), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::state_hash(world), before);
  world.step();
  World twin = make_world(scenes::pyramid(4));
  twin.step(11);
  EXPECT_EQ(test::state_hash(world), test::state_hash(twin));
}

TEST(WorldResume, ContactsOfBodiesThatStoppedMovingResumeLikeTheOriginal)
{
  // The box on the incline made static keeps its contacts until the next
  // frame, which finds no mover in the pair and drops them. A world rebuilt
  // from the snapshot then must not keep them as if an island slept there
  // (sleeping on: contacts with a sleeping body are kept aside).
  for (const bool soft : {true, false})
  {
    Scene scene = scenes::incline();
    scene.settings.soft_step = soft;
    scene.settings.sleeping = Toggle::On;
    World original = make_world(scene);
    original.step(14);
    const BodyId box = original.body_ids().back();
    ASSERT_FALSE(original.contacts().empty());
    original.set_body_type(box, BodyType::Static);
    World resumed = test::rebuilt(original);
    original.step();
    resumed.step();
    EXPECT_TRUE(original.contacts().empty()) << "soft " << soft;
    EXPECT_TRUE(test::same_contacts(resumed.contacts(), original.contacts())) << "soft " << soft;
    EXPECT_EQ(test::state_hash(resumed), test::state_hash(original)) << "soft " << soft;
  }
}

TEST(WorldResume, ACopyMidRunStepsOnBitForBitWithoutItsScratch)
{
  // A copy leaves the frame's scratch behind (the frame block starts empty):
  // nothing a step reads before writing it is in there. The pyramid packs
  // soft-step rows each frame, the gas one-point manifolds.
  for (const Scene& scene : {scenes::pyramid(6), scenes::elastic_gas(40)})
  {
    World world = make_world(scene);
    world.step(30);
    World copy = world;
    World assigned(scene.settings);
    assigned = world;
    world.step(30);
    copy.step(30);
    assigned.step(30);
    EXPECT_EQ(test::state_hash(copy), test::state_hash(world)) << scene.name;
    EXPECT_EQ(test::state_hash(assigned), test::state_hash(world)) << scene.name;
  }
}

}  // namespace
}  // namespace collision2d
