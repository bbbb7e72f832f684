// The settings tables against their ROS faces, without a master: the
// messages, the cfg's parameters and their defaults match the tables, every
// field survives each conversion both ways, an out-of-range reconfigure value
// is refused (named, with its range) and the old value put back, and a request
// changes only the fields its client changed.
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/message_traits.h>

#include "../unit/settings_test_support.h"
#include "collision2d/ros/reconfigure.h"
#include "collision2d/ros/settings_conversions.h"
#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string refusal(const std::function<void()>& call)
{
  try
  {
    call();
  }
  catch (const InvalidRequest& e)
  {
    return e.what();
  }
  return "";
}

/// Edits `world` the way the node's WorldService does: all or nothing.
WorldSettingsEditor editor(WorldSettings& world)
{
  return [&world](const auto& change) {
    world = change(world);
    return world;
  };
}

TEST(SettingsTables, CfgDeclaresExactlyTheTablesParameters)
{
  std::vector<std::string> cfg;
  for (const auto& description : Collision2dConfig::__getParamDescriptions__())
  {
    cfg.push_back(description->name);
  }
  const std::vector<std::string> table = table_parameter_names();
  EXPECT_EQ(std::set<std::string>(cfg.begin(), cfg.end()), std::set<std::string>(table.begin(), table.end()));
  EXPECT_EQ(cfg.size(), table.size());
  EXPECT_EQ(table.size(), 8u + 33u) << "8 solver fields, 32 world fields, gravity as two";
}

TEST(SettingsTables, CfgDefaultsAreTheTablesDefaults)
{
  const Collision2dConfig defaults = Collision2dConfig::__getDefault__();
  test::expect_same_world_settings(world_settings_from_config(defaults), WorldSettings());
  test::expect_same_resolve_settings(resolve_settings_from_config(defaults), ResolveSettings());
}

TEST(SettingsTables, CfgNeverClamps)
{
  // Limits as wide as the types: the node sees the value the user sent.
  const Collision2dConfig& min = Collision2dConfig::__getMin__();
  const Collision2dConfig& max = Collision2dConfig::__getMax__();
  EXPECT_EQ(min.world_dt, -kInf);
  EXPECT_EQ(max.solver_restitution, kInf);
  EXPECT_EQ(min.solver_tolerance, -kInf);
  EXPECT_EQ(min.world_substeps, std::numeric_limits<int>::min());
  EXPECT_EQ(max.world_rotation, std::numeric_limits<int>::max());
  Collision2dConfig config = Collision2dConfig::__getDefault__();
  config.world_dt = -1.0;
  config.solver_restitution = 1.5;
  config.world_substeps = 0;
  config.__clamp__();
  EXPECT_EQ(config.world_dt, -1.0);
  EXPECT_EQ(config.solver_restitution, 1.5);
  EXPECT_EQ(config.world_substeps, 0);
}

TEST(SettingsTables, EveryWorldFieldSurvivesTheMessageAndTheConfig)
{
  const WorldSettings settings = test::world_settings_off_default();
  test::expect_same_world_settings(world_settings_from_msg(world_settings_to_msg(settings)), settings);
  Collision2dConfig config = Collision2dConfig::__getDefault__();
  world_settings_to_config(settings, config);
  test::expect_same_world_settings(world_settings_from_config(config), settings);
}

TEST(SettingsTables, EveryResolveFieldSurvivesTheMessageAndTheConfig)
{
  const ResolveSettings settings = test::resolve_settings_off_default();
  const SolverSettings msg = resolve_settings_to_msg(settings);
  EXPECT_FALSE(msg.use_node_settings);
  test::expect_same_resolve_settings(resolve_settings_from_msg(msg), settings);
  Collision2dConfig config = Collision2dConfig::__getDefault__();
  resolve_settings_to_config(settings, config);
  test::expect_same_resolve_settings(resolve_settings_from_config(config), settings);
}

/// A field line "<type> <name>" followed by a space, comment or line end.
bool declares(const std::string& definition, const std::string& name)
{
  for (std::size_t at = definition.find(" " + name); at != std::string::npos;
       at = definition.find(" " + name, at + 1))
  {
    const std::size_t end = at + 1 + name.size();
    if (end == definition.size() || definition[end] == ' ' || definition[end] == '\n')
    {
      return true;
    }
  }
  return false;
}

TEST(SettingsTables, MessagesDeclareEveryFieldByItsName)
{
  const std::string world = ros::message_traits::Definition<WorldConfig>::value();
  const std::string solver = ros::message_traits::Definition<SolverSettings>::value();
  const WorldSettings w;
  visit_world_settings(w, [&](const SettingInfo& info, const auto&) {
    EXPECT_TRUE(declares(world, info.name)) << info.name;
  });
  const ResolveSettings r;
  visit_resolve_settings(r, [&](const SettingInfo& info, const auto&) {
    EXPECT_TRUE(declares(solver, info.name)) << info.name;
  });
}

