// A step or an edit that runs out of memory leaves the World exactly as it
// was (world_rollback.h for the step). This binary's operator new
// (allocation_counter.h) is armed to fail one allocation; each allocation of
// a step or edit is failed in turn, and the world afterwards must hold what
// it held before and then step on bit for bit like a copy that never failed. On one worker the
// allocations come in the same order every time, so each is failed once; on
// two, a worker's allocations may interleave differently from run to run.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/world.h"

#include "allocation_counter.h"
#include "extremes_support.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
/// Frames both worlds step after the failed step, compared bit for bit.
constexpr int kFramesAfter = 30;
/// Fewer for the larger world of the two-worker case.
constexpr int kFramesAfterShared = 3;

bool same_origins(const std::vector<WorldContact>& x, const std::vector<WorldContact>& y)
{
  for (std::size_t k = 0; k < x.size() && k < y.size(); ++k)
  {
    const ContactOrigin& p = x[k].origin;
    const ContactOrigin& q = y[k].origin;
    if (p.known != q.known || !test::same_bits(p.r_a, q.r_a) || !test::same_bits(p.r_b, q.r_b) ||
        !test::same_bits(p.separation, q.separation) || !test::same_bits(p.theta_a, q.theta_a) ||
        !test::same_bits(p.theta_b, q.theta_b))
    {
      return false;
    }
  }
  return x.size() == y.size();
}

/// What a caller can read of a world, and what its next steps depend on.
void expect_same_world(const World& x, const World& y, const char* when)
{
  ASSERT_EQ(x.body_ids(), y.body_ids()) << when;
  for (BodyId id : x.body_ids())
  {
    const Body& a = x.body(id);
    const Body& b = y.body(id);
    EXPECT_TRUE(a.type() == b.type() && test::same_bits(a.position(), b.position()) &&
                test::same_bits(a.theta(), b.theta()) && test::same_bits(a.velocity(), b.velocity()) &&
                test::same_bits(a.omega(), b.omega()))
        << when << ": body " << id;
  }
  EXPECT_TRUE(test::same_contacts(x.contacts(), y.contacts())) << when << ": contacts";
  EXPECT_TRUE(same_origins(x.contacts(), y.contacts())) << when << ": contact origins";
  const StepState sx = x.step_state();
  const StepState sy = y.step_state();
  EXPECT_TRUE(test::same_bits(sx.contact_substep, sy.contact_substep)) << when;
  EXPECT_EQ(sx.asleep, sy.asleep) << when << ": sleeping bodies";
  EXPECT_EQ(sx.rest_time, sy.rest_time) << when << ": rest times";
  EXPECT_EQ(x.frame_count(), y.frame_count()) << when;
  EXPECT_TRUE(test::same_bits(x.time(), y.time())) << when;
}

/// Fails each allocation of `change` (a step or an edit) on a copy of
/// `world` in turn: a refused change leaves the world as it was, and it
/// steps on like an intact copy. A change the failure did not stop (an
/// allocation the library may go without, such as std::stable_sort's buffer,
/// or on several workers one their order skipped this time) must end as
/// the change does.
void fail_each_allocation(const World& world, const std::function<void(World&)>& change, const char* name,
                          int frames_after = kFramesAfter, long stride = 1)
{
  World changed = world;
  const long before = test::g_allocations.load();
  change(changed);
  const long count = test::g_allocations.load() - before;
  std::printf("%s: failing each of its %ld allocations\n", name, count);
  ASSERT_GT(count, 0) << name << ": allocates nothing, so it tests nothing";
  for (long n = 0; n < count; n += stride)
  {
    World failed = world;
    bool threw = false;
    test::g_allocations_until_failure.store(n);
    try
    {
      change(failed);
    }
    catch (const std::bad_alloc&)
    {
      threw = true;
    }
    test::g_allocations_until_failure.store(-1);
    expect_same_world(failed, threw ? world : changed, threw ? "after the failed change" : "after the change");
    World intact = threw ? world : changed;
    for (int f = 0; f < frames_after; ++f)
    {
      failed.step();
      intact.step();
    }
    expect_same_world(failed, intact, "stepped on");
    if (::testing::Test::HasFailure())
    {
      FAIL() << name << ": allocation " << n << " of " << count;
    }
  }
}

/// fail_each_allocation for `world`'s next step of `frames` frames.
void fail_each_allocation_of_step(const World& world, const char* name, int frames_after = kFramesAfter,
                                  long stride = 1, int frames = 1)
{
  fail_each_allocation(world, [frames](World& w) { w.step(frames); }, name, frames_after, stride);
}

Scene with_workers(Scene scene, bool soft_step, int workers = 1)
{
  scene.settings.workers = workers;
  scene.settings.soft_step = soft_step;
  return scene;
}

/// A pyramid whose bodies fall asleep after resting 0.1 s.
Scene sleepy_pyramid(int base, bool soft_step)
{
  Scene scene = with_workers(scenes::pyramid(base), soft_step);
  scene.settings.sleeping = Toggle::On;
  scene.settings.sleep_time = 0.1;
  return scene;
}

/// A pyramid of 21 boxes asleep on its ground.
World sleeping_pyramid()
{
  World world = make_world(sleepy_pyramid(6, true));
  constexpr int kFramesToSleep = 120;
  for (int f = 0; f < kFramesToSleep; ++f)
  {
    world.step();
  }
  return world;
}

TEST(WorldOutOfMemory, FirstStepOfTheSoftStepPutsTheWorldBack)
{
  fail_each_allocation_of_step(make_world(with_workers(scenes::pyramid(6), true)), "pyramid, soft step, first step");
}

TEST(WorldOutOfMemory, FirstStepOfTheFx2dStepPutsTheWorldBack)
{
  fail_each_allocation_of_step(make_world(with_workers(scenes::pyramid(6), false)), "pyramid, Fx2D, first step");
}

