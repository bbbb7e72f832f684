// collision2d_sweep_bench: the speed/accuracy sweep. Prints CSV.
//
//   collision2d_sweep_bench PART... [--quick] [--scene NAME]... [--reps N] [--out FILE]
//     with PART among world, peers, stand (one CSV, one header)
//   collision2d_sweep_bench solver [--quick] [--scenes N] [--out FILE]
//   collision2d_sweep_bench paired --scene NAME --key KEY... [--rounds N] [--quick] [--out FILE]
//
// CSV goes to FILE (default stdout): the packaged Chipmunk prints a banner
// on stdout when its first space is made, which must not land in the CSV.
//
// world:  our World in both pipelines (pipeline column: soft = soft step,
//         fx2d = the Fx2D order; default_pipeline names the build's default)
//         over one-knob-at-a-time sweeps (iterations, substeps, warm
//         starting, time of impact, solver mode; Fx2D only: slop, position
//         passes and block, warm-start variants; soft step only: contact
//         stiffness, damping, push speed, speculative margin) and a substeps x
//         iterations grid;
// peers:  Box2D 2.4.1, Chipmunk and (when built in) Box2D v3 with their
//         defaults and matched to a few of our points, and ours at the same
//         points in both pipelines, all in this one process;
// stand:  the stacks for 60 s at a few settings of each pipeline (the drift target);
// solver: the instantaneous ContactSolver on random islands per mode,
//         iteration cap and tolerance: Newton-target and complementarity residuals;
// paired: runs of world and peers named by key (run_key) timed again in
//         rounds, each round timing every run once, so that a ratio of two
//         runs can be taken within a round (scripts/report_pairs.py).
// Progress goes to stderr; docs/performance.md explains every column.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "metrics.h"
#include "sweep.h"
#include "timing.h"

namespace
{
using namespace collision2d;
using namespace collision2d::bench;

constexpr std::size_t kSolverScenes = 400;  // random islands per solver point
constexpr std::size_t kQuickSolverScenes = 100;
constexpr std::uint64_t kSolverSeed = 20240601;  // the same draws for every point
constexpr int kQuickRepetitions = 3;
constexpr int kPairedRounds = 7;

struct Arguments
{
  std::vector<std::string> parts;
  bool quick = false;
  std::vector<std::string> scenes;  ///< empty: all
  RunOptions options;
  std::size_t solver_scenes = kSolverScenes;
  std::string out;  ///< empty: stdout
  std::vector<std::string> keys;  ///< paired: the runs to time
  int rounds = kPairedRounds;     ///< paired
};

FILE* g_csv = stdout;

[[noreturn]] void usage(const std::string& problem)
{
  std::fprintf(stderr,
               "%s\nusage: collision2d_sweep_bench world|peers|stand...|solver [--quick] [--scene NAME]... "
               "[--reps N] [--scenes N] [--out FILE]\n"
               "       collision2d_sweep_bench paired --scene NAME --key KEY... [--rounds N] [--quick] [--out FILE]\n",
               problem.c_str());
  std::exit(2);
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments args;
  bool reps_given = false;
  bool scenes_given = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    if (flag.compare(0, 2, "--") != 0)
    {
      args.parts.push_back(flag);
    }
    else if (flag == "--quick")
    {
      args.quick = true;
    }
    else if (flag == "--scene" && has_value)
    {
      args.scenes.push_back(argv[++i]);
    }
    else if (flag == "--reps" && has_value)
    {
      reps_given = (args.options.repetitions = std::atoi(argv[++i])) > 0;
    }
    else if (flag == "--out" && has_value)
    {
      args.out = argv[++i];
    }
    else if (flag == "--key" && has_value)
    {
      args.keys.push_back(argv[++i]);
    }
    else if (flag == "--rounds" && has_value)
    {
      args.rounds = std::atoi(argv[++i]);
    }
    else if (flag == "--scenes" && has_value)
    {
      scenes_given = (args.solver_scenes = std::strtoul(argv[++i], nullptr, 10)) > 0;
    }
    else
    {
      usage("unknown or incomplete argument: " + flag);
    }
  }
  if (args.quick && !reps_given)
  {
    args.options.repetitions = kQuickRepetitions;
  }
  if (args.quick && !scenes_given)
  {
    args.solver_scenes = kQuickSolverScenes;
  }
  if (args.parts.empty())
  {
    usage("missing part");
  }
  if (args.options.repetitions < 1 || args.solver_scenes < 1 || args.rounds < 1)
  {
    usage("--reps, --scenes and --rounds must be positive");
  }
  return args;
}

