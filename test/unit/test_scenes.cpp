// The standard scene builders, the shipped YAML scenes, the YAML reader's
// errors and exact save/load round trips.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/scene_file.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "settings_test_support.h"

namespace collision2d
{
namespace
{
namespace fs = std::filesystem;
using scenes::make_standard_scene;
using scenes::standard_scene_names;

/// Overlap allowed between bodies a builder places exactly touching: the
/// round-off of rotating a box onto a tilted slab (m).
constexpr double kTouchingOverlap = 1e-12;
/// Gap still counted as touching when looking for resting contacts (relative).
constexpr double kTouchTolerance = 1e-9;

fs::path repo_root()
{
  // test/unit/test_scenes.cpp -> repository root, wherever the binary runs.
  return fs::path(__FILE__).parent_path().parent_path().parent_path();
}

std::string scene_dir()
{
  return (repo_root() / "config" / "scenes").string();
}

std::vector<Body> bodies_of(const Scene& scene)
{
  std::vector<Body> bodies;
  for (const SceneBody& entry : scene.bodies)
  {
    bodies.push_back(entry.body);
  }
  return bodies;
}

double largest_overlap(const Scene& scene)
{
  double deepest = 0.0;
  for (const Contact& c : ContactSolver::detect_contacts(bodies_of(scene)))
  {
    deepest = std::max(deepest, c.penetration);
  }
  return deepest;
}

/// Distinct body pairs that touch or overlap.
std::size_t touching_pairs(const Scene& scene)
{
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const Contact& c : ContactSolver::detect_contacts(bodies_of(scene), kTouchTolerance))
  {
    pairs.emplace_back(c.a, c.b);
  }
  std::sort(pairs.begin(), pairs.end());
  return static_cast<std::size_t>(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
}

std::size_t count_type(const Scene& scene, BodyType type)
{
  return static_cast<std::size_t>(std::count_if(scene.bodies.begin(), scene.bodies.end(),
                                                [type](const SceneBody& e) { return e.body.type() == type; }));
}

void expect_same_material(const Material& a, const Material& b, const std::string& where)
{
  EXPECT_EQ(a.restitution, b.restitution) << where;
  EXPECT_EQ(a.static_friction, b.static_friction) << where;
  EXPECT_EQ(a.kinetic_friction, b.kinetic_friction) << where;
}

/// Bit-for-bit equality of everything a body carries (vertices within
/// `vertex_tolerance`, see scene_yaml_write.cpp on recentring).
void expect_same_body(const SceneBody& a, const SceneBody& b, const std::string& where,
                      double vertex_tolerance = 0.0)
{
  EXPECT_EQ(a.name, b.name) << where;
  EXPECT_EQ(a.body.shape(), b.body.shape()) << where;
  EXPECT_EQ(a.body.type(), b.body.type()) << where;
  EXPECT_EQ(a.body.mass(), b.body.mass()) << where;
  EXPECT_EQ(a.body.position(), b.body.position()) << where;
  EXPECT_EQ(a.body.velocity(), b.body.velocity()) << where;
  EXPECT_EQ(a.body.theta(), b.body.theta()) << where;
  EXPECT_EQ(a.body.omega(), b.body.omega()) << where;
  ASSERT_EQ(a.body.vertex_count(), b.body.vertex_count()) << where;
  if (vertex_tolerance == 0.0)
  {
    EXPECT_EQ(a.body.radius(), b.body.radius()) << where;
    EXPECT_EQ(a.body.inertia(), b.body.inertia()) << where;
  }
  for (std::size_t i = 0; i < a.body.vertex_count(); ++i)
  {
    EXPECT_NEAR(a.body.local_vertices()[i].x, b.body.local_vertices()[i].x, vertex_tolerance) << where;
    EXPECT_NEAR(a.body.local_vertices()[i].y, b.body.local_vertices()[i].y, vertex_tolerance) << where;
  }
  expect_same_material(a.material, b.material, where);
}

void expect_same_settings(const WorldSettings& a, const WorldSettings& b)
{
  test::expect_same_world_settings(a, b);
}

void expect_same_scene(const Scene& a, const Scene& b, double vertex_tolerance = 0.0)
{
  EXPECT_EQ(a.name, b.name);
  expect_same_settings(a.settings, b.settings);
  ASSERT_EQ(a.bodies.size(), b.bodies.size()) << a.name;
  for (std::size_t i = 0; i < a.bodies.size(); ++i)
  {
    expect_same_body(a.bodies[i], b.bodies[i], a.name + " body " + std::to_string(i), vertex_tolerance);
  }
}

// ---------------------------------------------------------------------------
// Builders

TEST(StandardScenes, EveryBuilderStartsWithoutOverlapAndWithStillStaticBodies)
{
  for (const std::string& name : standard_scene_names())
  {
    const Scene scene = make_standard_scene(name);
    EXPECT_EQ(scene.name, name);
    EXPECT_LE(largest_overlap(scene), kTouchingOverlap) << name;
    for (const SceneBody& entry : scene.bodies)
    {
      if (entry.body.type() == BodyType::Static)
      {
        EXPECT_EQ(entry.body.velocity(), Vec2{}) << name << " " << entry.name;
        EXPECT_EQ(entry.body.omega(), 0.0) << name << " " << entry.name;
      }
    }
  }
}

TEST(StandardScenes, GasInAnExtremelyWideRegionIsRefusedWithoutOverflow)
{
  // Found by fuzz_scene_yaml: width / height beyond an int's range made the
  // column count overflow its cast (undefined behaviour). Capped at one
  // column per disk, the cells are far too flat for the disks: refused.
  Scene scene;
  scenes::GasParams gas;
  gas.count = 3;
  gas.lower = Vec2{0.0, 0.0};
  gas.upper = Vec2{1e300, 1e-300};
  EXPECT_THROW(scenes::add_gas(scene, gas), std::invalid_argument);
  // A wide but possible region gets one row of disks, one per column.
  gas.upper = Vec2{1e6, 1.0};
  gas.radius = 0.1;
  scenes::add_gas(scene, gas);
  ASSERT_EQ(scene.bodies.size(), 3u);
  for (const SceneBody& b : scene.bodies)
  {
    EXPECT_GT(b.body.position().x, 0.0);
    EXPECT_LT(b.body.position().x, 1e6);
  }
}

TEST(StandardScenes, UnknownNameIsRejectedByName)
{
  try
  {
    make_standard_scene("pyramids");
    FAIL() << "no exception";
  }
  catch (const std::invalid_argument& error)
  {
    EXPECT_NE(std::string(error.what()).find("unknown scene 'pyramids'"), std::string::npos) << error.what();
  }
}

TEST(StandardScenes, PyramidHasTriangularCountAndEveryBoxRestsOnSomething)
{
  for (int base : {1, 4, 20})
  {
    const Scene scene = scenes::pyramid(base);
    EXPECT_EQ(count_type(scene, BodyType::Static), 1u);
    EXPECT_EQ(count_type(scene, BodyType::Dynamic), static_cast<std::size_t>(base * (base + 1) / 2));
    // Row r (r boxes): r - 1 side-by-side pairs; every box above the bottom
    // row stands on two, each bottom box on the ground.
    std::size_t expected = 0;
    for (int row_boxes = base; row_boxes >= 1; --row_boxes)
    {
      expected += static_cast<std::size_t>(row_boxes - 1) + (row_boxes == base ? row_boxes : 2 * row_boxes);
    }
    EXPECT_EQ(touching_pairs(scene), expected) << "base " << base;
  }
}

TEST(StandardScenes, ColumnIsAStackOfTouchingBoxes)
{
  const Scene scene = scenes::column(20);
  ASSERT_EQ(scene.bodies.size(), 21u);
  EXPECT_EQ(touching_pairs(scene), 20u);  // ground-box and 19 box-box
  double top = 0.0;
  for (const SceneBody& entry : scene.bodies)
  {
    top = std::max(top, entry.body.aabb().hi.y);
  }
  EXPECT_NEAR(top, 20.0, 1e-12);
}

TEST(StandardScenes, NewtonsCradleTouchesAndOnlyTheFirstMoves)
{
  const Scene scene = scenes::newtons_cradle(5);
  ASSERT_EQ(scene.bodies.size(), 5u);
  EXPECT_EQ(scene.settings.gravity, Vec2{});
  EXPECT_EQ(touching_pairs(scene), 4u);
  EXPECT_GT(scene.bodies[0].body.velocity().x, 0.0);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    EXPECT_EQ(scene.bodies[i].material.restitution, 1.0);
    EXPECT_EQ(scene.bodies[i].material.static_friction, 0.0);
    EXPECT_EQ(scene.bodies[i].body.mass(), scene.bodies[0].body.mass());
    EXPECT_EQ(scene.bodies[i].body.radius(), scene.bodies[0].body.radius());
    if (i > 0)
    {
      EXPECT_EQ(scene.bodies[i].body.velocity(), Vec2{});
    }
  }
}

TEST(StandardScenes, InclineBoxSitsOnTheSlabFaceTurnedWithIt)
{
  const double angle = 0.3;
  const Scene scene = scenes::incline(angle, 0.7, 0.4);
  ASSERT_EQ(scene.bodies.size(), 2u);
  const Body& slab = scene.bodies[0].body;
  const Body& box = scene.bodies[1].body;
  EXPECT_EQ(slab.type(), BodyType::Static);
  EXPECT_EQ(box.theta(), angle);
  // Slab half-thickness plus box half-edge along the slab's normal, nothing along it.
  const Vec2 normal{-std::sin(angle), std::cos(angle)};
  const Vec2 offset = box.position() - slab.position();
  EXPECT_NEAR(dot(offset, normal), 1.0, 1e-12);
  EXPECT_NEAR(cross(normal, offset), 0.0, 1e-12);
  EXPECT_EQ(touching_pairs(scene), 1u);
  EXPECT_EQ(scene.bodies[1].material.static_friction, 0.7);
  EXPECT_EQ(scene.bodies[1].material.kinetic_friction, 0.4);
}

TEST(StandardScenes, BouncingDisksShareTheirRestitutionWithTheFloor)
{
  const Scene scene = scenes::bouncing_disks(7, 0.6);
  ASSERT_EQ(scene.bodies.size(), 8u);
  EXPECT_EQ(touching_pairs(scene), 0u);  // all in the air
  for (const SceneBody& entry : scene.bodies)
  {
    EXPECT_EQ(entry.material.restitution, 0.6);
  }
}

TEST(StandardScenes, ElasticGasIsConfinedAtRestAsAWholeAndReproducible)
{
  const int n = 1000;
  const Scene scene = scenes::elastic_gas(n, 7);
  ASSERT_EQ(count_type(scene, BodyType::Dynamic), static_cast<std::size_t>(n));
  EXPECT_EQ(count_type(scene, BodyType::Static), 4u);
  EXPECT_EQ(scene.settings.gravity, Vec2{});
  Vec2 momentum;
  Aabb inner{{1e9, 1e9}, {-1e9, -1e9}};
  for (const SceneBody& entry : scene.bodies)
  {
    EXPECT_EQ(entry.material.restitution, 1.0);
    EXPECT_EQ(entry.material.kinetic_friction, 0.0);
    if (entry.body.type() == BodyType::Dynamic)
    {
      momentum += entry.body.momentum();
      const Aabb box = entry.body.aabb();
      inner = Aabb{{std::min(inner.lo.x, box.lo.x), std::min(inner.lo.y, box.lo.y)},
                   {std::max(inner.hi.x, box.hi.x), std::max(inner.hi.y, box.hi.y)}};
    }
  }
  EXPECT_NEAR(momentum.x, 0.0, 1e-9);
  EXPECT_NEAR(momentum.y, 0.0, 1e-9);
  // Every disk inside the walls' inner rectangle [0, 16]^2.
  EXPECT_GE(inner.lo.x, 0.0);
  EXPECT_GE(inner.lo.y, 0.0);
  EXPECT_LE(inner.hi.x, 16.0);
  EXPECT_LE(inner.hi.y, 16.0);
  EXPECT_EQ(touching_pairs(scene), 0u);
  expect_same_scene(scene, scenes::elastic_gas(n, 7));
  EXPECT_NE(scenes::elastic_gas(n, 8).bodies[4].body.position(), scene.bodies[4].body.position());
}

TEST(StandardScenes, BulletWallAndHeavyOnLightHaveTheirParameters)
{
  const Scene bullet = scenes::bullet_wall(300.0);
  ASSERT_EQ(bullet.bodies.size(), 2u);
  EXPECT_EQ(bullet.bodies[1].body.velocity(), (Vec2{300.0, 0.0}));
  // The wall is thinner than one substep's travel: the scene tests tunnelling.
  const double substep = bullet.settings.dt / bullet.settings.substeps;
  const Aabb wall = bullet.bodies[0].body.aabb();
  EXPECT_LT(wall.hi.x - wall.lo.x, 300.0 * substep);

  const Scene stack = scenes::heavy_on_light(250.0);
  ASSERT_EQ(stack.bodies.size(), 3u);
  EXPECT_EQ(stack.bodies[2].body.mass() / stack.bodies[1].body.mass(), 250.0);
  EXPECT_GT(stack.bodies[2].body.position().y, stack.bodies[1].body.position().y);
  EXPECT_EQ(touching_pairs(stack), 2u);
}

TEST(StandardScenes, BuildingBlocksRejectImpossibleParameters)
{
  Scene scene;
  scenes::PyramidParams pyramid;
  pyramid.base = 0;
  EXPECT_THROW(scenes::add_pyramid(scene, pyramid), std::invalid_argument);
  scenes::GasParams gas;
  gas.count = 100;
  gas.radius = 1.0;
  gas.upper = Vec2{5.0, 5.0};
  EXPECT_THROW(scenes::add_gas(scene, gas), std::invalid_argument);
  EXPECT_TRUE(scene.bodies.empty());
}

// ---------------------------------------------------------------------------
// Shipped scene files

TEST(StandardScenes, RainFallsAsAlternatingDisksAndBoxesWithoutTouching)
{
  Scene scene;
  scenes::RainParams rain;
  rain.count = 200;
  scenes::add_rain(scene, rain);
  ASSERT_EQ(scene.bodies.size(), 200u);
  EXPECT_EQ(touching_pairs(scene), 0u);
  std::size_t disks = 0;
  for (const SceneBody& b : scene.bodies)
  {
    EXPECT_EQ(b.body.type(), BodyType::Dynamic);
    EXPECT_EQ(b.body.velocity().y, -rain.speed);
    EXPECT_GE(b.body.position().y, rain.bottom);
    disks += b.body.shape() == Shape::Disk ? 1 : 0;
  }
  EXPECT_EQ(disks, 100u);  // disks and boxes in turn, shifted by a row so columns mix too
  Scene again;
  scenes::add_rain(again, rain);
  EXPECT_EQ(again.bodies.back().body.position(), scene.bodies.back().body.position());
  rain.spacing = rain.size;
  EXPECT_THROW(scenes::add_rain(again, rain), std::invalid_argument);
}

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
