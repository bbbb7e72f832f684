// Sweep grids (see sweep.h).
#include "sweep.h"

#include <algorithm>
#include <cstdio>
#include <type_traits>
#include <utility>

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kStandSeconds = 60.0;       // the target: stacks stand for a minute (s)
// The most accurate stacking setting found for the World: many substeps and
// position passes with a slop of 10 um.
constexpr int kPreciseSubsteps = 16;
constexpr int kPreciseVelocityIterations = 4;
constexpr int kPrecisePositionIterations = 16;
constexpr double kPreciseSlop = 1e-5;  // m
constexpr double kQuickStandSeconds = 20.0;  // s
constexpr int kExactFallbackIterations = 256;  // cap of the iterative solve an exact failure falls back to
// The second setting warm_start_before_integration is swept at (see add_warm_before_integration).
constexpr int kWarmIntegrationSubsteps = 8;
constexpr int kWarmIntegrationIterations = 4;
// The soft step's stiffer stand setting: 120 Hz contacts need 8 substeps
// (the stiffness is capped at a quarter of the substep rate).
constexpr int kSoftStiffSubsteps = 8;
constexpr double kSoftStiffHertz = 120.0;

/// SFINAE: true when WorldSettings has a `solver_mode` field; the benchmark
/// then sweeps it without needing a code change.
template <typename S, typename = void>
struct HasSolverMode : std::false_type
{
};
template <typename S>
struct HasSolverMode<S, std::void_t<decltype(std::declval<S&>().solver_mode = SolverMode::Exact)>> : std::true_type
{
};

template <typename S>
bool set_solver_mode(S& settings, SolverMode mode)
{
  if constexpr (HasSolverMode<S>::value)
  {
    settings.solver_mode = mode;
    return true;
  }
  else
  {
    (void)settings;
    (void)mode;
    return false;
  }
}

/// A template so that the branch naming the missing field is never compiled.
template <typename S>
std::string solver_mode_of(const S& settings)
{
  if constexpr (HasSolverMode<S>::value)
  {
    return settings.solver_mode == SolverMode::Exact ? "exact" : "iterative";
  }
  else
  {
    (void)settings;
    return "iterative";
  }
}

bool is_headline(const BenchScene& s)
{
  return s.name == "pyramid" || s.name == "column" || s.name == "elastic_gas";
}

bool is_stack(const BenchScene& s)
{
  return s.name == "pyramid" || s.name == "column";
}

bool is_mass_ratio(const BenchScene& s)
{
  return s.name.compare(0, 15, "heavy_on_light_") == 0;
}

/// Scenes whose bodies come to rest: a world that sleeps then holds them
/// still at little cost (the peers sleep at their defaults too).
bool comes_to_rest(const BenchScene& s) { return s.kind == SceneKind::Resting || s.kind == SceneKind::Incline; }