void print_run_header()
{
  std::fprintf(
      g_csv,
      "part,scene,kind,engine,variant,pipeline,default_pipeline,knob,value,substeps,iterations,slop,warm_starting,"
      "time_of_impact,solver_mode,seconds,ms_per_step,cpu_ms_per_step,max_penetration_m,drift_m,sink_m,energy_error,bounce_error,"
      "incline_accel_error,tunnelled,error,error_name\n");
}

/// The columns that tell one run of a scene from another, as the CSV has them.
struct RunLabel
{
  std::string engine, variant, pipeline, knob, value, substeps, iterations;
};

RunLabel run_label(const RunSpec& run)
{
  const WorldSettings& s = run.config.settings;
  const bool peer_defaults = run.config.kind != EngineKind::Collision2d && run.config.variant == PeerVariant::Defaults;
  const bool ours = run.config.kind == EngineKind::Collision2d;
  // A peer's defaults use its own steps and iterations: leave ours out.
  // Box2D v3 has no velocity-iteration count to match.
  const bool no_iterations = peer_defaults || run.config.kind == EngineKind::Box2dV3;
  return RunLabel{engine_name(run.config.kind),
                  variant_name(run.config.variant),
                  ours ? pipeline_name(s) : "",
                  run.knob,
                  run.value,
                  peer_defaults ? "" : std::to_string(s.substeps),
                  no_iterations ? "" : std::to_string(s.velocity_iterations)};
}

/// How `paired` names a run: its part and label joined by '|'
/// (scripts/report_pairs.py builds the same key from a CSV row).
std::string run_key(const std::string& part, const RunSpec& run)
{
  const RunLabel l = run_label(run);
  return part + "|" + l.engine + "|" + l.variant + "|" + l.pipeline + "|" + l.knob + "|" + l.value + "|" +
         l.substeps + "|" + l.iterations;
}

void print_run(const std::string& part, const BenchScene& scene, const RunSpec& run, double seconds,
               const RunMetrics& m)
{
  const WorldSettings& s = run.config.settings;
  const bool ours = run.config.kind == EngineKind::Collision2d;
  const RunLabel l = run_label(run);
  std::fprintf(g_csv,
               "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%g,%s,%s,%s,%g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%g,%.6g,%s\n",
               part.c_str(), scene.name.c_str(), kind_name(scene.kind).c_str(), l.engine.c_str(), l.variant.c_str(),
               l.pipeline.c_str(), default_pipeline_name().c_str(), l.knob.c_str(), l.value.c_str(),
               l.substeps.c_str(), l.iterations.c_str(), s.slop, ours ? toggle_name(s.warm_starting).c_str() : "",
               ours ? toggle_name(s.time_of_impact).c_str() : "", ours ? world_mode_name(s).c_str() : "", seconds,
               m.ms_per_step, m.cpu_ms_per_step, m.max_penetration, m.drift, m.sink, m.energy_error, m.bounce_error,
               m.incline_error, m.tunnelled, m.error, error_name(scene.kind).c_str());
  std::fflush(g_csv);
}

std::vector<RunSpec> runs_for(const std::string& part, const BenchScene& scene, bool quick)
{
  if (part == "world")
  {
    return world_runs(scene, quick);
  }
  if (part == "peers")
  {
    return peer_runs(scene, quick);
  }
  return scene.name == "pyramid" || scene.name == "column" ? stand_runs(scene, quick) : std::vector<RunSpec>{};
}

void run_scene(const Arguments& args, const std::string& part, const BenchScene& scene)
{
  for (const RunSpec& run : runs_for(part, scene, args.quick))
  {
    RunOptions options = args.options;
    options.seconds = run.seconds;
    const bool ours = run.config.kind == EngineKind::Collision2d;
    std::fprintf(stderr, "%s %s %s%s%s %s=%s\n", part.c_str(), scene.name.c_str(), engine_name(run.config.kind).c_str(),
                 ours ? " " : "", ours ? pipeline_name(run.config.settings).c_str() : "", run.knob.c_str(),
                 run.value.c_str());
    const RunMetrics m = measure_run(scene, run.config, options);
    print_run(part, scene, run, run.seconds > 0.0 ? run.seconds : scene.seconds, m);
  }
}

