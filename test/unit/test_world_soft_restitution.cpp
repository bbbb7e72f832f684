// The soft step's restitution, substep by substep, checked against the
// closed forms it must meet: bodies that meet one after another within one
// frame bounce off each in turn (equal disks in a row pass the speed along),
// e = 1 keeps the kinetic energy however many bodies meet at once, boxes on
// the contact rows bounce like disks on the point verbs, a bouncy body at
// rest stays at rest, a light body that a heavy one presses against a wall
// gains no energy when the step lets go of that press, and a bounce that
// unloads a contact leaves its friction inside the Coulomb cone.
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
using test::mechanical_energy;

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

/// A ground 40 m wide with its top at y = 0 and walls 20 m apart.
void add_ground_and_walls(World& world)
{
  world.add_body(scenes::make_static_box(40.0, 1.0, {0.0, -0.5}));
  world.add_body(scenes::make_static_box(1.0, 30.0, {-10.5, 14.0}));
  world.add_body(scenes::make_static_box(1.0, 30.0, {10.5, 14.0}));
}

/// A world under gravity (-10 m/s^2) in `mode` at `substeps`, with
/// add_ground_and_walls.
World walled_world(SolverMode mode, int substeps)
{
  WorldSettings settings;
  settings.gravity = Vec2{0.0, -10.0};
  settings.solver_mode = mode;
  settings.substeps = substeps;
  World world(settings);
  add_ground_and_walls(world);
  return world;
}

/// A rectangle's outline about its centre (m).
std::vector<Vec2> rectangle(double half_width, double half_height)
{
  return {{-half_width, -half_height}, {half_width, -half_height}, {half_width, half_height}, {-half_width, half_height}};
}

/// The largest rise of the mechanical energy over `frames` frames (J).
double largest_energy_gain(World& world, int frames)
{
  const double g = -world.settings().gravity.y;
  const double start = mechanical_energy(world, g);
  double gain = 0.0;
  for (int frame = 0; frame < frames; ++frame)
  {
    world.step();
    gain = std::max(gain, mechanical_energy(world, g) - start);
  }
  return gain;
}

TEST(WorldSoftRestitution, ALightBodyRunIntoAWallKeepsNoPushWhenAHeavyOneLetsGo)
{
  // An 18 kg disk strikes a 0.39 kg heptagon toward the right wall at 44 m/s
  // and follows it at 27 m/s: parting from it at the substep's start, it
  // meets it within the substep once the wall has stopped it. Restitution
  // lets go of that meeting (the two bounce in a later substep), and with it
  // went the wall's push that balanced it: the exact mode threw the heptagon
  // at 1500 m/s (energy +1.8e5 J). No mode may gain energy.
  std::vector<Vec2> heptagon;
  for (int k = 0; k < 7; ++k)
  {
    const double angle = 2.0 * M_PI * k / 7.0;
    heptagon.push_back(0.1118 * Vec2{std::cos(angle), std::sin(angle)});
  }
  for (SolverMode mode : {SolverMode::Iterative, SolverMode::Exact})
  {
    for (int substeps : {1, 2, 4})
    {
      WorldSettings settings;
      settings.gravity = Vec2{0.0, -10.0};
      settings.sleeping = Toggle::Off;
      settings.solver_mode = mode;
      settings.substeps = substeps;
      World world(settings);
      add_ground_and_walls(world);
      world.add_body(Body(0.3914, heptagon, {8.897, 0.6326}, {-1.741, 16.144}, 5.226, -8.771),
                     Material{0.682, 0.840, 0.548});
      world.add_body(Body(18.14, 0.03028, {8.3513, 0.9872}, {28.365, -8.118}, -19.857), Material{0.449, 0.108, 0.059});
      const double start = mechanical_energy(world, 10.0);
      const double gain = largest_energy_gain(world, 60);
      std::printf("%s, %d substeps: largest energy gain %.3g J of %.4g\n", to_text(mode), substeps, gain, start);
      EXPECT_LE(gain, 1e-9 * start) << to_text(mode) << ", " << substeps << " substeps";
    }
  }
}

