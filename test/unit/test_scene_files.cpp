// Scene files: the shipped YAML scenes equal their builders, exact save/load
// and World round trips, and the YAML reader's errors naming line and key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_file.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "scene_test_support.h"

namespace collision2d
{
namespace
{
namespace fs = std::filesystem;
using scenes::make_standard_scene;
using scenes::standard_scene_names;
using test::expect_same_body;
using test::expect_same_material;
using test::expect_same_scene;
using test::expect_same_settings;

fs::path repo_root()
{
  // test/unit/test_scene_files.cpp -> repository root, wherever the binary runs.
  return fs::path(__FILE__).parent_path().parent_path().parent_path();
}

std::string scene_dir()
{
  return (repo_root() / "config" / "scenes").string();
}

// ---------------------------------------------------------------------------
// Shipped scene files

TEST(SceneFiles, EveryShippedSceneEqualsItsBuilderBodyForBody)
{
  const std::vector<std::string> names = standard_scene_names();
  for (const std::string& name : names)
  {
    SCOPED_TRACE(name);
    expect_same_scene(make_standard_scene(name), scenes::load_named_scene(name, scene_dir()));
  }
  const std::vector<std::string> listed = scenes::list_scenes(scene_dir());
  for (const std::string& name : names)
  {
    EXPECT_NE(std::find(listed.begin(), listed.end(), name), listed.end()) << name;
  }
}

TEST(SceneFiles, UnknownNamedSceneListsTheKnownOnes)
{
  try
  {
    scenes::load_named_scene("piramid", scene_dir());
    FAIL() << "no exception";
  }
  catch (const std::runtime_error& error)
  {
    const std::string message = error.what();
    EXPECT_NE(message.find("unknown scene 'piramid'"), std::string::npos) << message;
    EXPECT_NE(message.find("known: "), std::string::npos) << message;
    EXPECT_NE(message.find("pyramid"), std::string::npos) << message;
  }
  // A path is not a name.
  EXPECT_THROW(scenes::load_named_scene("../scenes/pyramid", scene_dir()), std::runtime_error);
}

// ---------------------------------------------------------------------------
// Round trips

class TempFile
{
public:
  explicit TempFile(const std::string& name) : path_(fs::temp_directory_path() / name) {}
  ~TempFile() { std::remove(path_.string().c_str()); }
  std::string path() const { return path_.string(); }

private:
  fs::path path_;
};

TEST(SceneFiles, SaveThenLoadIsExactForEveryStandardScene)
{
  const TempFile file("collision2d_test_scenes_round_trip.yaml");
  for (const std::string& name : standard_scene_names())
  {
    SCOPED_TRACE(name);
    const Scene scene = make_standard_scene(name);
    scenes::save_scene_file(scene, file.path());
    expect_same_scene(scene, scenes::load_scene_file(file.path()));
  }
}

TEST(SceneFiles, SaveThenLoadKeepsEverySettingTypeAndAwkwardNumber)
{
  Scene scene;
  scene.name = "odd \"name\" \\ here";
  WorldSettings& s = scene.settings;
  s.gravity = Vec2{0.1, -1.0 / 3.0};
  s.dt = 1.0 / 240.0;
  s.substeps = 7;
  s.velocity_iterations = 9;
  s.slop = 2.5e-4;
  s.compliance = 3e-9;
  s.restitution_threshold = 0.02;
  s.rotation = Toggle::Off;
  s.friction = Toggle::On;
  s.restitution = Toggle::Off;
  s.position_correction = Toggle::On;
  s.time_of_impact = Toggle::On;
  s.warm_starting = Toggle::Off;
  s.sleeping = Toggle::On;
  s.toi_displacement_fraction = 0.3;
  s.sleep_linear_speed = 0.01;
  s.sleep_angular_speed = 0.02;
  s.sleep_time = 1.5;
  s.sleep_auto_min_bodies = 12345678901ULL;
  s.position_iterations = 3;
  s.position_block = !WorldSettings().position_block;
  s.solver_mode = SolverMode::Exact;
  s.exact_position_correction = false;
  s.warm_start_before_integration = !WorldSettings().warm_start_before_integration;
  Body disk(0.7, 0.123456789, {1e-300, -2.0 / 7.0}, {1.0 / 3.0, 0.0}, -4.5);
  disk.set_theta(1.0 / 9.0);
  scene.bodies.push_back(SceneBody{disk, Material{0.3, 0.2, 0.1}, "disk: with colon"});
  Body kinematic = scenes::make_box(3.0, 0.3, 0.7, {2.0, 1.0}, 0.25, {0.0, 1.0}, 0.5);
  kinematic.set_type(BodyType::Kinematic);
  scene.bodies.push_back(SceneBody{kinematic, Material{1.0, 0.9, 0.8}, ""});
  const Body triangle(1.5, std::vector<Vec2>{{0.1, 0.2}, {1.3, 0.1}, {0.7, 1.9}}, {0.3, 0.1}, {}, 0.3);
  scene.bodies.push_back(SceneBody{triangle, Material{0.3, 0.2, 0.1}, "triangle"});

  const Scene back = scenes::parse_scene_yaml(scenes::scene_to_yaml(scene), "round_trip");
  // A general polygon is recentred again on loading (scene_yaml_write.cpp).
  constexpr double kRecentringRoundOff = 1e-15;  // m
  expect_same_scene(scene, back, kRecentringRoundOff);
  expect_same_body(scene.bodies[0], back.bodies[0], "disk");
  expect_same_body(scene.bodies[1], back.bodies[1], "box");
}

TEST(SceneFiles, CollisionScenarioLoadsWithOneMaterialAndNoGravity)
{
  const TempFile file("collision2d_test_scenes.collision");
  {
    std::ofstream out(file.path());
    out << "# two disks\nbody 1 0.5 0 0 1 0\nbody 2 0.5 2 0 0 0\nrestitution 0.5\nfriction 0.25\n";
  }
  const Scene scene = scenes::load_scene_file(file.path());
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.settings.gravity, Vec2{});
  EXPECT_EQ(scene.bodies[1].body.mass(), 2.0);
  EXPECT_EQ(scene.bodies[0].body.velocity(), (Vec2{1.0, 0.0}));
  for (const SceneBody& entry : scene.bodies)
  {
    expect_same_material(entry.material, Material{0.5, 0.25, 0.25}, "collision body");
  }
  EXPECT_EQ(scene.name, "collision2d_test_scenes");
}

TEST(SceneFiles, WorldRoundTripKeepsBodiesMaterialsAndSettings)
{
  Scene scene = scenes::demo();
  scene.settings.substeps = 6;
  const Scene back = to_scene(make_world(scene), scene.name);
  ASSERT_EQ(back.bodies.size(), scene.bodies.size());
  expect_same_settings(scene.settings, back.settings);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    SceneBody expected = scene.bodies[i];
    expected.name = "";  // a world keeps no names
    expect_same_body(expected, back.bodies[i], "body " + std::to_string(i));
  }
}