TEST(SettingsTables, ConfigRefusalsNameTheParameterValueAndRange)
{
  Collision2dConfig config = Collision2dConfig::__getDefault__();
  config.world_dt = -1.0;
  EXPECT_EQ(refusal([&] { world_settings_from_config(config); }),
            "dynamic_reconfigure: world_dt = -1 is outside (0, inf)");
  config = Collision2dConfig::__getDefault__();
  config.world_rotation = 5;
  EXPECT_EQ(refusal([&] { world_settings_from_config(config); }),
            "dynamic_reconfigure: world_rotation = 5 is outside [0, 2] (auto | on | off)");
  config = Collision2dConfig::__getDefault__();
  config.world_sleep_auto_min_bodies = -1;
  EXPECT_EQ(refusal([&] { world_settings_from_config(config); }),
            "dynamic_reconfigure: world_sleep_auto_min_bodies = -1 is outside [0, inf)");
  config = Collision2dConfig::__getDefault__();
  config.solver_iterations = 0;
  EXPECT_EQ(refusal([&] { resolve_settings_from_config(config); }),
            "dynamic_reconfigure: solver_iterations = 0 is outside [1, 100000]");
}

TEST(SettingsTables, RefusedConfigPutsWhatTheServerShowedBack)
{
  WorldSettings world;
  world.dt = 0.01;
  Collision2dConfig shown = Collision2dConfig::__getDefault__();
  world_settings_to_config(world, shown);
  Collision2dConfig config = shown;
  config.world_dt = -1.0;
  config.world_substeps = 9;  // valid, but the change is all or nothing
  const WorldSettings before = world;
  accept_world_config(config, shown, editor(world));
  EXPECT_EQ(world.dt, before.dt);
  EXPECT_EQ(world.substeps, before.substeps);
  EXPECT_EQ(config.world_dt, 0.01);
  EXPECT_EQ(config.world_substeps, before.substeps);

  ResolveSettings kept = test::resolve_settings_off_default();
  resolve_settings_to_config(kept, config);
  config.solver_restitution = 1.5;
  const SolverSettings result = accept_solver_config(config, resolve_settings_to_msg(kept));
  test::expect_same_resolve_settings(resolve_settings_from_msg(result), kept);
  EXPECT_EQ(config.solver_restitution, kept.restitution);
  // A valid change goes through.
  config.solver_restitution = 0.125;
  EXPECT_EQ(accept_solver_config(config, resolve_settings_to_msg(kept)).restitution, 0.125);
}

// A request changes only the fields its client changed: a scene loaded after
// the client read the config keeps every other setting it brought.
TEST(SettingsTables, AReconfigureRequestChangesOnlyWhatItsClientChanged)
{
  WorldSettings old_scene;
  old_scene.dt = 0.02;
  old_scene.gravity = Vec2{0.0, -9.81};
  Collision2dConfig shown = Collision2dConfig::__getDefault__();
  world_settings_to_config(old_scene, shown);
  Collision2dConfig config = shown;
  config.world_substeps = old_scene.substeps + 3;
  config.world_gravity_x = 1.5;

  WorldSettings loaded;  // what a scene load put in place meanwhile
  loaded.dt = 0.005;
  loaded.gravity = Vec2{0.0, -1.62};
  loaded.sleeping = Toggle::Off;
  WorldSettings expected = loaded;
  expected.substeps = old_scene.substeps + 3;
  expected.gravity.x = 1.5;

  const WorldSettings merged = merge_world_config(config, shown, loaded);
  test::expect_same_world_settings(merged, expected);
  // Nothing asked, nothing changed.
  test::expect_same_world_settings(merge_world_config(shown, shown, loaded), loaded);

  WorldSettings world = loaded;
  accept_world_config(config, shown, editor(world));
  test::expect_same_world_settings(world, expected);
  EXPECT_EQ(config.world_dt, loaded.dt);  // the config shows what is in force
  EXPECT_EQ(config.world_substeps, expected.substeps);

  // Refused in the same window: the world keeps the loaded settings, and the
  // config what the server showed until the load's own update replaces it.
  world = loaded;
  Collision2dConfig refused = shown;
  refused.world_substeps = 0;
  accept_world_config(refused, shown, editor(world));
  test::expect_same_world_settings(world, loaded);
  EXPECT_EQ(refused.world_substeps, shown.world_substeps);
  EXPECT_EQ(refused.world_dt, shown.world_dt);
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