TEST(WorldOutOfMemory, StepOfSeveralFramesPutsTheWorldBack)
{
  constexpr int kFrames = 3;
  fail_each_allocation_of_step(make_world(with_workers(scenes::pyramid(6), true)),
                               "pyramid, soft step, 3 frames in one step", kFramesAfter, 1, kFrames);
}

TEST(WorldOutOfMemory, FirstStepOfTheExactModePutsTheWorldBack)
{
  // Each island's LCP is built per solve, so a frame costs milliseconds.
  constexpr int kExactFramesAfter = 2;
  Scene scene = with_workers(scenes::pyramid(3), true);
  scene.settings.solver_mode = SolverMode::Exact;
  fail_each_allocation_of_step(make_world(scene), "pyramid, soft step, exact mode, first step", kExactFramesAfter);
}

/// A pyramid of 465 boxes: enough pairs and points that the workers share
/// the stages, so allocations fail on either thread.
TEST(WorldOutOfMemory, FirstStepOnTwoWorkersPutsTheWorldBack)
{
  constexpr int kSharedBase = 30;
  // Under ThreadSanitizer a frame of it takes about 40 ms.
  const long frames_after = test::sized(kFramesAfterShared, 1, "frames stepped on after each failed step");
  const long stride = test::sized(1, 4, "allocations failed: every n-th,");
  fail_each_allocation_of_step(make_world(with_workers(scenes::pyramid(kSharedBase), true, 2)),
                               "pyramid of 465 boxes, soft step, 2 workers, first step",
                               static_cast<int>(frames_after), stride);
}

/// Steps a sleeping pyramid to the first step in which bodies fall asleep
/// and the step allocates, and fails each of that step's allocations.
void fail_each_allocation_as_bodies_fall_asleep(bool soft_step, const char* name)
{
  World world = make_world(sleepy_pyramid(4, soft_step));
  constexpr int kMaxFrames = 600;
  for (int f = 0; f < kMaxFrames; ++f)
  {
    World probe = world;
    const long before = test::g_allocations.load();
    probe.step();
    if (test::g_allocations.load() > before && probe.step_state().asleep.size() > world.step_state().asleep.size())
    {
      fail_each_allocation_of_step(world, name);
      return;
    }
    world.step();
  }
  FAIL() << name << ": no step put bodies to sleep while allocating";
}

/// A box dropped on the sleeping pyramid: the step in which it reaches the
/// pyramid wakes it.
TEST(WorldOutOfMemory, StepThatWakesASleepingPyramidPutsTheWorldBack)
{
  World world = sleeping_pyramid();
  const std::size_t asleep = world.step_state().asleep.size();
  ASSERT_GT(asleep, 0u) << "the pyramid should sleep";
  world.add_body(scenes::make_box(1.0, 1.0, 1.0, {0.0, 8.0}));
  constexpr int kMaxFrames = 120;
  for (int f = 0; f < kMaxFrames; ++f)
  {
    World probe = world;
    probe.step();
    if (probe.step_state().asleep.size() < asleep)
    {
      fail_each_allocation_of_step(world, "a box waking the sleeping pyramid");
      return;
    }
    world.step();
  }
  FAIL() << "the dropped box did not wake the pyramid";
}

TEST(WorldOutOfMemory, SoftStepThatPutsBodiesToSleepPutsTheWorldBack)
{
  fail_each_allocation_as_bodies_fall_asleep(true, "sleeping pyramid, soft step");
}

TEST(WorldOutOfMemory, Fx2dStepThatPutsBodiesToSleepPutsTheWorldBack)
{
  fail_each_allocation_as_bodies_fall_asleep(false, "sleeping pyramid, Fx2D");
}

TEST(WorldOutOfMemory, AddingABodyThatRunsOutOfMemoryLeavesTheWorldAsItWas)
{
  World world = make_world(with_workers(scenes::pyramid(6), true));
  world.step();
  const Body box = scenes::make_box(1.0, 1.0, 1.0, {0.0, 12.0});
  fail_each_allocation(world, [&](World& w) { w.add_body(box); }, "adding a box");
}

TEST(WorldOutOfMemory, RemovingABodyThatRunsOutOfMemoryLeavesTheWorldAsItWas)
{
  const World world = sleeping_pyramid();
  ASSERT_FALSE(world.step_state().asleep.empty()) << "the pyramid should sleep";
  const BodyId bottom = world.body_ids()[1];
  fail_each_allocation(world, [&](World& w) { w.remove_body(bottom); }, "removing a sleeping bottom box");
}

TEST(WorldOutOfMemory, ChangingABodysTypeThatRunsOutOfMemoryLeavesTheWorldAsItWas)
{
  const World world = sleeping_pyramid();
  ASSERT_FALSE(world.step_state().asleep.empty()) << "the pyramid should sleep";
  const BodyId top = world.body_ids().back();
  fail_each_allocation(world, [&](World& w) { w.set_body_type(top, BodyType::Kinematic); },
                               "making a sleeping box kinematic");
}

TEST(WorldOutOfMemory, RestoringAStepStateThatRunsOutOfMemoryLeavesTheWorldAsItWas)
{
  const World asleep = sleeping_pyramid();
  const StepState state = asleep.step_state();
  ASSERT_FALSE(state.asleep.empty()) << "the pyramid should sleep";
  World world = asleep;  // the same bodies, then stepped on: another state to replace
  world.set_step_state(StepState{{}, 0.0, {}, std::vector<double>(state.rest_time.size(), 0.0)});
  world.step();
  fail_each_allocation(world, [&](World& w) { w.set_step_state(state); }, "restoring a sleeping state");
}

}  // namespace
}  // namespace collision2d
