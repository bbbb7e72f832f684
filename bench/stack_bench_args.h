// collision2d_stack_bench's command line, read into one struct (the usage is in
// stack_bench.cpp's header comment).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "collision2d/world_settings.h"

#include "engine.h"
#include "sweep.h"

namespace collision2d
{
namespace bench
{
constexpr double kStackDefaultSeconds = 10.0;
constexpr double kStackDefaultTimingSeconds = 1.0;  // s of simulation per timed run
constexpr int kStackDefaultRepetitions = 5;

/// What the command line asks for.
struct StackBenchArguments
{
  std::vector<double> seconds{kStackDefaultSeconds};  ///< checkpoints, ascending
  int repetitions = kStackDefaultRepetitions;
  double timing_seconds = kStackDefaultTimingSeconds;
  std::vector<std::string> scenes;    ///< empty: all stacks
  std::vector<EngineKind> engines;    ///< empty: every engine built in
  std::string csv;                    ///< empty: no CSV
  std::vector<Pipeline> pipelines{Pipeline::Soft, Pipeline::Fx2d};  ///< ours, once per pipeline
  bool stiff = true;  ///< ours also in the stiff soft step
  /// --set NAME=VALUE, in order: WorldSettings fields set on every scene's
  /// settings, which ours takes as they are and a peer where it shares them.
  std::vector<std::pair<std::string, std::string>> settings;
};

/// Reads the command line; prints the usage and exits (status 2) on a bad argument.
StackBenchArguments parse_stack_bench_arguments(int argc, char** argv);
/// Prints `problem` and the usage, and exits with status 2.
[[noreturn]] void stack_bench_usage(const std::string& problem);
/// `settings` with the --set fields, read as a scene file's `settings:` map
/// (same names, ranges and former names); exits through stack_bench_usage naming
/// a field that does not exist or a value it does not accept.
WorldSettings with_set_fields(WorldSettings settings, const StackBenchArguments& args);

}  // namespace bench
}  // namespace collision2d
