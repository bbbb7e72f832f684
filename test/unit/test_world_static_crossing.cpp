// A light body on a static ground, struck from above by a heavy fast one:
// the contacts cannot hold it, and before the frame's centroid sweep against
// the static bodies (world_toi.cpp) it was driven into the ground, in places
// out of its bottom. No gravity, so only the impact presses it.
//
// What holds (asserted below), both pipelines, 1 to 8 substeps, strikes at
// 50 to 200 m/s, mass ratios 100 and 1000, disk and box: the light body's
// centroid never goes deeper than kDeepest below the ground's top (measured
// 2.9 mm at worst, at one substep; a centroid that creeps in by less than half
// its inner radius a frame is not swept). Without the sweep (7b2795b) 26 of
// these 96 strikes took the centroid below the top, by up to 200 mm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace
{
constexpr double kGroundTop = 0.0;     // m
constexpr double kHalfSize = 0.25;     // m: the light body's radius or half side
constexpr double kHeavyMass = 10.0;    // kg
constexpr double kHeavyRadius = 0.2;   // m
constexpr double kStrikeOffset = 0.05;  // m: the heavy body strikes off centre, so a box is turned too
constexpr double kStrikeGap = 0.5;     // m: between the bodies at the start
constexpr double kDeepest = 0.01;      // m: how far the light centroid may end below the top
constexpr int kFrames = 60;

struct Strike
{
  bool soft_step;
  int substeps;
  double speed;  // m/s, downward
  double light_mass;  // kg
  bool box;
};

std::string describe(const Strike& s)
{
  return std::string(s.soft_step ? "soft step" : "Fx2D") + ", " + std::to_string(s.substeps) + " substeps, " +
         std::to_string(s.speed) + " m/s, light " + std::to_string(s.light_mass) + " kg " + (s.box ? "box" : "disk");
}

TEST(WorldStaticCrossing, StruckBodyStaysOutOfTheGround)
{
  int stopped = 0;  // strikes in which the step stopped some body
  for (const bool soft : {false, true})
    for (const int substeps : {1, 2, 4, 8})
      for (const double speed : {50.0, 100.0, 200.0})
        for (const double light : {0.01, 0.1})
          for (const bool box : {false, true})
          {
            const Strike strike{soft, substeps, speed, light, box};
            WorldSettings settings;
            settings.soft_step = soft;
            settings.substeps = substeps;
            settings.gravity = Vec2{0.0, 0.0};
            World world(settings);
            Body ground = scenes::make_box(1.0, 40.0, 1.0, {0.0, kGroundTop - 0.5}, 0.0, {0.0, 0.0}, 0.0);
            ground.set_type(BodyType::Static);
            world.add_body(ground);
            const Vec2 rest{0.0, kGroundTop + kHalfSize};
            const BodyId id = world.add_body(box ? scenes::make_box(light, 2 * kHalfSize, 2 * kHalfSize, rest, 0.0,
                                                                    {0.0, 0.0}, 0.0)
                                                 : Body(light, kHalfSize, rest, {0.0, 0.0}, 0.0));
            const Vec2 start{kStrikeOffset, 2 * kHalfSize + kHeavyRadius + kStrikeGap};
            world.add_body(Body(kHeavyMass, kHeavyRadius, start, {0.0, -speed}, 0.0));
            double lowest = rest.y;
            std::size_t clamps = 0;
            for (int f = 0; f < kFrames; ++f)
            {
              clamps += world.step().toi_clamps;
              lowest = std::min(lowest, world.body(id).position().y);
            }
            EXPECT_GE(lowest, kGroundTop - kDeepest) << describe(strike);
            stopped += clamps > 0 ? 1 : 0;
          }
  EXPECT_GT(stopped, 0) << "no strike needed the sweep: the test no longer exercises it";
}

// A thin rod (2.8 m x 4 cm) half inside the ground: its centroid on the
// ground's top face, tilted 0.9 rad, moving into the ground and spinning. Its
// contacts are 1.1 m deep and do not stop the centroid, so the crossing check
// does. At 0ba2ab9 the check stopped the whole move, turn and all, and kept
// the velocity, every frame: the rod stayed frozen in the ground for good,
// its velocity kept (and growing under gravity).
//
// What holds (asserted below), both pipelines, 1 and 4 substeps, with and
// without gravity: the rod never ends a frame where it began while it moves
// faster than kStill; its centroid never goes more than kDeepest below the
// top while over the ground; under gravity it comes out and rests on the
// ground within kSettleFrames (or has slid off the ground's end).
TEST(WorldStaticCrossing, ACentroidOnTheFaceIsNotFrozenThere)
{
  constexpr double kRodLength = 2.8;   // m
  constexpr double kRodThick = 0.04;   // m
  constexpr double kRodMass = 9.4;     // kg
  constexpr double kTilt = 0.9;        // rad
  constexpr double kStill = 0.5;       // m/s, rad/s: slower than this, a frame may leave it in place
  // m/s: at rest, a third of one frame's gravity kick (10 m/s^2 / 60 Hz = 0.17 m/s):
  // the ground carries the rod's weight.
  constexpr double kRestSpeed = 0.05;
  constexpr double kGroundHalfWidth = 20.0;  // m
  constexpr int kSettleFrames = 180;
  struct Throw
  {
    Vec2 velocity;  // m/s
    double spin;    // rad/s
  };
  for (const bool soft : {false, true})
    for (const int substeps : {1, 4})
      for (const double gravity : {0.0, -10.0})
        for (const Throw t : {Throw{{-20.0, -40.0}, 0.0}, Throw{{0.0, -5.0}, 3.0}, Throw{{5.0, -10.0}, -2.0}})
        {
          const std::string what = std::string(soft ? "soft step" : "Fx2D") + ", " + std::to_string(substeps) +
                                   " substeps, gravity " + std::to_string(gravity) + ", v (" +
                                   std::to_string(t.velocity.x) + ", " + std::to_string(t.velocity.y) + "), spin " +
                                   std::to_string(t.spin);
          SCOPED_TRACE(what);
          WorldSettings settings;
          settings.soft_step = soft;
          settings.substeps = substeps;
          settings.gravity = Vec2{0.0, gravity};
          World world(settings);
          Material rough;
          rough.static_friction = 0.5;
          rough.kinetic_friction = 0.5;
          Body ground = scenes::make_box(1.0, 2 * kGroundHalfWidth, 1.0, {0.0, kGroundTop - 0.5}, 0.0, {0.0, 0.0}, 0.0);
          ground.set_type(BodyType::Static);
          world.add_body(ground, rough);
          const BodyId id = world.add_body(
              scenes::make_box(kRodMass, kRodLength, kRodThick, {0.0, kGroundTop}, kTilt, t.velocity, t.spin), rough);
          int frozen = 0;  // frames that left the moving rod where it was
          double lowest = kGroundTop;
          for (int f = 0; f < kSettleFrames; ++f)
          {
            const Body before = world.body(id);
            world.step();
            const Body& after = world.body(id);
            const bool moving = length(after.velocity()) > kStill || std::abs(after.omega()) > kStill;
            if (moving && after.position().x == before.position().x && after.position().y == before.position().y &&
                after.theta() == before.theta())
            {
              ++frozen;
            }
            if (std::abs(after.position().x) < kGroundHalfWidth)  // off the ground's end it may fall
            {
              lowest = std::min(lowest, after.position().y);
            }
          }
          EXPECT_EQ(frozen, 0);
          EXPECT_GE(lowest, kGroundTop - kDeepest);
          const Body& rod = world.body(id);
          if (gravity != 0.0 && std::abs(rod.position().x) < kGroundHalfWidth - kRodLength)
          {
            // At rest on the ground: flat on it, neither in it nor moving.
            EXPECT_NEAR(rod.position().y, kGroundTop + 0.5 * kRodThick, kDeepest);
            EXPECT_LT(length(rod.velocity()), kRestSpeed);
          }
        }
}

// A small box pressed 1 to 3 mm into a wall (its centroid inside the
// wall's face) is swept down by a kinematic bar striking at 30 to 60 m/s,
// tilted so that it pushes toward the wall too. The crossing check kept the
// box's move along the wall's face and did not sweep that move against the
// ground: the box went through the ground's top (13 m down in 20 frames, in
// the soft step at one substep). Its centroid must stay within kDeepest of
// the ground's top, both pipelines, 1 to 4 substeps.
TEST(WorldStaticCrossing, ABoxSlidDownAWallFaceStopsAtTheGround)
{
  constexpr double kWallFace = -10.0;   // m: the wall fills x < kWallFace
  constexpr double kBoxHalf = 0.01;     // m
  constexpr double kBoxMass = 0.05;     // kg
  constexpr double kBarHalfLength = 2.0;  // m
  constexpr double kBarHalfThick = 0.1;   // m
  constexpr double kBarTilt = -0.1;     // rad: its lower face points down and toward the wall
  constexpr double kBarBottom = 0.35;   // m: the bar's lower left corner's height, about, at the start
  constexpr int kStrikeFrames = 20;
  double worst = kGroundTop;
  for (const bool soft : {false, true})
    for (const int substeps : {1, 2, 4})
      for (const double speed : {30.0, 45.0, 60.0})
        for (const double pressed_in : {0.001, 0.002, 0.003})
        {
          WorldSettings settings;
          settings.soft_step = soft;
          settings.substeps = substeps;
          settings.gravity = Vec2{0.0, -10.0};
          World world(settings);
          world.add_body(scenes::make_static_box(40.0, 1.0, {0.0, kGroundTop - 0.5}));
          world.add_body(scenes::make_static_box(1.0, 30.0, {kWallFace - 0.5, 14.0}));
          const BodyId box = world.add_body(
              scenes::make_box(kBoxMass, 2 * kBoxHalf, 2 * kBoxHalf, {kWallFace - pressed_in, 0.3}, 0.0, {0.0, 0.0}, 0.0),
              Material{0.0, 0.5, 0.4});
          Body bar = scenes::make_box(1.0, 2 * kBarHalfLength, 2 * kBarHalfThick,
                                      {kWallFace + kBarHalfLength, kBarBottom + kBarHalfThick - kBarHalfLength * kBarTilt},
                                      kBarTilt, {0.0, -speed}, 0.0);
          bar.set_type(BodyType::Kinematic);
          world.add_body(bar);
          double lowest = kGroundTop + kBoxHalf;
          for (int f = 0; f < kStrikeFrames; ++f)
          {
            world.step();
            lowest = std::min(lowest, world.body(box).position().y);
          }
          const std::string what = std::string(soft ? "soft step" : "Fx2D") + ", " + std::to_string(substeps) +
                                   " substeps, " + std::to_string(speed) + " m/s, " + std::to_string(pressed_in) +
                                   " m into the wall";
          EXPECT_GE(lowest, kGroundTop - kDeepest) << what;
          worst = std::min(worst, lowest);
        }
  std::printf("lowest centroid of the struck boxes: %.4g m (ground top %.4g m)\n", worst, kGroundTop);
}

}  // namespace
}  // namespace collision2d
