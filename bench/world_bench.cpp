// collision2d_world_bench: runs the shipped scenes through the World and
// prints, per scene, the wall time of one frame (median of repetitions), the
// drift of stacks after 10 s, the largest penetration, the energy error of
// conservative scenes and the speed gained by model selection (Auto versus
// every physics effect forced On, timed in the same run; sleeping keeps the
// scene's setting in both).
//
//   collision2d_world_bench [--scene NAME] [--seconds S] [--reps N] [--csv]
//                           [--scene-dir DIR]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "collision2d/scenes/scene_file.h"
#include "world_bench_metrics.h"

namespace
{
using collision2d::ActiveEffects;
using collision2d::bench::BenchOptions;
using collision2d::bench::SceneMetrics;

constexpr double kMillimetresPerMetre = 1e3;

struct Arguments
{
  std::vector<std::string> scenes;  ///< empty: every scene in scene_dir
  std::string scene_dir = COLLISION2D_SCENE_DIR;
  BenchOptions options;
  bool csv = false;
};

[[noreturn]] void usage(const char* problem)
{
  std::fprintf(stderr,
               "%s\nusage: collision2d_world_bench [--scene NAME]... [--seconds S] [--reps N] [--csv] "
               "[--scene-dir DIR]\n",
               problem);
  std::exit(2);
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments args;
  for (int i = 1; i < argc; ++i)
  {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    if (flag == "--csv")
    {
      args.csv = true;
    }
    else if (flag == "--scene" && has_value)
    {
      args.scenes.push_back(argv[++i]);
    }
    else if (flag == "--scene-dir" && has_value)
    {
      args.scene_dir = argv[++i];
    }
    else if (flag == "--seconds" && has_value)
    {
      args.options.seconds = std::atof(argv[++i]);
    }
    else if (flag == "--reps" && has_value)
    {
      args.options.repetitions = std::atoi(argv[++i]);
    }
    else
    {
      usage(("unknown or incomplete argument: " + flag).c_str());
    }
  }
  if (!(args.options.seconds > 0.0) || args.options.repetitions < 1)
  {
    usage("--seconds must be positive and --reps at least 1");
  }
  return args;
}

/// One letter per effect Auto turned on: Rotation Friction rEstitution
/// Position correction Time of impact Warm starting Sleeping.
std::string effect_letters(const ActiveEffects& e)
{
  std::string s;
  s += e.rotation ? 'R' : '-';
  s += e.friction ? 'F' : '-';
  s += e.restitution ? 'E' : '-';
  s += e.position_correction ? 'P' : '-';
  s += e.time_of_impact ? 'T' : '-';
  s += e.warm_starting ? 'W' : '-';
  s += e.sleeping ? 'S' : '-';
  return s;
}

/// A table cell: "-" where the measure does not apply (NaN).
std::string cell(double value)
{
  if (std::isnan(value))
  {
    return "-";
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", value);
  return text;
}

void print_header(bool csv)
{
  if (csv)
  {
    std::printf("scene,bodies,ms_per_step_auto,ms_per_step_all_on,model_selection_speedup,drift_m,"
                "max_penetration_m,energy_error,auto_effects\n");
    return;
  }
  std::printf("%-16s %6s %10s %10s %8s %10s %9s %10s %s\n", "scene", "bodies", "ms/step", "ms/step", "speedup",
              "drift 10s", "max pen", "KE error", "Auto effects");
  std::printf("%-16s %6s %10s %10s %8s %10s %9s %10s %s\n", "", "", "(Auto)", "(all On)", "On/Auto", "(mm)", "(mm)",
              "(rel.)", "(RFEPTWS)");
}

void print_row(const SceneMetrics& m, bool csv)
{
  const double speedup = m.ms_per_step_on / m.ms_per_step_auto;
  const double drift = m.resting ? m.drift : NAN;
  const double energy = m.conservative ? m.energy_error : NAN;
  if (csv)
  {
    std::printf("%s,%zu,%.6g,%.6g,%.4g,%.6g,%.6g,%.6g,%s\n", m.name.c_str(), m.bodies, m.ms_per_step_auto,
                m.ms_per_step_on, speedup, drift, m.max_penetration, energy, effect_letters(m.auto_effects).c_str());
    return;
  }
  std::printf("%-16s %6zu %10.4f %10.4f %8.2f %10s %9.4g %10s %s\n", m.name.c_str(), m.bodies, m.ms_per_step_auto,
              m.ms_per_step_on, speedup, cell(drift * kMillimetresPerMetre).c_str(),
              m.max_penetration * kMillimetresPerMetre, cell(energy).c_str(), effect_letters(m.auto_effects).c_str());
}

}  // namespace

int main(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv);
  try
  {
    const std::vector<std::string> names =
        args.scenes.empty() ? collision2d::scenes::list_scenes(args.scene_dir) : args.scenes;
    print_header(args.csv);
    for (const std::string& name : names)
    {
      const collision2d::Scene scene = collision2d::scenes::load_named_scene(name, args.scene_dir);
      print_row(collision2d::bench::measure_scene(scene, args.options), args.csv);
      std::fflush(stdout);
    }
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "collision2d_world_bench: %s\n", error.what());
    return 1;
  }
  if (!args.csv)
  {
    std::printf("\nms/step: median wall time of one frame (dt = the scene's) over %d repetitions of %g s "
                "simulated.\nspeedup: all-On time / Auto time in the same run; all On forces every physics effect "
                "on, sleeping stays as the scene sets it.\ndrift (after %g s) and max pen: one Auto run. drift: "
                "stacks only (bodies starting at rest in contact). KE error: conservative scenes only (no gravity, "
                "e = 1, mu = 0).\n",
                args.options.repetitions, args.options.seconds, args.options.settle_seconds);
  }
  return 0;
}
