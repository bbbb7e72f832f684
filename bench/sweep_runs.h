// The sweep's building blocks (sweep.cpp builds its grids from them): which
// scenes get which extra runs, and the helpers that add one knob's runs
// around a base setting.
#pragma once

#include <string>
#include <vector>

#include "sweep.h"

namespace collision2d
{
namespace bench
{
namespace sweep
{
bool is_headline(const BenchScene& s);
/// The stacks of the sweep: the pyramid and the column.
bool is_stack(const BenchScene& s);
bool is_mass_ratio(const BenchScene& s);
/// Scenes whose bodies come to rest: a world that sleeps then holds them
/// still at little cost (the peers sleep at their defaults too).
bool comes_to_rest(const BenchScene& s);

/// A value as a run label ("%g").
std::string text(double value);
/// Our World with these settings.
EngineConfig ours(const WorldSettings& settings);
WorldSettings with_steps(WorldSettings s, int substeps, int iterations);
/// "4x2": substeps x iterations.
std::string steps_text(int substeps, int iterations);

/// The same run list whatever the pipeline: runs.add(knob, value, settings).
struct Runs
{
  std::vector<RunSpec>& out;
  void add(const std::string& knob, const std::string& value, const WorldSettings& settings)
  {
    out.push_back(RunSpec{knob, value, ours(settings)});
  }
};

void add_iterations(const WorldSettings& base, const std::vector<int>& values, Runs runs);
void add_substeps(const WorldSettings& base, const std::vector<int>& values, Runs runs);
void add_toggles(const WorldSettings& base, Toggle WorldSettings::*field, const char* knob,
                 const std::vector<Toggle>& values, Runs runs);
/// One double-valued knob of the settings at each value.
void add_values(const WorldSettings& base, double WorldSettings::*field, const char* knob,
                const std::vector<double>& values, Runs runs);
/// One bool knob set to the opposite of its value in `base`.
void add_flip(const WorldSettings& base, bool WorldSettings::*field, const char* knob, Runs runs);
/// Poses advanced with predicted velocities, on and off, at the scene's
/// setting and at 8x4 (where its gain on stacks shows without its 4x2
/// failure on the pyramid).
void add_warm_before_integration(const WorldSettings& base, Runs runs);
/// The exact solver mode (the iterative one is the baseline).
void add_exact(const WorldSettings& base, Runs runs);
/// Sleeping on, at the base's steps and at cheaper ones (a world that
/// sleeps once its bodies rest needs fewer substeps to hold them).
void add_sleeping(const WorldSettings& base, Runs runs);
/// Every substeps x iterations pair.
void add_grid(const WorldSettings& base, const std::vector<int>& substeps, const std::vector<int>& iterations,
              Runs runs);

}  // namespace sweep
}  // namespace bench
}  // namespace collision2d