std::string text(double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

EngineConfig ours(const WorldSettings& settings)
{
  return EngineConfig{EngineKind::Collision2d, PeerVariant::Matched, settings};
}

WorldSettings with_steps(WorldSettings s, int substeps, int iterations)
{
  s.substeps = substeps;
  s.velocity_iterations = iterations;
  return s;
}

std::string steps_text(int substeps, int iterations)
{
  return std::to_string(substeps) + "x" + std::to_string(iterations);
}

/// The same run list whatever the pipeline: runs.push_back(knob, value, settings).
struct Runs
{
  std::vector<RunSpec>& out;
  void add(const std::string& knob, const std::string& value, const WorldSettings& settings)
  {
    out.push_back(RunSpec{knob, value, ours(settings)});
  }
};

void add_iterations(const WorldSettings& base, const std::vector<int>& values, Runs runs)
{
  for (int it : values)
  {
    runs.add("iterations", std::to_string(it), with_steps(base, base.substeps, it));
  }
}

void add_substeps(const WorldSettings& base, const std::vector<int>& values, Runs runs)
{
  for (int n : values)
  {
    runs.add("substeps", std::to_string(n), with_steps(base, n, base.velocity_iterations));
  }
}

void add_toggles(const WorldSettings& base, Toggle WorldSettings::*field, const char* knob,
                 const std::vector<Toggle>& values, Runs runs)
{
  for (Toggle t : values)
  {
    WorldSettings s = base;
    s.*field = t;
    runs.add(knob, toggle_name(t), s);
  }
}

/// One double-valued knob of the settings at each value.
void add_values(const WorldSettings& base, double WorldSettings::*field, const char* knob,
                const std::vector<double>& values, Runs runs)
{
  for (double v : values)
  {
    WorldSettings s = base;
    s.*field = v;
    runs.add(knob, text(v), s);
  }
}

/// One bool knob set to the opposite of its value in `base`.
void add_flip(const WorldSettings& base, bool WorldSettings::*field, const char* knob, Runs runs)
{
  WorldSettings s = base;
  s.*field = !(base.*field);
  runs.add(knob, s.*field ? "on" : "off", s);
}

/// Poses advanced with predicted velocities, on and off, at the scene's
/// setting and at 8x4 (where its gain on stacks shows without its 4x2
/// failure on the pyramid).
void add_warm_before_integration(const WorldSettings& base, Runs runs)
{
  for (const WorldSettings& steps : {base, with_steps(base, kWarmIntegrationSubsteps, kWarmIntegrationIterations)})
  {
    for (bool on : {false, true})
    {
      WorldSettings s = steps;
      s.warm_start_before_integration = on;
      runs.add("warm_before_integration", steps_text(s.substeps, s.velocity_iterations) + (on ? " on" : " off"), s);
    }
  }
}

/// The exact solver mode (the iterative one is the baseline).
void add_exact(const WorldSettings& base, Runs runs)
{
  WorldSettings s = base;
  if (set_solver_mode(s, SolverMode::Exact))
  {
    runs.add("solver_mode", mode_name(SolverMode::Exact), s);
  }
}

void add_grid(const WorldSettings& base, const std::vector<int>& substeps, const std::vector<int>& iterations,
              Runs runs)
{
  for (int n : substeps)
  {
    for (int it : iterations)
    {
      runs.add("grid", steps_text(n, it), with_steps(base, n, it));
    }
  }
}

/// The Fx2D pipeline's runs (`base` has soft_step off).
void fx2d_world_runs(const BenchScene& scene, const WorldSettings& base, bool quick, Runs runs)
{
  runs.add("baseline", steps_text(base.substeps, base.velocity_iterations), base);
  // The pyramid is one cluster of 210 boxes (~2400 complementarity rows):
  // pivoting it did not finish 30 frames in several minutes, so it is left out.
  if (scene.name != "pyramid")
  {
    add_exact(base, runs);
  }
  if (comes_to_rest(scene))
  {
    add_toggles(base, &WorldSettings::sleeping, "sleeping", {Toggle::On}, runs);
  }
  if (scene.kind == SceneKind::Bullet)
  {
    add_toggles(base, &WorldSettings::time_of_impact, "time_of_impact", {Toggle::On, Toggle::Off}, runs);
    add_substeps(base, quick ? std::vector<int>{1, 16} : std::vector<int>{1, 2, 8, 16}, runs);
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
    if (set_solver_mode(rigid, SolverMode::Exact))
    {
      runs.add("compliance", "compliance 0", rigid);
      WorldSettings loose = rigid;
      loose.exact_position_correction = !rigid.exact_position_correction;
      runs.add("exact_position_correction",
               std::string(loose.exact_position_correction ? "on" : "off") + " (compliance 0)", loose);
    }
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
  runs.add("baseline", steps_text(base.substeps, base.velocity_iterations), base);
  // The exact mode in the soft step: as in Fx2D, not on the pyramid's one big cluster.
  if (scene.name != "pyramid")
  {
    add_exact(base, runs);
  }
  if (comes_to_rest(scene))
  {
    add_toggles(base, &WorldSettings::sleeping, "sleeping", {Toggle::On}, runs);
  }
  if (scene.kind == SceneKind::Bullet)
  {
    add_toggles(base, &WorldSettings::time_of_impact, "time_of_impact", {Toggle::On, Toggle::Off}, runs);
    add_substeps(base, quick ? std::vector<int>{1, 16} : std::vector<int>{1, 2, 8, 16}, runs);
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

bool world_has_solver_mode()
{
  return HasSolverMode<WorldSettings>::value;
}

WorldSettings with_pipeline(WorldSettings settings, Pipeline pipeline)
{
  settings.soft_step = pipeline == Pipeline::Soft;
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
  // The exact mode on the column (one cluster of 20 boxes), as in Fx2D below.
  WorldSettings soft_exact = soft;
  if (!pyramid && set_solver_mode(soft_exact, SolverMode::Exact))
  {
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
  // The exact mode on the column (one cluster of 20 boxes); the pyramid's
  // 210-box cluster is too costly to pivot for a minute within the budget.
  WorldSettings exact = fx2d;
  if (!pyramid && set_solver_mode(exact, SolverMode::Exact))
  {
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
  return solver_mode_of(settings);
}

}  // namespace bench
}  // namespace collision2d
