// Scale: the same scene at sizes 1e-4 m to 1e4 m gives the same
// dimensionless result. Lengths, speeds and gravity scale with the size L
// (times and masses do not); every setting that is a length or a speed must
// scale with it too, and the tests do so:
//   ContactSolver: slop (m) and tol (m/s);
//   World: slop (m), restitution_threshold (m/s), sleep_linear_speed (m/s)
//   and gravity (m/s^2). compliance (m/N, entering as compliance / h^2 in
//   1/kg) and every dimensionless setting stay as they are.
// Everything else in the core is relative already (touch tolerance, duplicate
// vertices, reference-face bias). With the defaults left unscaled, slop is
// 1 mm whatever the size: a 1 cm stack then rests 8% deep in itself, a 1e-4 m
// stack sinks entirely (the last test shows the first).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scene.h"
#include "collision2d/scenes/random_scenes.h"
#include "collision2d/scenes/scene_parts.h"
#include "extremes_support.h"

namespace collision2d
{
namespace
{
const std::vector<double> kScales = {1e-4, 1e-2, 1.0, 1e2, 1e4};
/// Dimensionless differences (velocities / (L * speed scale), positions / L):
/// round-off of the scaled inputs and of the solver's tolerance.
constexpr double kSolveRelativeTol = 1e-9;
/// World runs repeat the substep pipeline many times over contacts that
/// appear and vanish, so round-off differences grow a little.
constexpr double kWorldRelativeTol = 1e-6;

Body scaled(const Body& b, double L)
{
  Body out = b.shape() == Shape::Disk
                 ? Body(b.mass(), b.radius() * L, b.position() * L, b.velocity() * L, b.omega())
                 : [&] {
                     std::vector<Vec2> outline;
                     for (const Vec2& v : b.local_vertices())
                     {
                       outline.push_back(v * L);
                     }
                     return Body(b.mass(), outline, b.position() * L, b.velocity() * L, b.theta(), b.omega());
                   }();
  out.set_type(b.type());
  return out;
}

double speed_scale(const std::vector<Body>& bodies)
{
  double s = 0.0;
  for (const Body& b : bodies)
  {
    s = std::max({s, length(b.velocity()), std::abs(b.omega()) * b.radius()});
  }
  return s;
}

TEST(ExtremesScale, ResolveIsScaleFree)
{
  const long scene_count = test::sized(300, 60, "scale scenes");
  scenes::RandomSceneOptions options;
  options.static_probability = 0.2;
  scenes::RandomSceneGenerator generator(0x5ca1e, options);
  constexpr double kSlop = 1e-3;  // m at L = 1
  constexpr double kTol = 1e-12;  // m/s at L = 1
  double worst = 0.0;
  for (long k = 0; k < scene_count; ++k)
  {
    const scenes::RandomScene scene = generator.next();
    std::vector<Body> reference = scene.bodies;
    const double speed = std::max(speed_scale(reference), 1e-3);
    ContactSolver(scene.restitution, scene.friction, 1000, kTol, 0.2, kSlop).resolve(reference);
    for (double L : kScales)
    {
      std::vector<Body> bodies;
      for (const Body& b : scene.bodies)
      {
        bodies.push_back(scaled(b, L));
      }
      ContactSolver(scene.restitution, scene.friction, 1000, kTol * L, 0.2, kSlop * L).resolve(bodies);
      for (std::size_t i = 0; i < bodies.size(); ++i)
      {
        const double dv = std::max(length(bodies[i].velocity() / L - reference[i].velocity()),
                                   std::abs(bodies[i].omega() - reference[i].omega()) * reference[i].radius()) /
                          speed;
        const double dp = std::max(length(bodies[i].position() / L - reference[i].position()),
                                   std::abs(bodies[i].theta() - reference[i].theta()));
        worst = std::max({worst, dv, dp});
        ASSERT_LE(std::max(dv, dp), kSolveRelativeTol) << "scene " << k << ", L " << L << ", body " << i;
      }
    }
  }
  std::printf("%ld random scenes resolved at L = 1e-4..1e4 m:\n", scene_count);
  test::print_figure("largest dimensionless difference from L = 1", worst, kSolveRelativeTol);
}

/// A 5-box column on the ground, everything of length or speed scaled by L.
World column_world(double L, bool scale_settings, bool with_disk)
{
  Scene scene;
  scenes::GroundParams ground;
  ground.width = 10.0 * L;
  ground.thickness = L;
  scenes::add_ground(scene, ground);
  scenes::ColumnParams column;
  column.count = 5;
  column.box = L;
  column.at = {0.0, 0.5 * L};
  scenes::add_column(scene, column);
  // A thrown disk so the run has an impact and friction, not only rest.
  if (with_disk)
    scene.bodies.push_back(SceneBody{Body(0.5, 0.3 * L, {-3.0 * L, 2.0 * L}, {6.0 * L, 0.0}, 2.0),
                                   Material{0.5, 0.4, 0.3}, "disk"});
  WorldSettings& s = scene.settings;
  s.gravity = s.gravity * L;
  if (scale_settings)
  {
    s.slop *= L;
    s.restitution_threshold *= L;
    s.sleep_linear_speed *= L;
    s.contact_push_speed *= L;
    s.speculative_margin *= L;
    s.contact_reuse_distance *= L;
  }
  return make_world(scene);
}

/// Largest dimensionless difference between two worlds of the same bodies at
/// scales L and 1.
double world_difference(const World& world, const World& reference, double L)
{
  double worst = 0.0;
  for (BodyId id : world.body_ids())
  {
    const Body& b = world.body(id);
    const Body& r = reference.body(id);
    worst = std::max({worst, length(b.position() / L - r.position()), std::abs(b.theta() - r.theta()),
                      length(b.velocity() / L - r.velocity())});
  }
  return worst;
}

// Powers of two scale every length exactly in binary, so any absolute length
// or speed hidden in the world's code would show as a difference; a
// thrown disk hitting the column exercises impacts, friction and rotation.
TEST(ExtremesScale, WorldIsScaleFreeAtPowerOfTwoScales)
{
  const int frames = static_cast<int>(test::sized(240, 60, "scale world frames"));
  World reference = column_world(1.0, true, true);
  reference.step(frames);
  constexpr double kExactTol = 1e-12;
  double worst = 0.0;
  for (int exponent : {-14, -7, 7, 14})  // L = 6.1e-5 m .. 1.6e4 m
  {
    const double L = std::ldexp(1.0, exponent);
    World world = column_world(L, true, true);
    world.step(frames);
    ASSERT_TRUE(test::all_finite(world));
    const double d = world_difference(world, reference, L);
    EXPECT_LE(d, kExactTol) << "L = 2^" << exponent;
    worst = std::max(worst, d);
  }
  std::printf("column + thrown disk, %d frames at L = 2^-14..2^14 m:\n", frames);
  test::print_figure("largest dimensionless difference from L = 1", worst, kExactTol);
}

// At decimal scales the inputs themselves carry round-off (0.005 m is not
// exact), which a resting column absorbs. (The thrown disk is left out here:
// whether it grazes a corner is decided by round-off, so its path may differ
// by its own size between scales, as it would between two runs at the same
// scale with inputs one ulp apart.)
TEST(ExtremesScale, RestingColumnIsScaleFreeAtDecimalScales)
{
  const int frames = static_cast<int>(test::sized(240, 60, "scale world frames"));
  World reference = column_world(1.0, true, false);
  reference.step(frames);
  double worst = 0.0;
  for (double L : kScales)
  {
    World world = column_world(L, true, false);
    world.step(frames);
    ASSERT_TRUE(test::all_finite(world));
    const double d = world_difference(world, reference, L);
    EXPECT_LE(d, kWorldRelativeTol) << "L " << L;
    worst = std::max(worst, d);
  }
  std::printf("resting column, %d frames at L = 1e-4..1e4 m:\n", frames);
  test::print_figure("largest dimensionless difference from L = 1", worst, kWorldRelativeTol);
}

/// Deepest resting penetration of the column after `frames`, as a fraction of
/// the box size L.
double resting_depth_fraction(double L, bool scale_settings, int frames)
{
  World world = column_world(L, scale_settings, false);
  WorldSettings fx2d = world.settings();
  fx2d.soft_step = false;  // slop is a setting of the Fx2D pipeline
  world.set_settings(fx2d);
  const StepReport report = world.step(frames);
  return report.max_penetration / L;
}

TEST(ExtremesScale, UnscaledSlopDominatesSmallScenes)
{
  const int frames = static_cast<int>(test::sized(120, 60, "unscaled slop frames"));
  constexpr double kSmall = 1e-2;  // m
  const double scaled_depth = resting_depth_fraction(kSmall, true, frames);
  const double unscaled_depth = resting_depth_fraction(kSmall, false, frames);
  const double unit_depth = resting_depth_fraction(1.0, true, frames);
  // Scaled, the stack rests as deep (relative to its size) as at 1 m; with the
  // 1 mm default slop it rests about a slop (10% of the box) deep.
  constexpr double kSlopEffect = 10.0;
  EXPECT_NEAR(scaled_depth, unit_depth, kWorldRelativeTol);
  EXPECT_GE(unscaled_depth, kSlopEffect * scaled_depth);
  std::printf("1 cm column: resting depth / box size\n");
  test::print_figure("slop scaled to 1e-5 m (as at 1 m)", scaled_depth, unit_depth);
  test::print_figure("default slop 1e-3 m (at least 10x the scaled depth)", unscaled_depth, kSlopEffect * scaled_depth);
}

}  // namespace
}  // namespace collision2d
