// Fast kinematic pushers (a robot's links enter a World as kinematic bodies).
// The time-of-impact sweep moves only dynamic bodies; in the soft step a
// kinematic body's frame reach widens the speculative margin instead
// (world_contacts.cpp), so the pair's contact exists before the paddle
// arrives and the solve keeps the gap from closing, however fast it comes.
// A disk of 1 cm radius at rest meets a 2 cm paddle moving at 1 m/s to
// 10 km/s, head on and with the face turned 0.3 rad. Checked every frame: the
// disk's centre is never behind the face by more than round-off; while they
// touch, the frictionless inelastic push (e = 0 against an infinite mass) has
// given the disk exactly the paddle's velocity along the face normal and none
// along the face. The Fx2D order sweeps the fast paddle instead and pushes
// the disk ahead of the face from the time of impact
// (world_kinematic_push.cpp); it lets a contact overlap by `slop`, and a
// frame can end with the pair just touching before the impact, so its first
// touching frame is not checked for velocity. Without the push the paddle
// passed through the disk from 4.9 m/s.
// A turning kinematic face: a disk lies ahead of a 2 m bar that turns about
// its middle at 1 to 20 rad/s, is struck and slides out along it, without
// and with friction. Before each pass the contact follows the face as it
// turns (world_turning_faces.cpp). Checked: the disk never reaches the bar's middle
// plane, it slides off the end, it leaves no faster than a frictionless bead
// on the bar would at the tip, and it sinks into the face no deeper than a
// contact spring of contact_hertz would under the largest load the slide can
// ask of it (the Coriolis push 2 omega v for the disk's fastest speed v),
// and with friction `slop` more. Without the following the disk sank 3.4 mm
// at 3 rad/s, past both bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/world.h"
#include "extremes_support.h"

