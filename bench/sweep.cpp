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

bool is_mass_ratio(const BenchScene& s)
{
  return s.name.compare(0, 15, "heavy_on_light_") == 0;
}

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

void add_iterations(const WorldSettings& base, const std::vector<int>& values, std::vector<RunSpec>& runs)
{
  for (int it : values)
  {
    runs.push_back(RunSpec{"iterations", std::to_string(it), ours(with_steps(base, base.substeps, it))});
  }
}

void add_substeps(const WorldSettings& base, const std::vector<int>& values, std::vector<RunSpec>& runs)
{
  for (int n : values)
  {
    runs.push_back(RunSpec{"substeps", std::to_string(n), ours(with_steps(base, n, base.velocity_iterations))});
  }
}

void add_toggles(const WorldSettings& base, Toggle WorldSettings::*field, const char* knob,
                 const std::vector<Toggle>& values, std::vector<RunSpec>& runs)
{
  for (Toggle t : values)
  {
    WorldSettings s = base;
    s.*field = t;
    runs.push_back(RunSpec{knob, toggle_name(t), ours(s)});
  }
}

void add_slop(const WorldSettings& base, const std::vector<double>& values, std::vector<RunSpec>& runs)
{
  for (double slop : values)
  {
    WorldSettings s = base;
    s.slop = slop;
    runs.push_back(RunSpec{"slop", text(slop), ours(s)});
  }
}

/// Poses advanced with predicted velocities, on and off, at the scene's
/// setting and at 8x4 (where its gain on stacks shows without its 4x2
/// failure on the pyramid).
void add_warm_before_integration(const WorldSettings& base, std::vector<RunSpec>& runs)
{
  for (const WorldSettings& steps : {base, with_steps(base, kWarmIntegrationSubsteps, kWarmIntegrationIterations)})
  {
    for (bool on : {false, true})
    {
      WorldSettings s = steps;
      s.warm_start_before_integration = on;
      runs.push_back(RunSpec{"warm_before_integration",
                             steps_text(s.substeps, s.velocity_iterations) + (on ? " on" : " off"), ours(s)});
    }
  }
}

void add_modes(const WorldSettings& base, std::vector<RunSpec>& runs)
{
  for (SolverMode mode : {SolverMode::Iterative, SolverMode::Exact})
  {
    WorldSettings s = base;
    if (set_solver_mode(s, mode))
    {
      runs.push_back(RunSpec{"solver_mode", mode_name(mode), ours(s)});
    }
  }
}

void add_grid(const WorldSettings& base, const std::vector<int>& substeps, const std::vector<int>& iterations,
              std::vector<RunSpec>& runs)
{
  for (int n : substeps)
  {
    for (int it : iterations)
    {
      runs.push_back(RunSpec{"grid", steps_text(n, it), ours(with_steps(base, n, it))});
    }
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

}  // namespace

bool world_has_solver_mode()
{
  return HasSolverMode<WorldSettings>::value;
}

std::vector<RunSpec> world_runs(const BenchScene& scene, bool quick)
{
  const WorldSettings& base = scene.scene.settings;
  std::vector<RunSpec> runs{RunSpec{"baseline", steps_text(base.substeps, base.velocity_iterations), ours(base)}};
  // The pyramid is one cluster of 210 boxes (~2400 complementarity rows):
  // pivoting it did not finish 30 frames in several minutes, so it is left out.
  if (scene.name != "pyramid")
  {
    add_modes(base, runs);
  }
  if (scene.kind == SceneKind::Bullet)
  {
    add_toggles(base, &WorldSettings::time_of_impact, "time_of_impact", {Toggle::On, Toggle::Off}, runs);
    add_substeps(base, quick ? std::vector<int>{1, 16} : std::vector<int>{1, 2, 8, 16}, runs);
    return runs;
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
      runs.push_back(RunSpec{"compliance", "compliance 0", ours(rigid)});
    }
    return runs;
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
    add_slop(base, {1e-4, 1e-2}, runs);
    add_toggles(base, &WorldSettings::time_of_impact, "time_of_impact", {Toggle::On, Toggle::Off}, runs);
    add_warm_before_integration(base, runs);
    if (!quick)
    {
      add_grid(base, {1, 2, 8}, {1, 8}, runs);
    }
  }
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
  // Ours at the matched points, so the ratios compare like with like.
  for (const auto& point : matched_points(scene, quick))
  {
    const WorldSettings s = with_steps(scene.scene.settings, point.first, point.second);
    runs.push_back(RunSpec{"matched", steps_text(point.first, point.second), ours(s)});
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
  for (const auto& point : points)
  {
    RunSpec run{"stand", steps_text(point.first, point.second),
                ours(with_steps(scene.scene.settings, point.first, point.second))};
    run.seconds = seconds;
    runs.push_back(run);
  }
  // The same stacks with the poses advanced by predicted velocities.
  for (const auto& point : std::vector<std::pair<int, int>>{{4, 2}, {8, 4}})
  {
    WorldSettings s = with_steps(scene.scene.settings, point.first, point.second);
    s.warm_start_before_integration = true;
    RunSpec run{"stand", steps_text(point.first, point.second) + " warm before integration", ours(s)};
    run.seconds = seconds;
    runs.push_back(run);
  }
  // The precise setting: many substeps and position passes with a small slop.
  WorldSettings precise = with_steps(scene.scene.settings, kPreciseSubsteps, kPreciseVelocityIterations);
  precise.position_iterations = kPrecisePositionIterations;
  precise.slop = kPreciseSlop;
  RunSpec precise_run{"precise", "16 position passes slop 1e-5", ours(precise)};
  precise_run.seconds = seconds;
  runs.push_back(precise_run);
  // The exact mode on the column (one cluster of 20 boxes); the pyramid's
  // 210-box cluster is too costly to pivot for a minute within the budget.
  WorldSettings exact = scene.scene.settings;
  if (!pyramid && set_solver_mode(exact, SolverMode::Exact))
  {
    RunSpec run{"stand", "exact", ours(exact)};
    run.seconds = seconds;
    runs.push_back(run);
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
