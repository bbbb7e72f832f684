// The soft step's restitution, substep by substep, checked against the
// closed forms it must meet: bodies that meet one after another within one
// frame bounce off each in turn (equal disks in a row pass the speed along),
// e = 1 keeps the kinetic energy however many bodies meet at once, boxes on
// the contact rows bounce like disks on the point verbs, and a bouncy body at
// rest stays at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"
#include "world_test_support.h"

namespace collision2d
{
namespace
{
using test::kinetic_energy;

Vec2 momentum(const World& world)
{
  Vec2 p{0.0, 0.0};
  for (BodyId id : world.body_ids())
  {
    p = p + world.body(id).momentum();
  }
  return p;
}

WorldSettings weightless()
{
  WorldSettings s;
  s.gravity = Vec2{0.0, 0.0};
  s.sleeping = Toggle::Off;
  return s;
}

const Material kElastic{1.0, 0.0, 0.0};

TEST(WorldSoftRestitution, DisksMeetingInTurnWithinOneFramePassTheSpeedAlong)
{
  // Three equal disks in a row, gaps of 1 cm; the first at 6 m/s travels
  // 2.5 cm a substep, so it meets the second and the second the third within
  // one frame. Elastic impacts one after another leave the first two at rest
  // and the third at 6 m/s; resolved as one impact they would not.
  constexpr double kSpeed = 6.0;  // m/s
  World world(weightless());
  std::vector<BodyId> disks;
  for (int i = 0; i < 3; ++i)
  {
    const Vec2 velocity{i == 0 ? kSpeed : 0.0, 0.0};
    disks.push_back(world.add_body(Body(1.0, 0.5, {1.01 * i, 0.0}, velocity), kElastic));
  }
  const double energy = kinetic_energy(world);
  world.step(3);
  std::printf("after: %.12f %.12f %.12f m/s\n", world.body(disks[0]).velocity().x, world.body(disks[1]).velocity().x,
              world.body(disks[2]).velocity().x);
  EXPECT_NEAR(world.body(disks[0]).velocity().x, 0.0, 1e-9);
  EXPECT_NEAR(world.body(disks[1]).velocity().x, 0.0, 1e-9);
  EXPECT_NEAR(world.body(disks[2]).velocity().x, kSpeed, 1e-9);
  EXPECT_NEAR(momentum(world).x, kSpeed, 1e-12);
  EXPECT_NEAR(kinetic_energy(world), energy, 1e-12 * energy);
}

TEST(WorldSoftRestitution, ADiskStrikingTwoAtOnceKeepsEnergyAndMomentum)
{
  // A disk driven into the gap between two touching disks meets both in the
  // same substep: with e = 1 the impact is exactly elastic.
  World world(weightless());
  world.add_body(Body(1.0, 0.5, {0.0, 0.5}, {0.0, 0.0}), kElastic);
  world.add_body(Body(1.0, 0.5, {0.0, -0.5}, {0.0, 0.0}), kElastic);
  world.add_body(Body(2.0, 0.5, {-0.9, 0.02}, {3.0, 0.1}), kElastic);
  const double energy = kinetic_energy(world);
  const Vec2 before = momentum(world);
  world.step(60);
  EXPECT_NEAR(kinetic_energy(world), energy, 1e-12 * energy);
  EXPECT_NEAR(momentum(world).x, before.x, 1e-12);
  EXPECT_NEAR(momentum(world).y, before.y, 1e-12);
}

TEST(WorldSoftRestitution, AStrikeIntoAPairAlreadyParting)
{
  // The second and third disks touch and part at 0.1 m/s when the first
  // strikes the second: within the substep the second is driven back into the
  // third. Newton's rule lets that parting contact end approaching at e times
  // its speed; held at rest instead, the impact would lose energy.
  World world(weightless());
  world.add_body(Body(1.0, 0.5, {-1.01, 0.0}, {6.0, 0.0}), kElastic);
  world.add_body(Body(1.0, 0.5, {0.0, 0.0}, {0.0, 0.0}), kElastic);
  world.add_body(Body(1.0, 0.5, {1.0, 0.0}, {0.1, 0.0}), kElastic);
  const double energy = kinetic_energy(world);
  world.step(30);
  std::printf("energy %.15g -> %.15g J\n", energy, kinetic_energy(world));
  EXPECT_NEAR(kinetic_energy(world), energy, 1e-12 * energy);
  EXPECT_NEAR(momentum(world).x, 6.1, 1e-12);
}

TEST(WorldSoftRestitution, ElasticGasKeepsItsEnergyInBothModes)
{
  // Hundreds of disks in a box meeting walls and each other, often several
  // within a frame: the kinetic energy is kept to round-off.
  for (SolverMode mode : {SolverMode::Iterative, SolverMode::Exact})
  {
    Scene gas = scenes::elastic_gas(mode == SolverMode::Exact ? 100 : 400);
    gas.settings.solver_mode = mode;
    World world = make_world(gas);
    const double before = kinetic_energy(world);
    world.step(300);
    const double change = std::abs(kinetic_energy(world) - before) / before;
    std::printf("%s: relative change of kinetic energy %.3g over 5 s\n", to_text(mode), change);
    EXPECT_LT(change, 1e-10) << to_text(mode);
  }
}

TEST(WorldSoftRestitution, BoxesOnTheContactRowsBounceByNewtonsRule)
{
  // Two square boxes face to face (a two-point manifold, solved on the rows)
  // closing at 5 m/s; e = 0.5, mass 1 and 3 kg: momentum kept, the closing
  // speed reversed and halved, no spin.
  const Material half{0.5, 0.0, 0.0};
  World world(weightless());
  const BodyId a = world.add_body(scenes::make_box(1.0, 1.0, 1.0, {0.0, 0.0}, 0.0, {4.0, 0.0}), half);
  const BodyId b = world.add_body(scenes::make_box(3.0, 1.0, 1.0, {1.05, 0.0}, 0.0, {-1.0, 0.0}), half);
  const double before = momentum(world).x;
  world.step(10);
  const double closing = world.body(a).velocity().x - world.body(b).velocity().x;
  EXPECT_NEAR(momentum(world).x, before, 1e-12);
  EXPECT_NEAR(-closing, 0.5 * 5.0, 1e-9);
  EXPECT_NEAR(world.body(a).omega(), 0.0, 1e-12);
  EXPECT_NEAR(world.body(b).omega(), 0.0, 1e-12);
}

TEST(WorldSoftRestitution, BouncyBodiesAtRestStayAtRest)
{
  // A bouncy disk and box resting on the ground under gravity: the substeps'
  // gravity kicks are no impacts, so neither hops.
  WorldSettings settings;
  settings.sleeping = Toggle::Off;
  World world(settings);
  const Material bouncy{0.9, 0.5, 0.5};
  world.add_body(scenes::make_static_box(20.0, 1.0, {0.0, -0.5}), bouncy);
  const BodyId disk = world.add_body(Body(1.0, 0.5, {0.0, 0.5}, {0.0, 0.0}), bouncy);
  const BodyId box = world.add_body(scenes::make_box(1.0, 1.0, 1.0, {3.0, 0.5}), bouncy);
  world.step(60);
  double fastest = 0.0;
  for (int frame = 0; frame < 300; ++frame)
  {
    world.step();
    for (BodyId id : {disk, box})
    {
      fastest = std::max(fastest, length(world.body(id).velocity()));
    }
  }
  EXPECT_LT(fastest, 1e-3) << "m/s";
  EXPECT_NEAR(world.body(disk).position().y, 0.5, 5e-3);
  EXPECT_NEAR(world.body(box).position().y, 0.5, 5e-3);
}

}  // namespace
}  // namespace collision2d
