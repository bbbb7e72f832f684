// Sweep grids (see sweep.h); their building blocks are sweep_runs.h.
#include "sweep.h"

#include <algorithm>
#include <utility>

#include "sweep_runs.h"

namespace collision2d
{
namespace bench
{
namespace
{
using namespace sweep;

constexpr double kStandSeconds = 60.0;       // the target: stacks stand for a minute (s)
// The most accurate stacking setting found for the World: many substeps and
// position passes with a slop of 10 um.
constexpr int kPreciseSubsteps = 16;
constexpr int kPreciseVelocityIterations = 4;
constexpr int kPrecisePositionIterations = 16;
constexpr double kPreciseSlop = 1e-5;  // m
constexpr double kQuickStandSeconds = 20.0;  // s
constexpr int kExactFallbackIterations = 256;  // cap of the iterative solve an exact failure falls back to
// The soft step's stiffer stand setting: 120 Hz contacts need 8 substeps
// (the stiffness is capped at a quarter of the substep rate).
constexpr int kSoftStiffSubsteps = 8;
constexpr double kSoftStiffHertz = 120.0;

/// The runs both pipelines start with: the baseline, the exact mode and
/// sleeping where the scene comes to rest.
void add_common_runs(const BenchScene& scene, const WorldSettings& base, Runs runs)
{
  runs.add("baseline", steps_text(base.substeps, base.velocity_iterations), base);
  // The pyramid is one island of 210 boxes (~2400 complementarity rows):
  // pivoting it did not finish 30 frames in several minutes, so it is left out.
  if (scene.name != "pyramid")
  {
    add_exact(base, runs);
  }
  if (comes_to_rest(scene))
  {
    add_sleeping(base, runs);
  }
}

/// A bullet scene's runs in both pipelines: the time of impact and the substeps.
void add_bullet_runs(const WorldSettings& base, bool quick, Runs runs)
{
  add_toggles(base, &WorldSettings::time_of_impact, "time_of_impact", {Toggle::On, Toggle::Off}, runs);
  add_substeps(base, quick ? std::vector<int>{1, 16} : std::vector<int>{1, 2, 8, 16}, runs);
}

/// The Fx2D pipeline's runs (`base` has soft_step off).
void fx2d_world_runs(const BenchScene& scene, const WorldSettings& base, bool quick, Runs runs)
{
  add_common_runs(scene, base, runs);
  if (scene.kind == SceneKind::Bullet)
  {
    add_bullet_runs(base, quick, runs);
    return;
  }
  if (is_mass_ratio(scene))
  {
    add_iterations(base, quick ? std::vector<int>{8} : std::vector<int>{8, 32, 128}, runs);
    add_substeps(base, {16}, runs);
    // The default compliance lets a 1e6 kg box sink by load x compliance
    // (~0.1 m) by design; a rigid contact shows what the exact mode holds.
    WorldSettings rigid = base;
    rigid.compliance = 0.0;
    rigid.solver_mode = SolverMode::Exact;
    runs.add("compliance", "compliance 0", rigid);
    WorldSettings loose = rigid;
    loose.exact_position_correction = !rigid.exact_position_correction;
    runs.add("exact_position_correction",
             std::string(loose.exact_position_correction ? "on" : "off") + " (compliance 0)", loose);
    return;
  }
  // Every pass over the pyramid's ~800 contact points costs: 64 iterations
  // already take ~30 ms a frame, so the pyramid stops there to keep the whole
  // report within its time budget on two shared cores.
  const std::vector<int> full_iterations = scene.name == "pyramid" ? std::vector<int>{1, 2, 4, 8, 16, 64}
                                                                   : std::vector<int>{1, 2, 4, 8, 16, 64, 256};
  add_iterations(base, quick ? std::vector<int>{1, 8, 32} : full_iterations, runs);
  add_substeps(base, quick ? std::vector<int>{1, 16} : std::vector<int>{1, 2, 8, 16}, runs);
  add_toggles(base, &WorldSettings::warm_starting, "warm_starting", {Toggle::On, Toggle::Off}, runs);
  if (is_headline(scene))
  {
    add_values(base, &WorldSettings::slop, "slop", {1e-4, 1e-2}, runs);
    add_toggles(base, &WorldSettings::time_of_impact, "time_of_impact", {Toggle::On, Toggle::Off}, runs);
  }
  if (is_stack(scene))
  {
    add_warm_before_integration(base, runs);
    for (int passes : quick ? std::vector<int>{16} : std::vector<int>{1, 16})
    {
      WorldSettings s = base;
      s.position_iterations = passes;
      runs.add("position_iterations", std::to_string(passes), s);
    }
    add_flip(base, &WorldSettings::position_block, "position_block", runs);
  }
  if (is_headline(scene) && !quick)
  {
    add_grid(base, {1, 2, 8}, {1, 8}, runs);
  }
}

/// The soft step's runs (`base` has soft_step on). Its contacts are springs
/// found once a frame: the slop and the position passes do not enter it.
void soft_world_runs(const BenchScene& scene, const WorldSettings& base, bool quick, Runs runs)
{
  add_common_runs(scene, base, runs);
  if (scene.kind == SceneKind::Bullet)
  {
    add_bullet_runs(base, quick, runs);
    add_values(base, &WorldSettings::speculative_margin, "speculative_margin", {0.0}, runs);
    return;
  }
  if (is_mass_ratio(scene))
  {
    add_iterations(base, {8}, runs);
    add_substeps(base, {16}, runs);
    add_values(base, &WorldSettings::contact_hertz, "contact_hertz", quick ? std::vector<double>{10.0}
                                                                          : std::vector<double>{10.0, 60.0}, runs);
    return;
  }
  add_iterations(base, quick ? std::vector<int>{8} : std::vector<int>{1, 8}, runs);
  add_substeps(base, quick ? std::vector<int>{1, 16} : std::vector<int>{1, 2, 8, 16}, runs);
  add_toggles(base, &WorldSettings::warm_starting, "warm_starting", {Toggle::On, Toggle::Off}, runs);
  // The stiffness is capped at a quarter of the substep rate (60 Hz at 4
  // substeps of a 60 Hz frame): stiffer springs need more substeps.
  add_values(base, &WorldSettings::contact_hertz, "contact_hertz",
             quick ? std::vector<double>{10.0} : std::vector<double>{10.0, 60.0}, runs);
  add_values(base, &WorldSettings::contact_damping_ratio, "contact_damping_ratio",
             quick ? std::vector<double>{1.0} : std::vector<double>{1.0, 100.0}, runs);
  if (!quick)
  {
    add_values(base, &WorldSettings::contact_push_speed, "contact_push_speed", {1.0, 10.0}, runs);
  }
  add_values(base, &WorldSettings::speculative_margin, "speculative_margin",
             quick ? std::vector<double>{0.1} : std::vector<double>{0.005, 0.1}, runs);
  // 0: found every frame (the nudged column buckles); 5 mm finds them again sooner.
  add_values(base, &WorldSettings::contact_reuse_distance, "contact_reuse_distance",
             quick ? std::vector<double>{0.0} : std::vector<double>{0.0, 0.005}, runs);
  if (is_headline(scene))
  {
    add_toggles(base, &WorldSettings::time_of_impact, "time_of_impact", {Toggle::On, Toggle::Off}, runs);
    // Stiffer contacts with the substeps that allow them.
    for (const auto& point : std::vector<std::pair<int, double>>{{8, 120.0}, {16, 240.0}})
    {
      if (quick && point.first == 16)
      {
        continue;
      }
      WorldSettings s = with_steps(base, point.first, base.velocity_iterations);
      s.contact_hertz = point.second;
      runs.add("contact_hertz", text(point.second), s);
    }
    // Or the stiff setting for tall stacks: 6 substeps, their stiffest
    // contacts, 2 passes (and 4).
    for (int passes : quick ? std::vector<int>{kStiffPasses} : std::vector<int>{kStiffPasses, 2 * kStiffPasses})
    {
      runs.add("soft_iterations", std::to_string(passes), with_stiff_contacts(base, passes));
    }
  }
  if (is_headline(scene) && !quick)
  {
    add_grid(base, {1, 2, 8}, {1, 8}, runs);
  }
}

/// The (substeps, iterations) points where peers run matched to us.
std::vector<std::pair<int, int>> matched_points(const BenchScene& scene, bool quick)
{
  const WorldSettings& s = scene.scene.settings;
  if (quick || !is_headline(scene))
  {
    return {{s.substeps, s.velocity_iterations}, {1, 8}};
  }
  return {{s.substeps, s.velocity_iterations}, {1, 8}, {4, 8}, {8, 8}};
}

RunSpec long_run(const std::string& knob, const std::string& value, const WorldSettings& s, double seconds)
{
  RunSpec run{knob, value, ours(s)};
  run.seconds = seconds;
  return run;
}

}  // namespace

WorldSettings with_pipeline(WorldSettings settings, Pipeline pipeline)
{
  settings.soft_step = pipeline == Pipeline::Soft;
  return settings;
}

WorldSettings with_stiff_contacts(WorldSettings settings, int passes)
{
  // The World caps a contact's stiffness at a quarter of the substep rate:
  // 6 substeps of a 60 Hz frame allow 90 Hz.
  constexpr int kStiffSubsteps = 6;
  constexpr double kStiffHertz = 90.0;  // Hz
  // More damped than the defaults' 10: a base-100 pyramid's breathing
  // settles within the first second (docs/performance.md).
  constexpr double kStiffDampingRatio = 15.0;
  settings.soft_step = true;
  settings.substeps = kStiffSubsteps;
  settings.contact_hertz = kStiffHertz;
  settings.contact_damping_ratio = kStiffDampingRatio;
  settings.soft_iterations = passes;
  return settings;
}

std::string pipeline_name(const WorldSettings& settings)
{
  return settings.soft_step ? "soft" : "fx2d";
}

std::string default_pipeline_name()
{
  return pipeline_name(WorldSettings{});
}

std::vector<RunSpec> world_runs(const BenchScene& scene, bool quick)
{
  std::vector<RunSpec> runs;
  soft_world_runs(scene, with_pipeline(scene.scene.settings, Pipeline::Soft), quick, Runs{runs});
  fx2d_world_runs(scene, with_pipeline(scene.scene.settings, Pipeline::Fx2d), quick, Runs{runs});
  return runs;
}

std::vector<RunSpec> peer_runs(const BenchScene& scene, bool quick)
{
  std::vector<RunSpec> runs;
  for (EngineKind kind : {EngineKind::Box2d, EngineKind::Chipmunk, EngineKind::Box2dV3})
  {
    if (!engine_available(kind))
    {
      continue;
    }
    runs.push_back(RunSpec{"defaults", "", EngineConfig{kind, PeerVariant::Defaults, scene.scene.settings}});
    std::vector<int> substeps_done;
    for (const auto& point : matched_points(scene, quick))
    {
      // Box2D v3 has no iteration count: points differing only in it would repeat one run.
      if (kind == EngineKind::Box2dV3 &&
          std::find(substeps_done.begin(), substeps_done.end(), point.first) != substeps_done.end())
      {
        continue;
      }
      substeps_done.push_back(point.first);
      const WorldSettings s = with_steps(scene.scene.settings, point.first, point.second);
      runs.push_back(RunSpec{"matched", steps_text(point.first, point.second),
                             EngineConfig{kind, PeerVariant::Matched, s}});
    }
  }
  // Ours at the matched points in both pipelines, so the ratios compare like with like.
  for (Pipeline pipeline : {Pipeline::Soft, Pipeline::Fx2d})
  {
    for (const auto& point : matched_points(scene, quick))
    {
      const WorldSettings s = with_steps(with_pipeline(scene.scene.settings, pipeline), point.first, point.second);
      runs.push_back(RunSpec{"matched", steps_text(point.first, point.second), ours(s)});
    }
  }
  return runs;
}

std::vector<RunSpec> stand_runs(const BenchScene& scene, bool quick)
{
  const double seconds = quick ? kQuickStandSeconds : kStandSeconds;
  // A 60 s pyramid costs 3600 frames of several ms each: two settings only.
  const bool pyramid = scene.name == "pyramid";
  const std::vector<std::pair<int, int>> points =
      quick || pyramid ? std::vector<std::pair<int, int>>{{4, 2}, {8, 4}}
                       : std::vector<std::pair<int, int>>{{4, 2}, {4, 8}, {8, 8}, {16, 16}};
  std::vector<RunSpec> runs;
  // The soft step at the same points, and stiffer contacts with 8 substeps.
  const WorldSettings soft = with_pipeline(scene.scene.settings, Pipeline::Soft);
  for (const auto& point : points)
  {
    runs.push_back(long_run("stand", steps_text(point.first, point.second),
                            with_steps(soft, point.first, point.second), seconds));
  }
  WorldSettings stiff = with_steps(soft, kSoftStiffSubsteps, soft.velocity_iterations);
  stiff.contact_hertz = kSoftStiffHertz;
  runs.push_back(long_run("contact_hertz", text(kSoftStiffHertz), stiff, seconds));
  runs.push_back(long_run("soft_iterations", std::to_string(kStiffPasses), with_stiff_contacts(soft), seconds));
  // The exact mode on the column (one island of 20 boxes), as in Fx2D below.
  if (!pyramid)
  {
    WorldSettings soft_exact = soft;
    soft_exact.solver_mode = SolverMode::Exact;
    runs.push_back(long_run("stand", "exact", soft_exact, seconds));
  }

  const WorldSettings fx2d = with_pipeline(scene.scene.settings, Pipeline::Fx2d);
  for (const auto& point : points)
  {
    runs.push_back(long_run("stand", steps_text(point.first, point.second),
                            with_steps(fx2d, point.first, point.second), seconds));
  }
  // The same stacks with the poses advanced by predicted velocities.
  for (const auto& point : std::vector<std::pair<int, int>>{{4, 2}, {8, 4}})
  {
    WorldSettings s = with_steps(fx2d, point.first, point.second);
    s.warm_start_before_integration = true;
    runs.push_back(long_run("stand", steps_text(point.first, point.second) + " warm before integration", s, seconds));
  }
  // The precise setting: many substeps and position passes with a small slop.
  WorldSettings precise = with_steps(fx2d, kPreciseSubsteps, kPreciseVelocityIterations);
  precise.position_iterations = kPrecisePositionIterations;
  precise.slop = kPreciseSlop;
  runs.push_back(long_run("precise", "16 position passes slop 1e-5", precise, seconds));
  // The exact mode on the column (one island of 20 boxes); the pyramid's
  // 210-box island is too costly to pivot for a minute within the budget.
  if (!pyramid)
  {
    WorldSettings exact = fx2d;
    exact.solver_mode = SolverMode::Exact;
    runs.push_back(long_run("stand", "exact", exact, seconds));
  }
  return runs;
}

std::vector<SolverSweepPoint> solver_points(bool quick)
{
  const std::vector<int> iterations = quick ? std::vector<int>{1, 16, 256} : std::vector<int>{1, 4, 16, 64, 256};
  const std::vector<double> tolerances = quick ? std::vector<double>{1e-3, 1e-12}
                                               : std::vector<double>{1e-3, 1e-6, 1e-9, 1e-12};
  std::vector<SolverSweepPoint> points;
  for (double ratio : {100.0, 1e6})
  {
    for (int it : iterations)
    {
      for (double tol : tolerances)
      {
        points.push_back(SolverSweepPoint{SolverMode::Iterative, it, tol, ratio});
      }
    }
    for (double tol : tolerances)
    {
      // Pivoting ignores the iteration cap (it only bounds the iterative
      // fallback); tol only judges convergence.
      points.push_back(SolverSweepPoint{SolverMode::Exact, kExactFallbackIterations, tol, ratio});
    }
  }
  return points;
}

std::string toggle_name(Toggle toggle)
{
  switch (toggle)
  {
    case Toggle::Auto:
      return "auto";
    case Toggle::On:
      return "on";
    case Toggle::Off:
      return "off";
  }
  return "?";
}

std::string mode_name(SolverMode mode)
{
  return mode == SolverMode::Exact ? "exact" : "iterative";
}

std::string world_mode_name(const WorldSettings& settings)
{
  return mode_name(settings.solver_mode);
}

}  // namespace bench
}  // namespace collision2d