TEST(WorldSoftRestitution, ALightBoxPressedIntoAWallByAHeavyDiskGainsNoEnergy)
{
  // A 0.44 kg box lies against the left wall when a 125 kg disk rolls into
  // it (from a random stress world, kept to full precision: it meets the box
  // 1.5 s in). The exact mode let go of the disk's push and left the wall's,
  // throwing the box at 2500 m/s (energy +6.7e5 J, 11 times the start).
  const std::vector<Vec2> box = rectangle(0.13539458806499688, 0.44768277326006206);
  for (SolverMode mode : {SolverMode::Iterative, SolverMode::Exact})
  {
    for (int substeps : {1, 2, 4})
    {
      World world = walled_world(mode, substeps);
      world.add_body(Body(0.44046674059211038, box, {-5.3962684239280438, 11.310480006445957},
                          {-4.641343343185131, -26.337496492725229}, 0.87391837344346046, -7.3526587800540355),
                     Material{0.57348503142224239, 0.66275112484944598, 0.33389985929275467});
      world.add_body(Body(124.7565637982582, 0.5182968336811884, {6.7194314263879527, 2.8845926360273455},
                          {-29.556712276487527, 6.0156571180496101}, 1.9776122866122421),
                     Material{0.18516109462626718, 0.32242107954630539, 0.2221043488880711});
      const double start = mechanical_energy(world, 10.0);
      const double gain = largest_energy_gain(world, 120);
      std::printf("%s, %d substeps: largest energy gain %.3g J of %.4g\n", to_text(mode), substeps, gain, start);
      EXPECT_LE(gain, 1e-9 * start) << to_text(mode) << ", " << substeps << " substeps";
    }
  }
}

TEST(WorldSoftRestitution, ABounceThatUnloadsAContactTakesItsFrictionOffToo)
{
  // A 27 kg disk sits on a 70 g one by the left wall when a 96 kg plank
  // slides into the light disk (from a random stress world, rounded). The
  // heavy disk's bounce drove its normal impulse on the light one down and
  // left the friction it had carried: the exact mode spun the light disk to
  // 1.2e4 rad/s (energy +8200 J). Every published impulse must lie in the
  // Coulomb cone, and no mode may gain energy.
  const std::vector<Vec2> plank = rectangle(0.00308, 0.3796);
  for (SolverMode mode : {SolverMode::Iterative, SolverMode::Exact})
  {
    for (int substeps : {1, 2, 4, 8})
    {
      World world = walled_world(mode, substeps);
      world.add_body(Body(27.08, 0.04915, {-9.9509, 0.17718}, {0.0, -1.213}, -16.09), Material{0.2335, 0.9866, 0.7882});
      world.add_body(Body(0.06965, 0.0545, {-9.9001, 0.05447}, {2.835, 0.0}, 145.3), Material{0.3945, 0.5806, 0.5443});
      world.add_body(Body(96.22, plank, {-9.2678, 0.01827}, {-5.86, 0.0}, 4.7525, 0.0), Material{0.0765, 0.7279, 0.6395});
      const double start = mechanical_energy(world, 10.0);
      double gain = 0.0;
      double outside = 0.0;  // N s
      for (int frame = 0; frame < 60; ++frame)
      {
        world.step();
        gain = std::max(gain, mechanical_energy(world, 10.0) - start);
        for (const WorldContact& c : world.contacts())
        {
          const double mu = std::min(world.material(c.a).static_friction, world.material(c.b).static_friction);
          const double limit = mu * c.impulse.normal;
          outside = std::max(outside, std::abs(c.impulse.tangent) - limit - 1e-9 * (1.0 + limit));
        }
      }
      std::printf("%s, %d substeps: largest energy gain %.3g J of %.4g, friction outside the cone %.3g N s\n",
                  to_text(mode), substeps, gain, start, outside);
      EXPECT_LE(gain, 1e-9 * start) << to_text(mode) << ", " << substeps << " substeps";
      EXPECT_LE(outside, 0.0) << to_text(mode) << ", " << substeps << " substeps";
    }
  }
}

}  // namespace
}  // namespace collision2d