// ---------------------------------------------------------------------------
// Errors: every one names the source, the line and the key.

struct BadScene
{
  const char* text;
  int line;
  const char* key;
  const char* message;
};

TEST(SceneFiles, EveryErrorNamesTheLineAndTheKey)
{
  const BadScene cases[] = {
      {"name: x\ngravty: [0, 1]\n", 2, "gravty", "unknown key"},
      {"gravity: [0, x]\n", 1, "gravity[1]", "must be a number"},
      {"gravity: [0]\n", 1, "gravity", "pair"},
      {"settings:\n  dt: 0.01\n  substeps: 0\n", 3, "settings.substeps", "at least 1"},
      {"settings:\n  friction: maybe\n", 2, "settings.friction", "auto, on or off"},
      {"settings:\n  dt: -1\n", 2, "settings.dt", "must be positive"},
      {"settings:\n  contact_push_speed: 0\n", 2, "settings.contact_push_speed", "must be positive"},
      {"settings:\n  gravity: [0, 1]\n", 2, "settings.gravity", "unknown key"},
      {"settings:\n  position_iterations: 0\n", 2, "settings.position_iterations", "at least 1"},
      {"settings:\n  solver_mode: pivoting\n", 2, "settings.solver_mode", "iterative or exact"},
      {"settings:\n  exact_position_correction: yes\n", 2, "settings.exact_position_correction", "true or false"},
      {"materials:\n  a: {restitution: 2}\n", 2, "materials.a.restitution", "[0, 1]"},
      {"materials:\n  a: {restitutoin: 0.5}\n", 2, "materials.a.restitutoin", "unknown key"},
      {"bodies:\n  - {shape: disk, mass: 1, radius: 1}\n  - {shape: disk, mass: -1, radius: 1}\n", 3,
       "bodies[1].mass", "must be positive"},
      {"bodies:\n  - shape: disk\n    radius: 1\n", 2, "bodies[0].mass", "missing"},
      {"bodies:\n  - shape: box\n    mass: 1\n    size: [1, 1]\n    radius: 2\n", 5, "bodies[0].radius",
       "unknown key"},
      {"bodies:\n  - {shape: hexagon, mass: 1}\n", 2, "bodies[0].shape", "disk, polygon or box"},
      {"bodies:\n  - {shape: disk, type: floating, mass: 1, radius: 1}\n", 2, "bodies[0].type", "dynamic, static"},
      {"bodies:\n  - {shape: disk, mass: 1, radius: 1, material: nope}\n", 2, "bodies[0].material",
       "unknown material"},
      {"bodies:\n  - {shape: disk, mass: 1, radius: 1, mass: 2}\n", 2, "bodies[0].mass", "duplicate key"},
      {"bodies:\n  - {shape: disk, type: static, radius: 1, velocity: [1, 0]}\n", 2, "bodies[0].velocity",
       "static body cannot move"},
      {"bodies:\n  -\n    shape: polygon\n    mass: 1\n    vertices: [[0, 0], [0, 1], [1, 0]]\n", 3, "bodies[0]",
       "counter-clockwise"},
      {"generate:\n  - pyramd: {base: 3}\n", 2, "generate[0].pyramd", "unknown generator"},
      {"generate:\n  - pyramid: {base: 0}\n", 2, "generate[0].pyramid.base", "at least 1"},
      {"generate:\n  - pyramid: {bsae: 3}\n", 2, "generate[0].pyramid.bsae", "unknown key"},
      {"generate:\n  - gas: {count: 100, radius: 5}\n", 2, "generate[0].gas", "do not fit"},
      {"generate:\n  - gas: {seed: -1}\n", 2, "generate[0].gas.seed", "non-negative integer"},
      // Limits: a few bytes must not ask for billions of bodies or substeps.
      {"generate:\n  - pyramid: {base: 100000}\n", 2, "generate[0].pyramid.base", "larger than"},
      {"generate:\n  - gas: {count: 2000000}\n", 2, "generate[0].gas.count", "larger than"},
      {"settings:\n  substeps: 1000000000\n", 2, "settings.substeps", "at most"},
      {"settings:\n  velocity_iterations: 1000000\n", 2, "settings.velocity_iterations", "at most"},
      {"bodies: {shape: disk}\n", 1, "bodies", "must be a list"},
      {"name: x\nbodies: [1, 2\n", 3, "", "YAML syntax"},
  };
  for (const BadScene& c : cases)
  {
    SCOPED_TRACE(c.text);
    try
    {
      scenes::parse_scene_yaml(c.text, "scenes/bad.yaml");
      ADD_FAILURE() << "no exception";
    }
    catch (const std::runtime_error& error)
    {
      const std::string message = error.what();
      const std::string where = "scenes/bad.yaml:" + std::to_string(c.line) + ": " + c.key;
      EXPECT_EQ(message.rfind(where, 0), 0u) << message << "\nexpected to start with: " << where;
      EXPECT_NE(message.find(c.message), std::string::npos) << message;
    }
  }
}

TEST(SceneFiles, FileErrorsNameTheFile)
{
  EXPECT_THROW(scenes::load_scene_file("/nonexistent/x.yaml"), std::runtime_error);
  EXPECT_THROW(scenes::load_scene_file("scene.txt"), std::runtime_error);
  EXPECT_THROW(scenes::list_scenes("/nonexistent/dir"), std::runtime_error);
}

}  // namespace
}  // namespace collision2d