void run_scenes(const Arguments& args)
{
  const std::vector<std::string> names = args.scenes.empty() ? bench_scene_names() : args.scenes;
  print_run_header();
  for (const std::string& part : args.parts)
  {
    for (const std::string& name : names)
    {
      run_scene(args, part, make_bench_scene(name));
    }
  }
}

void run_paired(const Arguments& args)
{
  if (args.scenes.size() != 1 || args.keys.size() < 2)
  {
    usage("paired takes one --scene and at least two --key");
  }
  const BenchScene scene = make_bench_scene(args.scenes.front());
  std::vector<std::pair<std::string, RunSpec>> runs;  // every run of the scene, by key
  for (const std::string part : {"world", "peers"})
  {
    for (const RunSpec& run : runs_for(part, scene, args.quick))
    {
      runs.emplace_back(run_key(part, run), run);
    }
  }
  std::vector<RunSpec> picked;
  for (const std::string& key : args.keys)
  {
    const auto named = std::find_if(runs.begin(), runs.end(), [&](const auto& r) { return r.first == key; });
    if (named == runs.end())
    {
      usage("no run of " + scene.name + " has the key " + key);
    }
    picked.push_back(named->second);
  }
  std::fprintf(g_csv, "scene,round,key,ms_per_step,cpu_ms_per_step\n");
  // Each round starts one run further on, so no run always follows the same one.
  for (int round = 0; round < args.rounds; ++round)
  {
    for (std::size_t k = 0; k < picked.size(); ++k)
    {
      const std::size_t i = (static_cast<std::size_t>(round) + k) % picked.size();
      std::fprintf(stderr, "paired %s round %d %s\n", scene.name.c_str(), round, args.keys[i].c_str());
      const FrameTime t = time_run(scene, picked[i].config, args.options);
      std::fprintf(g_csv, "%s,%d,%s,%.6g,%.6g\n", scene.name.c_str(), round, args.keys[i].c_str(), t.wall_ms,
                   t.cpu_ms);
      std::fflush(g_csv);
    }
  }
}

void run_solver(const Arguments& args)
{
  std::fprintf(g_csv,
               "mode,iterations,tolerance,max_mass_ratio,scenes,contacts,us_per_solve,max_target_residual,"
               "max_complementarity,mean_complementarity,max_coulomb_excess,converged_fraction,exact_fallbacks\n");
  for (const SolverSweepPoint& p : solver_points(args.quick))
  {
    std::fprintf(stderr, "solver %s it=%d tol=%g ratio=%g\n", mode_name(p.mode).c_str(), p.iterations, p.tolerance,
                 p.max_mass_ratio);
    const SolverMetrics m = measure_solver(p, args.solver_scenes, kSolverSeed);
    std::fprintf(g_csv, "%s,%d,%g,%g,%zu,%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%zu\n", mode_name(p.mode).c_str(),
                 p.iterations, p.tolerance, p.max_mass_ratio, m.scenes, m.contacts, m.us_per_solve,
                 m.max_target_residual, m.max_complementarity, m.mean_complementarity, m.max_coulomb_excess,
                 m.converged_fraction, m.exact_fallbacks);
    std::fflush(g_csv);
  }
}

}  // namespace

int main(int argc, char** argv)
{
  // Each repetition builds a fresh world: its time must not depend on what
  // the process freed before (timing.h).
  fix_allocator_thresholds();
  const Arguments args = parse_arguments(argc, argv);
  if (!args.out.empty() && (g_csv = std::fopen(args.out.c_str(), "w")) == nullptr)
  {
    usage("cannot write " + args.out);
  }
  try
  {
    for (const std::string& part : args.parts)
    {
      const bool alone = part == "solver" || part == "paired";
      const bool known = alone || part == "world" || part == "peers" || part == "stand";
      if (!known || (alone && args.parts.size() > 1))
      {
        usage("unknown part '" + part + "' (solver and paired run alone)");
      }
    }
    if (args.parts.front() == "solver")
    {
      run_solver(args);
    }
    else if (args.parts.front() == "paired")
    {
      run_paired(args);
    }
    else
    {
      run_scenes(args);
    }
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "collision2d_sweep_bench: %s\n", error.what());
    return 1;
  }
  return 0;
}
