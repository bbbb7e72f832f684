// The settings tables (world_settings.h, resolve_settings.h): every field
// validates, survives a scene file, and former names load with a warning.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_file.h"
#include "collision2d/world.h"
#include "settings_test_support.h"

namespace collision2d
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(SettingsTable, DefaultsAndOffDefaultValuesAreValid)
{
  EXPECT_NO_THROW(validate_world_settings(WorldSettings()));
  EXPECT_NO_THROW(validate_world_settings(test::world_settings_off_default()));
  EXPECT_NO_THROW(validate_resolve_settings(ResolveSettings()));
  EXPECT_NO_THROW(validate_resolve_settings(test::resolve_settings_off_default()));
  test::expect_every_world_setting_differs(test::world_settings_off_default(), WorldSettings());
  test::expect_every_resolve_setting_differs(test::resolve_settings_off_default(), ResolveSettings());
}

/// Index of each field whose range has a bound, with a value beyond it.
struct BadValueOf
{
  explicit BadValueOf(std::size_t field) : target(field) {}

  std::size_t target;
  std::size_t index = 0;
  std::string name;  ///< set when the target field took a bad value

  void bad(const SettingInfo& info, double& v)
  {
    if (index++ == target)
    {
      v = std::isfinite(info.range.min) ? info.range.min - (info.range.min_exclusive ? 0.0 : 1.0) : kNaN;
      name = info.name;
    }
  }
  void operator()(const SettingInfo& info, double& v) { bad(info, v); }
  void operator()(const SettingInfo& info, int& v)
  {
    double d = v;
    bad(info, d);
    v = std::isfinite(d) ? static_cast<int>(d) : v;
  }
  void operator()(const SettingInfo& info, Vec2& v)
  {
    if (index++ == target)
    {
      v.y = kNaN;
      name = info.name;
    }
  }
  template <typename T>
  void operator()(const SettingInfo&, T&)
  {
    ++index;  // any value of a flag, choice or count is valid
  }
};

TEST(SettingsTable, EachOutOfRangeWorldSettingIsRefusedByName)
{
  std::size_t refused = 0;
  for (std::size_t field = 0;; ++field)
  {
    WorldSettings settings;
    BadValueOf visitor(field);
    visit_world_settings(settings, visitor);
    if (field >= visitor.index)
    {
      break;
    }
    if (visitor.name.empty())
    {
      continue;
    }
    SCOPED_TRACE(visitor.name);
    try
    {
      World::validate(settings);
      ADD_FAILURE() << "accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("WorldSettings." + visitor.name + " must be ", 0), 0u) << e.what();
      ++refused;
    }
  }
  // gravity, dt, substeps, velocity_iterations, slop, compliance,
  // restitution_threshold, toi_displacement_fraction, three sleep thresholds,
  // position_iterations, the soft step's contact_hertz,
  // contact_damping_ratio, soft_iterations, contact_push_speed,
  // speculative_margin and contact_reuse_distance, and workers have bounds or
  // must be finite.
  EXPECT_EQ(refused, 19u);
}

TEST(SettingsTable, ValidationMessagesKeepTheirWording)
{
  WorldSettings settings;
  settings.dt = -1.0;
  EXPECT_THROW(validate_world_settings(settings), std::invalid_argument);
  try
  {
    validate_world_settings(settings);
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_STREQ(e.what(), "WorldSettings.dt must be finite and > 0 (got -1)");
  }
  settings = WorldSettings();
  settings.substeps = 0;
  try
  {
    validate_world_settings(settings);
    ADD_FAILURE() << "substeps 0 accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_STREQ(e.what(), "WorldSettings.substeps must be >= 1 (got 0)");
  }
  ResolveSettings resolve;
  resolve.iterations = 100001;
  try
  {
    validate_resolve_settings(resolve);
    ADD_FAILURE() << "iterations 100001 accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_STREQ(e.what(), "ResolveSettings.iterations must be in [1, 100000] (got 100001)");
  }
}

TEST(SettingsTable, ContactSolverTakesEveryResolveSetting)
{
  const ResolveSettings s = test::resolve_settings_off_default();
  const ContactSolver solver = make_contact_solver(s);
  EXPECT_EQ(solver.restitution(), s.restitution);
  EXPECT_EQ(solver.friction(), s.friction);
  EXPECT_EQ(solver.max_iterations(), s.iterations);
  EXPECT_EQ(solver.tolerance(), s.tolerance);
  EXPECT_EQ(solver.bias_factor(), s.bias_factor);
  EXPECT_EQ(solver.slop(), s.slop);
  EXPECT_EQ(solver.mode(), s.mode);
}

TEST(SettingsTable, SceneFileRoundTripKeepsEveryField)
{
  Scene scene;
  scene.settings = test::world_settings_off_default();
  const Scene back = scenes::parse_scene_yaml(scenes::scene_to_yaml(scene), "round_trip");
  test::expect_same_world_settings(scene.settings, back.settings);
}

