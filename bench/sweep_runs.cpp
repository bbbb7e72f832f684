// The sweep's building blocks (see sweep_runs.h).
#include "sweep_runs.h"

#include <cstdio>

namespace collision2d
{
namespace bench
{
namespace sweep
{
namespace
{
// The second setting warm_start_before_integration is swept at (see add_warm_before_integration).
constexpr int kWarmIntegrationSubsteps = 8;
constexpr int kWarmIntegrationIterations = 4;

}  // namespace

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

void add_flip(const WorldSettings& base, bool WorldSettings::*field, const char* knob, Runs runs)
{
  WorldSettings s = base;
  s.*field = !(base.*field);
  runs.add(knob, s.*field ? "on" : "off", s);
}

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

void add_exact(const WorldSettings& base, Runs runs)
{
  WorldSettings s = base;
  s.solver_mode = SolverMode::Exact;
  runs.add("solver_mode", mode_name(SolverMode::Exact), s);
}

void add_sleeping(const WorldSettings& base, Runs runs)
{
  WorldSettings s = base;
  s.sleeping = Toggle::On;
  runs.add("sleeping", toggle_name(Toggle::On), s);
  // The peers' cheap settings (one substep) sleep too.
  for (const auto& [substeps, iterations] : {std::pair{1, 2}, std::pair{2, 2}, std::pair{1, 8}})
  {
    runs.add("sleeping", toggle_name(Toggle::On), with_steps(s, substeps, iterations));
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

}  // namespace sweep
}  // namespace bench
}  // namespace collision2d
