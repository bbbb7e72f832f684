// Fast bodies that turn while they touch a thin static wall: the time-of-impact
// sweep holds each body's orientation, so a pair already touching is swept
// again with the body's centroid alone (world_toi.cpp). Whatever the spin,
// no centroid crosses the wall, in either pipeline, with the sweep on Auto
// (the default) or On; the body ends on its own side, not moving into the
// wall, without having gained kinetic energy (restitution 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_parts.h"
#include "extremes_support.h"

namespace collision2d
{
namespace
{
constexpr double kWallThickness = 0.02;  // m, its near face at x = 0
constexpr double kWallHeight = 20.0;     // m
constexpr int kFrames = 60;
/// Round-off allowed on the final speed into the wall (m/s).
constexpr double kSpeedTol = 1e-6;

struct Throw
{
  std::string what;
  Body body;
  bool soft_step = true;
  int substeps = 4;
};

struct Outcome
{
  double farthest_centroid = -1e300;  ///< largest centroid x seen after any frame (m)
  Body final_state;
  double energy_before = 0.0;         ///< J
  double energy_after = 0.0;          ///< J
};

Outcome run(const Throw& t, Toggle time_of_impact)
{
  WorldSettings s;
  s.gravity = {0.0, 0.0};
  s.soft_step = t.soft_step;
  s.substeps = t.substeps;
  s.time_of_impact = time_of_impact;
  s.sleeping = Toggle::Off;
  World world(s);
  world.add_body(scenes::make_static_box(kWallThickness, kWallHeight, {0.5 * kWallThickness, 0.0}));
  const BodyId id = world.add_body(t.body);
  Outcome out{-1e300, t.body, t.body.kinetic_energy(), 0.0};
  for (int f = 0; f < kFrames; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    out.farthest_centroid = std::max(out.farthest_centroid, world.body(id).position().x);
  }
  out.final_state = world.body(id);
  out.energy_after = out.final_state.kinetic_energy();
  return out;
}

std::vector<Throw> throws()
{
  // A 0.5 m box at 3 km/s meets the wall on one corner, which turns it at
  // some 7000 rad/s: the next frame's sweep, with its orientation held,
  // sees the corner touching and once let the box through.
  const Body box = scenes::make_box(2.5, 0.5, 0.5, {-3.5, 2.25}, 0.0, {3000.0, 75.0}, -1.0);
  // A 2 m rod, 2 cm thick, at 300 m/s spinning at 1000 rad/s: in the soft
  // step the solver holds its frame contacts, which its turn leaves behind.
  const Body rod = scenes::make_box(6.5, 2.0, 0.02, {-2.0, -3.0}, 0.0, {300.0, -22.5}, -1000.0);
  return {{"box at 3 km/s, Fx2D, 1 substep", box, false, 1},
          {"box at 3 km/s, soft step, 4 substeps", box, true, 4},
          {"spinning rod, soft step, 4 substeps", rod, true, 4},
          {"spinning rod, Fx2D, 4 substeps", rod, false, 4}};
}

TEST(ExtremesSpin, NoCentroidCrossesAThinWallWhateverItsSpin)
{
  for (const Throw& t : throws())
  {
    for (Toggle toi : {Toggle::Auto, Toggle::On})
    {
      SCOPED_TRACE(t.what + (toi == Toggle::On ? ", time_of_impact On" : ", time_of_impact Auto"));
      const Outcome out = run(t, toi);
      std::printf("%s, toi %s: farthest centroid x %.4g m, final x %.4g m, vx %.3g m/s, energy %.4g -> %.4g J\n",
                  t.what.c_str(), toi == Toggle::On ? "On" : "Auto", out.farthest_centroid,
                  out.final_state.position().x, out.final_state.velocity().x, out.energy_before, out.energy_after);
      EXPECT_LT(out.farthest_centroid, 0.0) << "a centroid reached the wall's near face";
      EXPECT_LT(out.final_state.position().x, 0.0);
      EXPECT_LE(out.final_state.velocity().x, kSpeedTol) << "still moving into the wall";
      EXPECT_LE(out.energy_after, out.energy_before) << "restitution 0 cannot add energy";
    }
  }
}

// A thin rod spinning about its resting centre strikes a small disk ahead of
// it. Swept at its orientation alone, its far end jumped past the disk from
// 17 rad/s in the Fx2D order and from 60 rad/s in the soft step (this rod,
// 4 substeps); a polygon whose spin outruns its reach is swept turning
// (world_sweep_marks.cpp). Checked from the bodies' states each frame: the
// disk is struck before the rod's mid-plane reaches its centre, linear
// momentum stays zero and kinetic energy does not grow (restitution 0).
constexpr double kRodLength = 1.0;       // m
constexpr double kRodThickness = 0.02;   // m
constexpr double kRodMass = 1.0;         // kg
constexpr double kDiskRadius = 0.01;     // m
constexpr double kDiskMass = 0.01;       // kg
constexpr double kDiskDistance = 0.4;    // m from the rod's centre
constexpr int kMaxStrikeFrames = 600;

struct Strike
{
  bool struck = false;             ///< the disk moved before the rod's mid-plane reached it
  bool crossed = false;            ///< the mid-plane passed the disk's centre first
  double deepest = 0.0;            ///< largest overlap of disk and rod seen (m)
  double momentum = 0.0;           ///< largest |total linear momentum| seen (kg m/s)
  double energy_before = 0.0;      ///< J
  double energy_after = 0.0;       ///< J
};

/// The disk's centre in the rod's frame.
Vec2 in_rod_frame(const Body& rod, const Body& disk)
{
  const Vec2 d = disk.position() - rod.position();
  return {rod.cos_theta() * d.x + rod.sin_theta() * d.y, -rod.sin_theta() * d.x + rod.cos_theta() * d.y};
}

Strike strike(bool soft_step, double omega, double ahead)
{
  WorldSettings s;
  s.gravity = {0.0, 0.0};
  s.soft_step = soft_step;
  s.sleeping = Toggle::Off;
  World world(s);
  const BodyId rod_id = world.add_body(scenes::make_box(kRodMass, kRodLength, kRodThickness, {0.0, 0.0}, 0.0,
                                                        {0.0, 0.0}, omega));
  const Vec2 at{kDiskDistance * std::cos(ahead), kDiskDistance * std::sin(ahead)};
  const BodyId disk_id = world.add_body(Body(kDiskMass, kDiskRadius, at, {0.0, 0.0}));
  Strike out;
  out.energy_before = world.body(rod_id).kinetic_energy();
  for (int f = 0; f < kMaxStrikeFrames && !out.struck && !out.crossed; ++f)
  {
    world.step();
    const Body& rod = world.body(rod_id);
    const Body& disk = world.body(disk_id);
    const Vec2 local = in_rod_frame(rod, disk);
    out.deepest = std::max(out.deepest, kDiskRadius + 0.5 * kRodThickness - std::abs(local.y));
    out.momentum = std::max(out.momentum, length(rod.velocity() * kRodMass + disk.velocity() * kDiskMass));
    out.energy_after = rod.kinetic_energy() + disk.kinetic_energy();
    out.struck = length_sq(disk.velocity()) > 0.0;
    // Turning anticlockwise, the rod's mid-plane meets the disk from below.
    out.crossed = !out.struck && local.y < 0.0;
  }
  return out;
}

TEST(ExtremesSpin, ASpinningRodStrikesASmallDiskAhead)
{
  for (bool soft_step : {false, true})
  {
    for (double omega : {10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0})
    {
      for (double ahead : {0.5, 1.0, 2.0})
      {
        SCOPED_TRACE(std::string(soft_step ? "soft step" : "Fx2D") + ", " + std::to_string(omega) + " rad/s, disk " +
                     std::to_string(ahead) + " rad ahead");
        const Strike out = strike(soft_step, omega, ahead);
        std::printf("%s, %g rad/s, %g rad ahead: struck %d, deepest %.3g mm, |p| %.3g, energy %.6g -> %.6g J\n",
                    soft_step ? "soft step" : "Fx2D", omega, ahead, out.struck, 1e3 * out.deepest, out.momentum,
                    out.energy_before, out.energy_after);
        EXPECT_TRUE(out.struck) << "the rod passed through the disk";
        EXPECT_LT(out.deepest, kDiskRadius) << "the disk's centre went inside the rod's outline";
        EXPECT_LE(out.momentum, 1e-12 * kRodMass * omega * kRodLength) << "impulses not equal and opposite";
        EXPECT_LE(out.energy_after, out.energy_before * (1.0 + 1e-12)) << "restitution 0 cannot add energy";
      }
    }
  }
}

}  // namespace
}  // namespace collision2d