// A table of former names as later versions will have one.
const std::vector<FormerSetting> kFormerForTest = {
    {"iterations_per_substep", "velocity_iterations", "renamed in a test"},
    {"contact_hertz", "", ""},
};

TEST(SettingsTable, RenamedSettingIsReadUnderItsNewNameWithAWarning)
{
  std::vector<std::string> warnings;
  scenes::SceneReading reading;
  reading.warnings = &warnings;
  reading.former = &kFormerForTest;
  const Scene scene = scenes::parse_scene_yaml("settings:\n  iterations_per_substep: 7\n", "old.yaml", reading);
  EXPECT_EQ(scene.settings.velocity_iterations, 7);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "old.yaml: settings.iterations_per_substep is the former name of velocity_iterations: read as "
            "velocity_iterations (renamed in a test)");
}

TEST(SettingsTable, RetiredSettingIsIgnoredWithAWarningAndTheNewNameWins)
{
  std::vector<std::string> warnings;
  scenes::SceneReading reading;
  reading.warnings = &warnings;
  reading.former = &kFormerForTest;
  const Scene scene = scenes::parse_scene_yaml(
      "settings:\n  contact_hertz: 30\n  velocity_iterations: 5\n  iterations_per_substep: 9\n", "old.yaml", reading);
  EXPECT_EQ(scene.settings.velocity_iterations, 5);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "old.yaml: settings.iterations_per_substep is the former name of velocity_iterations, which "
                         "the file also sets: ignored (renamed in a test)");
  EXPECT_EQ(warnings[1], "old.yaml: settings.contact_hertz is retired and ignored");
}

TEST(SettingsTable, UnknownKeysStillFailAndWarningsGoToTheHandler)
{
  scenes::SceneReading reading;
  reading.former = &kFormerForTest;
  EXPECT_THROW(scenes::parse_scene_yaml("settings:\n  iterations_per_substepp: 7\n", "old.yaml", reading),
               std::runtime_error);
  std::vector<std::string> handled;
  scenes::set_warning_handler([&](const std::string& message) { handled.push_back(message); });
  scenes::parse_scene_yaml("settings:\n  contact_hertz: 30\n", "old.yaml", reading);
  scenes::set_warning_handler(nullptr);
  ASSERT_EQ(handled.size(), 1u);
  EXPECT_EQ(handled[0], "old.yaml: settings.contact_hertz is retired and ignored");
}

/// True when former_world_settings() lists `name` as retired.
bool listed_as_retired(const std::string& name)
{
  for (const FormerSetting& former : former_world_settings())
  {
    if (former.name == name)
    {
      return std::string(former.replacement).empty();
    }
  }
  return false;
}

TEST(SettingsTable, RetiredWarmStartKnobsLoadWithAWarningAndChangeNothing)
{
  // Files of earlier versions may name them; the Fx2D step they acted in.
  const std::string head = "settings:\n  soft_step: false\n";
  const std::string tail = "generate:\n  - pyramid: {base: 4}\n";
  const Scene without = scenes::parse_scene_yaml(head + tail, "new.yaml");
  const std::pair<std::string, std::string> retired[] = {{"warm_start_factor", "0.9"},
                                                         {"warm_start_every_substep", "false"}};
  for (const auto& [name, value] : retired)
  {
    SCOPED_TRACE(name);
    EXPECT_TRUE(listed_as_retired(name));
    std::vector<std::string> warnings;
    scenes::SceneReading reading;  // the real former_world_settings()
    reading.warnings = &warnings;
    const Scene with = scenes::parse_scene_yaml(head + "  " + name + ": " + value + "\n" + tail, "old.yaml", reading);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].rfind("old.yaml: settings." + name + " is retired and ignored (", 0), 0u) << warnings[0];
    test::expect_same_world_settings(with.settings, without.settings);
    EXPECT_EQ(scenes::scene_to_yaml(with), scenes::scene_to_yaml(without));
    World a = make_world(with);
    World b = make_world(without);
    for (int frame = 0; frame < 30; ++frame)
    {
      a.step();
      b.step();
    }
    for (BodyId id : b.body_ids())
    {
      EXPECT_EQ(a.body(id).position(), b.body(id).position()) << "body " << id;
      EXPECT_EQ(a.body(id).theta(), b.body(id).theta()) << "body " << id;
    }
  }
}

TEST(SettingsTable, FormerNamesAreNotCurrentNames)
{
  ASSERT_FALSE(former_world_settings().empty());
  for (const FormerSetting& former : former_world_settings())
  {
    bool current = false;
    bool replacement_exists = std::string(former.replacement).empty();
    const WorldSettings defaults;
    visit_world_settings(defaults, [&](const SettingInfo& info, const auto&) {
      current = current || info.name == std::string(former.name);
      replacement_exists = replacement_exists || info.name == std::string(former.replacement);
    });
    EXPECT_FALSE(current) << former.name;
    EXPECT_TRUE(replacement_exists) << former.replacement;
  }
}

}  // namespace
}  // namespace collision2d
