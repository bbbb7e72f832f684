// The World in SolverMode::Exact: what it buys (a heavy-on-light stack at a
// 1e6 mass ratio settles where the contact compliance puts it and
// stays there, where the iterative passes let the heavy box fall through the
// light one), and that it keeps the contract of the iterative mode (Coulomb
// stick/slip on an incline with mu_s/mu_k, fallback when pivoting fails).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "collision2d/scenes/scene_parts.h"
#include "collision2d/scenes/standard_scenes.h"

namespace collision2d
{
namespace
{
constexpr double kMassRatio = 1e6;
// The compliance sag approaches its rest depth geometrically: each substep
// corrects K / (K + epsilon / h^2) of the excess, 1.7e-3 for the heavy box at
// the defaults, a time constant of about 2.4 s.
constexpr double kSettleSeconds = 15.0;  // s, six time constants
constexpr double kSeconds = 20.0;        // s, time the stack is watched

int frames_for(const World& world, double seconds)
{
  return static_cast<int>(std::lround(seconds / world.settings().dt));
}

/// How far a body has sunk below its start height (m).
double sink(const World& world, BodyId id, double start_y)
{
  return start_y - world.body(id).position().y;
}

struct Stack
{
  World world;
  BodyId light;
  BodyId heavy;
  double light_y;
  double heavy_y;
};

Stack heavy_on_light(SolverMode mode, double compliance)
{
  Scene scene = scenes::heavy_on_light(kMassRatio);
  scene.settings.solver_mode = mode;
  scene.settings.compliance = compliance;
  World world = make_world(scene);
  const std::vector<BodyId> ids = world.body_ids();
  Stack s{world, ids[1], ids[2], 0.0, 0.0};
  s.light_y = s.world.body(s.light).position().y;
  s.heavy_y = s.world.body(s.heavy).position().y;
  return s;
}

/// Rest depth of a box's two-point contact under `load` (N): each point is a
/// spring of compliance epsilon (the penetration pass's epsilon / h^2 term), the two
/// share the load, and the correction stops at slop. The ground gives nothing
/// beyond slop: the exact position LCP puts no compliance on a static body's
/// contacts.
double rest_depth(const WorldSettings& s, double load, bool on_ground)
{
  constexpr double kPointsPerFace = 2.0;
  return s.slop + (on_ground ? 0.0 : load * s.compliance / kPointsPerFace);
}

void expect_stack_rests(double compliance)
{
  // Compliance and slop are the Fx2D pipeline's (the soft step's exact mode:
  // WorldSoftStep.ExactModeHoldsAMillionKilogramBoxOnALightOneForAMinute).
  Stack s = heavy_on_light(SolverMode::Exact, compliance);
  WorldSettings fx2d = s.world.settings();
  fx2d.soft_step = false;
  s.world.set_settings(fx2d);
  const WorldSettings& settings = s.world.settings();
  const double g = -settings.gravity.y;
  const double heavy_weight = s.world.body(s.heavy).mass() * g;
  const double light_weight = s.world.body(s.light).mass() * g;
  const double light_expected = rest_depth(settings, heavy_weight + light_weight, true);
  const double heavy_expected = light_expected + rest_depth(settings, heavy_weight, false);

  StepReport report = s.world.step(frames_for(s.world, kSettleSeconds));
  EXPECT_EQ(report.exact_fallbacks, 0u);
  EXPECT_GT(report.exact_islands, 0u);
  const double heavy_settled = sink(s.world, s.heavy, s.heavy_y);
  report = s.world.step(frames_for(s.world, kSeconds - kSettleSeconds));
  const double light_sink = sink(s.world, s.light, s.light_y);
  const double heavy_sink = sink(s.world, s.heavy, s.heavy_y);
  std::printf("exact, compliance %g m/N: light sinks %.5f m (expected %.5f), heavy %.5f m (expected %.5f), "
              "heavy moved %.2e m in the last 5 s, velocity residual %.2e m/s\n",
              compliance, light_sink, light_expected, heavy_sink, heavy_expected,
              std::abs(heavy_sink - heavy_settled), report.velocity_residual);
  EXPECT_EQ(report.exact_fallbacks, 0u);
  constexpr double kRestTolerance = 0.01;
  EXPECT_NEAR(light_sink, light_expected, kRestTolerance * light_expected);
  EXPECT_NEAR(heavy_sink, heavy_expected, kRestTolerance * heavy_expected);
  EXPECT_LT(std::abs(heavy_sink - heavy_settled), kRestTolerance * heavy_expected);
  EXPECT_LT(std::abs(s.world.body(s.heavy).position().x), 1e-9);
  EXPECT_LT(std::abs(s.world.body(s.heavy).theta()), 1e-9);
  // Exact velocities: the resting contacts meet their targets to round-off
  // of the heavy box's speeds.
  EXPECT_LT(report.velocity_residual, 1e-9);
}

TEST(WorldExact, HeavyOnLightAtMassRatio1e6RestsAtItsComplianceDepth)
{
  // Default compliance 1e-8 m/N: the 1e7 N box presses each face ~5 cm in.
  expect_stack_rests(WorldSettings().compliance);
}

TEST(WorldExact, HeavyOnLightAtMassRatio1e6WithoutComplianceRestsAtSlop)
{
  expect_stack_rests(0.0);
}

TEST(WorldExact, IterativePassesLetTheHeavyBoxFallThrough)
{
  // The same scene with the default iterative settings: two Gauss-Seidel
  // passes cannot carry a 1e6 ratio, so the heavy box falls into the light
  // one (measured: about 1 m, a box height, within half a second).
  Stack s = heavy_on_light(SolverMode::Iterative, WorldSettings().compliance);
  s.world.step(frames_for(s.world, kSeconds));
  const double heavy_sink = sink(s.world, s.heavy, s.heavy_y);
  const double light_height = s.world.body(s.light).aabb().hi.y - s.world.body(s.light).aabb().lo.y;
  std::printf("iterative: heavy sinks %.3f m (light box %.3f m tall)\n", heavy_sink, light_height);
  EXPECT_GT(heavy_sink, 0.5 * light_height);
}

TEST(WorldExact, InclineSticksBelowStaticAndSlidesWithKineticFriction)
{
  // The LCP's cone is mu_s for a contact that stuck in the previous substep
  // and mu_k for one that slid, as in the iterative passes.
  const double mu_s = 0.5;
  const double mu_k = 0.3;
  Scene stick = scenes::incline(0.4, mu_s, mu_k);  // tan 0.4 = 0.42 < mu_s
  stick.settings.solver_mode = SolverMode::Exact;
  World still = make_world(stick);
  const BodyId box = still.body_ids().back();
  still.step();
  const Vec2 settled = still.body(box).position();
  const StepReport r = still.step(300);
  EXPECT_EQ(r.exact_fallbacks, 0u);
  EXPECT_LT(length(still.body(box).position() - settled), still.settings().slop);

  const double angle = 0.6;  // tan 0.6 = 0.68 > mu_s
  Scene slide = scenes::incline(angle, mu_s, mu_k);
  slide.settings.solver_mode = SolverMode::Exact;
  World sliding = make_world(slide);
  const Vec2 downhill{-std::cos(angle), -std::sin(angle)};
  sliding.step(30);
  const double v0 = dot(sliding.body(box).velocity(), downhill);
  const double t0 = sliding.time();
  EXPECT_EQ(sliding.step(60).exact_fallbacks, 0u);
  const double measured = (dot(sliding.body(box).velocity(), downhill) - v0) / (sliding.time() - t0);
  const double expected = -slide.settings.gravity.y * (std::sin(angle) - mu_k * std::cos(angle));
  std::printf("exact incline: a = %.5f m/s^2, g (sin - mu_k cos) = %.5f\n", measured, expected);
  EXPECT_NEAR(measured, expected, 0.01 * expected);
}

TEST(WorldExact, InfeasibleIslandFallsBackToThePassesAndIsCounted)
{
  // A disk pinched between two kinematic boxes closing in: no push-only
  // impulse can meet both Newton targets, so pivoting ends on a ray and the
  // island goes through the iterative passes; the step stays finite.
  WorldSettings settings;
  settings.gravity = Vec2{0.0, 0.0};
  settings.solver_mode = SolverMode::Exact;
  World world(settings);
  constexpr double kClosing = 1.0;  // m/s, each wall
  for (double side : {-1.0, 1.0})
  {
    Body wall = scenes::make_box(1.0, 1.0, 4.0, {side * 1.0, 0.0});
    wall.set_type(BodyType::Kinematic);
    wall.set_velocity(Vec2{-side * kClosing, 0.0});
    world.add_body(wall);
  }
  const BodyId disk = world.add_body(Body(1.0, 0.5, {0.0, 0.0}, {0.0, 0.0}));
  const StepReport report = world.step(3);
  EXPECT_GT(report.exact_fallbacks, 0u);
  EXPECT_TRUE(is_finite(world.body(disk).position()));
  EXPECT_TRUE(is_finite(world.body(disk).velocity()));
}

TEST(WorldExact, SettingIsValidated)
{
  WorldSettings s;
  s.solver_mode = static_cast<SolverMode>(7);
  EXPECT_THROW(World::validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace collision2d