namespace collision2d
{
namespace
{
constexpr double kDiskRadius = 0.01;     // m
constexpr double kPaddleWidth = 0.02;    // m
constexpr double kStartGap = 0.5;        // m between the face and the disk
constexpr double kRunSeconds = 1.0;      // s the disk stays on the face at the longest
constexpr int kFrames = 60;
/// Overlap allowed at any frame (m): round-off at positions up to 1e4 m.
constexpr double kGapTol = 1e-9;
/// A gap at most this wide counts as touching (m).
constexpr double kTouchGap = 1e-6;
/// Relative error allowed on the disk's velocity while it touches.
constexpr double kVelocityTol = 1e-9;

struct Push
{
  double speed = 0.0;  ///< m/s, along +x
  double turn = 0.0;   ///< rad, the face normal's angle from +x
};

struct Outcome
{
  double deepest = -1e300;       ///< largest overlap of the disk behind the face (m)
  double worst_velocity = 0.0;   ///< largest |v - (v_paddle . n) n| / speed while touching
  int touching_frames = 0;
};

/// A world without gravity at the default settings (the soft step), or in the Fx2D order.
World weightless_world(bool soft_step)
{
  WorldSettings s;
  s.gravity = {0.0, 0.0};
  s.soft_step = soft_step;
  return World(s);
}

Outcome run(const Push& push, bool soft_step = true)
{
  World world = weightless_world(soft_step);
  const Vec2 n{std::cos(push.turn), std::sin(push.turn)};
  const Vec2 along = perp(n);
  // Tall enough that the disk, sliding along a turned face, stays on it.
  const double height = 2.0 * (1.0 + push.speed * std::abs(n.y) * kRunSeconds);
  Body paddle = scenes::make_box(1.0, kPaddleWidth, height, -(kStartGap + kDiskRadius + 0.5 * kPaddleWidth) * n, push.turn);
  paddle.set_type(BodyType::Kinematic);
  paddle.set_velocity({push.speed, 0.0});
  const BodyId paddle_id = world.add_body(paddle);
  const BodyId disk_id = world.add_body(Body(1.0, kDiskRadius, {0.0, 0.0}, {0.0, 0.0}));
  const Vec2 pushed = (push.speed * n.x) * n;
  Outcome out;
  for (int f = 0; f < kFrames; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    const Vec2 offset = world.body(disk_id).position() - world.body(paddle_id).position();
    if (std::abs(dot(offset, along)) > 0.5 * height)
    {
      break;  // slid off the face's end
    }
    const double gap = dot(offset, n) - 0.5 * kPaddleWidth - kDiskRadius;
    out.deepest = std::max(out.deepest, -gap);
    if (gap <= kTouchGap)
    {
      ++out.touching_frames;
      if (soft_step || out.touching_frames > 1)
      {
        out.worst_velocity = std::max(out.worst_velocity, length(world.body(disk_id).velocity() - pushed) / push.speed);
      }
    }
  }
  return out;
}

/// Runs the paddle at each speed, head on and turned, in one pipeline:
/// the disk at most `allowed` (m) behind the face, and in contact on more
/// than `least_touching` frames.
void expect_paddle_pushes(bool soft_step, double allowed, int least_touching, std::initializer_list<double> speeds)
{
  const std::string pipeline = soft_step ? "soft step" : "Fx2D";
  for (double turn : {0.0, 0.3})
  {
    for (double speed : speeds)
    {
      SCOPED_TRACE(pipeline + ", paddle at " + std::to_string(speed) + " m/s, face turned " + std::to_string(turn) + " rad");
      const Outcome out = run(Push{speed, turn}, soft_step);
      std::printf("%s: paddle %g m/s, face turned %g rad, touching %d frames:\n", pipeline.c_str(), speed, turn,
                  out.touching_frames);
      test::print_figure("deepest overlap behind the face (m)", out.deepest, allowed);
      test::print_figure("worst |v - (v_paddle . n) n| / speed while touching", out.worst_velocity, kVelocityTol);
      EXPECT_GT(out.touching_frames, least_touching) << "the paddle never pushed the disk";
      EXPECT_LE(out.deepest, allowed) << "the disk went behind the paddle's face";
      EXPECT_LE(out.worst_velocity, kVelocityTol) << "not the paddle's normal velocity";
    }
  }
}

TEST(ExtremesKinematic, SoftStepPaddlePushesASmallDiskAtAnySpeed)
{
  expect_paddle_pushes(true, kGapTol, 0, {1.0, 5.0, 30.0, 100.0, 1e3, 1e4});
}

/// A row: a second disk 5 cm ahead of the first, 3 mm off its line.
constexpr double kRowSpacing = 0.05;  // m
constexpr double kRowOffset = 0.003;  // m
constexpr int kRowFrames = 30;

struct RowOutcome
{
  double deepest = -1e300;    ///< largest overlap of either disk behind the face (m)
  double slowest = 1e300;     ///< least x velocity of either disk at the end (m/s)
};

/// Bodies at rest far away: with this many the soft step sweeps only the
/// bodies a contact touches, unless a fast kinematic body asks for all.
constexpr int kBystanders = 20;

RowOutcome run_row(double speed, int bystanders)
{
  World world = weightless_world(true);
  for (int k = 0; k < bystanders; ++k)
  {
    world.add_body(Body(1.0, kDiskRadius, {100.0 + 0.1 * k, 50.0}, {0.0, 0.0}));
  }
  Body paddle = scenes::make_box(1.0, kPaddleWidth, 2.0, {-(kStartGap + kDiskRadius + 0.5 * kPaddleWidth), 0.0});
  paddle.set_type(BodyType::Kinematic);
  paddle.set_velocity({speed, 0.0});
  const BodyId paddle_id = world.add_body(paddle);
  const BodyId disks[] = {world.add_body(Body(1.0, kDiskRadius, {0.0, 0.0}, {0.0, 0.0})),
                          world.add_body(Body(1.0, kDiskRadius, {kRowSpacing, kRowOffset}, {0.0, 0.0}))};
  RowOutcome out;
  for (int f = 0; f < kRowFrames; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    const double face = world.body(paddle_id).position().x + 0.5 * kPaddleWidth;
    for (BodyId id : disks)
    {
      out.deepest = std::max(out.deepest, face - (world.body(id).position().x - kDiskRadius));
    }
  }
  for (BodyId id : disks)
  {
    out.slowest = std::min(out.slowest, world.body(id).velocity().x);
  }
  return out;
}

// A disk that the paddle drives into another stops at their time of impact
// (the frame found no contact between the two); the face pushes it on from
// there, and it pushes the second disk (world_kinematic_push.cpp). Before,
// the paddle ran through the stopped disk: from 20 m/s both disks ended
// behind the face, 0.12 m at 20 m/s and 0.97 m at 100 m/s.
TEST(ExtremesKinematic, SoftStepPaddlePushesARowOfDisks)
{
  for (int bystanders : {0, kBystanders})
  {
    for (double speed : {4.0, 8.0, 20.0, 100.0, 1e3, 1e4})
    {
      SCOPED_TRACE("paddle at " + std::to_string(speed) + " m/s into a row of two disks, " + std::to_string(bystanders) +
                   " bodies far away");
      const RowOutcome out = run_row(speed, bystanders);
      std::printf("soft step: paddle %g m/s into a row of two disks, %d bodies far away:\n", speed, bystanders);
      test::print_figure("deepest overlap behind the face (m)", out.deepest, kGapTol);
      test::print_figure("1 - slowest disk's x velocity / paddle's at the end", 1.0 - out.slowest / speed, kVelocityTol);
      EXPECT_LE(out.deepest, kGapTol) << "a disk went behind the paddle's face";
      EXPECT_LE(1.0 - out.slowest / speed, kVelocityTol) << "a disk was left behind";
    }
  }
}

TEST(ExtremesKinematic, Fx2dPaddlePushesASmallDiskAtAnySpeed)
{
  // The Fx2D order's correction leaves slop; its first touching frame can
  // end before the impact, so it must touch on more than one.
  expect_paddle_pushes(false, WorldSettings().slop + kGapTol, 1, {1.0, 4.0, 5.0, 7.0, 30.0, 100.0, 1e3, 1e4});
}

constexpr double kBarLength = 2.0;  // m, turning about its middle
constexpr double kBarStartTurn = -0.3;  // rad: the disk lies ahead of the face
constexpr double kDiskOnBar = 0.8;  // m from the bar's middle
constexpr int kMaxBarFrames = 600;
constexpr double kPi = 3.14159265358979323846;

struct Sweep
{
  double deepest = 0.0;    ///< largest sinking below the face while on the bar (m)
  double nearest_middle = 1e300;  ///< least height of the centre above the bar's middle plane (m)
  double fastest = 0.0;    ///< largest speed (m/s)
  double fastest_spin = 0.0;  ///< largest |omega| (rad/s)
  bool left = false;       ///< slid off the bar's end
};

Sweep sweep(World& world, double omega, double mu)
{
  Material material;
  material.static_friction = mu;
  material.kinetic_friction = mu;
  Body bar = scenes::make_box(1.0, kBarLength, kPaddleWidth, {0.0, 0.0}, kBarStartTurn);
  bar.set_type(BodyType::Kinematic);
  bar.set_omega(omega);
  const BodyId bar_id = world.add_body(bar, material);
  const BodyId disk_id = world.add_body(Body(1.0, kDiskRadius, {kDiskOnBar, 0.0}, {0.0, 0.0}), material);
  const double half = 0.5 * kBarLength;
  Sweep out;
  for (int f = 0; f < kMaxBarFrames && !out.left; ++f)
  {
    world.step();
    EXPECT_TRUE(test::all_finite(world));
    const double theta = world.body(bar_id).theta();
    const Vec2 c = world.body(disk_id).position();
    const Vec2 along{std::cos(theta), std::sin(theta)};
    const double x = dot(c, along);
    const double height = dot(c, perp(along));  // above the middle plane, on the face's side
    out.fastest = std::max(out.fastest, length(world.body(disk_id).velocity()));
    out.fastest_spin = std::max(out.fastest_spin, std::abs(world.body(disk_id).omega()));
    out.left = std::abs(x) > half + kDiskRadius;
    if (std::abs(x) <= half - kDiskRadius)
    {
      out.nearest_middle = std::min(out.nearest_middle, height);
      out.deepest = std::max(out.deepest, 0.5 * kPaddleWidth + kDiskRadius - height);
    }
  }
  return out;
}

/// The disk slid off the bar's end, never reached its middle plane, sank
/// no deeper than `sinking_bound` (m) and left no faster than the bar can
/// throw it.
void expect_left_the_bar(const Sweep& out, double omega, double sinking_bound)
{
  // A frictionless bead let go on the bar at rest relative to it leaves the
  // tip at omega sqrt(2 x^2 - x0^2 + d^2) <= sqrt(2) omega |tip|; friction
  // only slows its slide.
  const double tip = std::hypot(0.5 * kBarLength, 0.5 * kPaddleWidth + kDiskRadius);
  const double fastest_bound = std::sqrt(2.0) * omega * tip;
  test::print_figure("sinking below the face (mm)", 1e3 * out.deepest, 1e3 * sinking_bound);
  test::print_figure("fastest (m/s)", out.fastest, fastest_bound);
  EXPECT_TRUE(out.left) << "the disk never slid off the bar";
  EXPECT_GT(out.nearest_middle, 0.0) << "the disk went through the bar";
  EXPECT_LE(out.fastest, fastest_bound) << "faster than the bar can throw it";
  EXPECT_LE(out.deepest, sinking_bound) << "sank into the turning face deeper than its load allows";
}

TEST(ExtremesKinematic, SoftStepTurningBarKeepsASmallDiskAhead)
{
  for (double mu : {0.0, 0.5})
  {
    for (double omega : {1.0, 3.0, 5.0, 10.0, 20.0})
    {
      SCOPED_TRACE("bar at " + std::to_string(omega) + " rad/s, mu " + std::to_string(mu));
      World world = weightless_world(true);
      const Sweep out = sweep(world, omega, mu);
      // On the bar the disk needs at most the Coriolis push 2 omega v across
      // it; a spring of contact_hertz compresses by that over (2 pi f)^2.
      // With friction the disk rolls and sinks further, in proportion to its
      // spin and to the substep (at 1 rad/s 0.056 mm where the push
      // compresses the spring 0.015 mm; 0.016 mm at 16 substeps): that is
      // held to the overlap contacts may keep, `slop`, as in the Fx2D order.
      const double spring_rate = 2.0 * kPi * world.settings().contact_hertz;
      const double rolling = mu > 0.0 ? world.settings().slop : 0.0;
      const double sinking_bound = 2.0 * omega * out.fastest / (spring_rate * spring_rate) + rolling;
      std::printf("bar %g rad/s, mu %g:\n", omega, mu);
      expect_left_the_bar(out, omega, sinking_bound);
    }
  }
}

// Only friction can spin the disk: the face's normal passes through its
// centre. Friction is at most mu times the normal impulse J_n, so
// I |omega| <= mu R J_n with I = m R^2 / 2. In the bar's frame the strike
// gives the disk the face's speed omega x0, and sliding out by dx the face
// pushes at most the Coriolis 2 m omega x' across it: J_n <= m omega (x0 +
// 2 dx), and a tenth more for the spring's push-out of the strike's
// overlap. Before, the disk's lever arm was the one prepared, as long as
// the gap then (0.2 m, 20 radii) and half a substep's turn behind the
// normal: the disk spun 14 to 200 times past this bound (a bar crushing a
// disk in a corner spun it to 2500 rad/s).
TEST(ExtremesKinematic, SoftStepTurningBarSpinsADiskOnlyByFriction)
{
  constexpr double kFaintFriction = 1e-3;
  constexpr double kPushOut = 1.1;
  const double slide = 0.5 * kBarLength + kDiskRadius - kDiskOnBar;
  for (double omega : {5.0, 10.0, 20.0, 30.0, -20.0})
  {
    SCOPED_TRACE("bar at " + std::to_string(omega) + " rad/s");
    World world = weightless_world(true);
    const Sweep out = sweep(world, omega, kFaintFriction);
    const double normal_impulse = kPushOut * std::abs(omega) * (kDiskOnBar + 2.0 * slide);  // per kg
    const double spin_bound = 2.0 * kFaintFriction * normal_impulse / kDiskRadius;
    std::printf("bar %g rad/s, mu %g:\n", omega, kFaintFriction);
    test::print_figure("fastest spin of the disk (rad/s)", out.fastest_spin, spin_bound);
    EXPECT_TRUE(out.left) << "the disk never slid off the bar";
    EXPECT_LE(out.fastest_spin, spin_bound) << "spun faster than friction can";
  }
}

// A disk at rest just beyond the circle the bar's tip sweeps, so nothing of
// the bar can reach it. Its frame's contact is found on the bar's face
// (the bar's reach in a frame widens the margin); as the bar turns, the
// followed contact read the gap off the face's plane, which runs on past
// the tip: the disk sat deep in the plane and was struck at the speed the
// plane would have there (6.8 m/s at 10 rad/s, 34 m/s at 30). The point now
// follows the bar's nearest feature once the face is no longer it. A
// substep's straight move of the tip reaches past its circle by
// tip (sqrt(1 + (omega h)^2) - 1), which a speculative contact may close;
// the spins are those where the clearance is larger. Checked: the disk
// never moves (round-off aside), from three angles ahead of the bar.
TEST(ExtremesKinematic, SoftStepTurningBarDoesNotStrikeADiskBesideItsTip)
{
  constexpr double kClearance = 0.01;  // m beyond the tip's circle
  constexpr double kStill = 1e-9;      // m/s: round-off
  const double tip = std::hypot(0.5 * kBarLength, 0.5 * kPaddleWidth);
  double fastest_of_all = 0.0;
  for (double omega : {10.0, 20.0, 30.0, -20.0})
  {
    for (double ahead : {0.3, 0.7, 1.2})
    {
      SCOPED_TRACE("bar at " + std::to_string(omega) + " rad/s, disk " + std::to_string(ahead) + " rad ahead");
      World world = weightless_world(true);
      const double h = world.settings().dt / world.settings().substeps;
      ASSERT_GT(kClearance, tip * (std::sqrt(1.0 + omega * omega * h * h) - 1.0));
      Body bar = scenes::make_box(1.0, kBarLength, kPaddleWidth, {0.0, 0.0});
      bar.set_type(BodyType::Kinematic);
      bar.set_omega(omega);
      world.add_body(bar);
      const double at = std::copysign(ahead, omega);
      const double from_middle = tip + kDiskRadius + kClearance;
      const BodyId disk =
          world.add_body(Body(1.0, kDiskRadius, from_middle * Vec2{std::cos(at), std::sin(at)}, {0.0, 0.0}));
      double fastest = 0.0;
      for (int f = 0; f < kFrames; ++f)
      {
        world.step();
        fastest = std::max(fastest, length(world.body(disk).velocity()));
      }
      EXPECT_LE(fastest, kStill) << "the bar struck a disk it cannot reach";
      fastest_of_all = std::max(fastest_of_all, fastest);
    }
  }
  test::print_figure("disk beside the tip, fastest of all runs (m/s)", fastest_of_all, kStill);
}

// The Fx2D order finds contacts where a substep ends. A bar whose far points
// move more than its reach in a substep (here from 2.4 rad/s) is swept with
// its turn (time_of_impact with turns); the disk it strikes is carried round
// ahead of it, and a disk on it is lifted back onto the face where each
// substep ends (world_kinematic_push.cpp). Before, the bar went through the
// disk at 7 of the 21 spins from 10 to 30 rad/s in steps of 1 (first at 13).
// Checked as above, with the Fx2D order's slop for the sinking.
TEST(ExtremesKinematic, Fx2dTurningBarStrikesASmallDiskAtAnySpin)
{
  for (double omega : {1.0, 5.0, 10.0, 30.0, 100.0, 300.0, 1000.0})
  {
    SCOPED_TRACE("Fx2D, bar at " + std::to_string(omega) + " rad/s");
    World world = weightless_world(false);
    const Sweep out = sweep(world, omega, 0.0);
    std::printf("Fx2D: bar %g rad/s:\n", omega);
    expect_left_the_bar(out, omega, world.settings().slop + kGapTol);
  }
}

}  // namespace
}  // namespace collision2d
