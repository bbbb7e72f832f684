// The standard scene builders and their building blocks: no overlap at the
// start, the counts, contacts and parameters each builder promises, and bad
// parameters refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "scene_test_support.h"

namespace collision2d
{
namespace
{
using scenes::make_standard_scene;
using scenes::standard_scene_names;
using test::expect_same_scene;

/// Overlap allowed between bodies a builder places exactly touching: the
/// round-off of rotating a box onto a tilted slab (m).
constexpr double kTouchingOverlap = 1e-12;
/// Gap still counted as touching when looking for resting contacts (relative).
constexpr double kTouchTolerance = 1e-9;

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

}  // namespace
}  // namespace collision2d
