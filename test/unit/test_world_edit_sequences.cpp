// Edits between steps, drawn at random from fixed seeds: velocities set,
// bodies made static, kinematic or dynamic, removed and added, on small
// scenes with the pipeline and effects drawn too. After every edit or step
// three promises hold bit for bit: 1 and 2 workers give the same world, a
// world rebuilt from its snapshot steps on like the original, and a step the
// world refuses (it overflows) leaves it as it was.
#include <algorithm>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/scene.h"
#include "collision2d/scenes/standard_scenes.h"
#include "collision2d/setting_table.h"
#include "collision2d/world.h"
#include "extremes_support.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
/// Frames a rebuilt world and the original step side by side after each edit.
constexpr int kResumeFrames = 2;
/// Edits and steps drawn per sequence.
constexpr int kEditsPerSequence = 10;
/// The largest velocity an edit sets (m/s) and spin (rad/s).
constexpr double kMaxEditSpeed = 20.0;
constexpr double kMaxEditSpin = 10.0;

using Random = std::mt19937_64;

double uniform(Random& random, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); }

int pick(Random& random, int count) { return std::uniform_int_distribution<int>(0, count - 1)(random); }

Scene draw_scene(Random& random)
{
  switch (pick(random, 6))
  {
    case 0:
      return scenes::pyramid(2 + pick(random, 4));
    case 1:
      return scenes::column(2 + pick(random, 6));
    case 2:
      return scenes::bouncing_disks(1 + pick(random, 5), uniform(random, 0.0, 1.0));
    case 3:
      return scenes::incline(uniform(random, 0.1, 1.0), uniform(random, 0.0, 1.0), uniform(random, 0.0, 0.5));
    case 4:
      return scenes::heavy_on_light(uniform(random, 1.0, 1e4));
    default:
      return scenes::newtons_cradle(2 + pick(random, 4));
  }
}

void draw_settings(Random& random, WorldSettings& s)
{
  const Toggle toggles[] = {Toggle::Auto, Toggle::On, Toggle::Off};
  s.soft_step = pick(random, 2) == 0;
  s.substeps = 1 + pick(random, 4);
  s.soft_iterations = 1 + pick(random, 2);
  s.sleeping = toggles[pick(random, 3)];
  s.time_of_impact = toggles[pick(random, 3)];
  s.warm_starting = toggles[pick(random, 3)];
  s.contact_reuse_distance = pick(random, 2) == 0 ? 0.0 : s.contact_reuse_distance;
  s.solver_mode = pick(random, 4) == 0 ? SolverMode::Exact : SolverMode::Iterative;
}

/// The drawn settings, for a failure's message.
std::string describe(const WorldSettings& s)
{
  return std::string(s.soft_step ? "soft step" : "Fx2D") + ", substeps " + std::to_string(s.substeps) + ", passes " +
         std::to_string(s.soft_iterations) + ", sleeping " + to_text(s.sleeping) + ", time of impact " +
         to_text(s.time_of_impact) + ", warm starting " + to_text(s.warm_starting) + ", reuse " +
         number_text(s.contact_reuse_distance) + " m, " + to_text(s.solver_mode);
}

/// One edit or step, the same on both worlds.
void edit(Random& random, World& one, World& two, std::string& log)
{
  const std::vector<BodyId> ids = one.body_ids();
  const BodyId id = ids[static_cast<std::size_t>(pick(random, static_cast<int>(ids.size())))];
  const auto both = [&](auto change) {
    change(one);
    change(two);
  };
  switch (pick(random, 6))
  {
    case 0:
    case 1:
    {
      const int frames = 1 + pick(random, 20);
      log += " step " + std::to_string(frames);
      both([frames](World& w) { w.step(frames); });
      return;
    }
    case 2:
    {
      const Vec2 v{uniform(random, -kMaxEditSpeed, kMaxEditSpeed), uniform(random, -kMaxEditSpeed, kMaxEditSpeed)};
      const double omega = uniform(random, -kMaxEditSpin, kMaxEditSpin);
      log += " velocity " + std::to_string(id);
      both([&](World& w) { w.set_body_state(id, w.body(id).position(), w.body(id).theta(), v, omega); });
      return;
    }
    case 3:
    {
      const BodyType type = static_cast<BodyType>(pick(random, 3));
      log += " type " + std::to_string(id) + "->" + std::to_string(static_cast<int>(type));
      both([&](World& w) { w.set_body_type(id, type); });
      return;
    }
    case 4:
      if (ids.size() > 1)
      {
        log += " remove " + std::to_string(id);
        both([id](World& w) { w.remove_body(id); });
      }
      return;
    default:
    {
      const Body disk(uniform(random, 0.5, 2.0), uniform(random, 0.1, 0.5),
                      {uniform(random, -3.0, 3.0), uniform(random, 0.5, 6.0)}, {0.0, 0.0});
      log += " add";
      both([&](World& w) { w.add_body(disk); });
      return;
    }
  }
}

/// A copy with a body thrown at 1e308 m/s under 1e308 m/s^2 for a frame of
/// 1 s: unless a contact stops the body in time, the step overflows, and the
/// world must then be left exactly as it was. True if the step was refused.
bool refused_step_changes_nothing(const World& world, const std::string& log)
{
  const std::vector<BodyId> ids = world.body_ids();
  const auto dynamic = std::find_if(ids.begin(), ids.end(),
                                    [&](BodyId id) { return world.body(id).type() == BodyType::Dynamic; });
  if (dynamic == ids.end())
  {
    return false;
  }
  World thrown = world;
  WorldSettings settings = thrown.settings();
  settings.gravity = {0.0, -1e308};
  settings.dt = 1.0;
  thrown.set_settings(settings);
  const Body& body = thrown.body(*dynamic);
  thrown.set_body_state(*dynamic, body.position(), body.theta(), {0.0, -1e308}, 0.0);
  const std::uint64_t before = test::state_hash(thrown);
  try
  {
    thrown.step();
  }
  catch (const std::overflow_error&)
  {
    EXPECT_EQ(test::state_hash(thrown), before) << "the refused step changed the world:" << log;
    return true;
  }
  return false;
}

TEST(WorldEditSequences, WorkersSnapshotsAndRefusedStepsKeepEveryBit)
{
  const long sequences = test::sized(300, 100, "edit sequences");
  long refused = 0;
  for (long seed = 0; seed < sequences; ++seed)
  {
    Random random(static_cast<std::uint64_t>(seed));
    Scene scene = draw_scene(random);
    draw_settings(random, scene.settings);
    World one = make_world(scene);
    scene.settings.workers = 2;
    World two = make_world(scene);
    std::string log = " seed " + std::to_string(seed) + ", " + scene.name + " (" + describe(scene.settings) + "):";
    for (int k = 0; k < kEditsPerSequence; ++k)
    {
      edit(random, one, two, log);
      ASSERT_EQ(test::state_hash(one), test::state_hash(two)) << "1 and 2 workers differ after" << log;
      World original = one;
      World resumed = test::rebuilt(one);
      for (int frame = 0; frame < kResumeFrames; ++frame)
      {
        original.step();
        resumed.step();
      }
      ASSERT_EQ(test::state_hash(resumed), test::state_hash(original)) << "the rebuilt world differs after" << log;
    }
    refused += refused_step_changes_nothing(one, log) ? 1 : 0;
  }
  // Most sequences end with a body that nothing stops before it overflows.
  test::print_figure("sequences whose thrown copy was refused", static_cast<double>(refused),
                     static_cast<double>(sequences / 2));
  EXPECT_GT(refused, sequences / 2);
}

}  // namespace
}  // namespace collision2d
