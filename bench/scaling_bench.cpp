// collision2d_scaling_bench: time per frame and peak memory for one scene of
// about n bodies, one size per process so that the peak resident set (VmHWM)
// belongs to that size alone. Scenes: gas (scenes::elastic_gas, n scattered
// disks), pyramid and rain (stack_scenes.h: the Box2D v3 comparison's rules),
// resting: the pyramid with sleeping on (each engine's own sleeping),
// timed once it has fallen asleep, which is what a settled world costs; and
// stirred: the resting pyramid plus one kinematic disk sliding past far from
// it, what a world costs when almost all of it sleeps.
//
//   collision2d_scaling_bench --bodies N [--scene gas|pyramid|rain|resting|stirred] [--workers W]
//                             [--engine collision2d|box2d|chipmunk|box2d_v3] [--reps R]
//                             [--period-ms P] [--header]
//
// --period-ms steps the timed frames one per P ms, as a timer in a ROS node
// would, and times the steps alone (0, the default: back to back).
// Prints one CSV row: engine,scene,bodies,workers,frames,ms_per_step,cpu_ms_per_step,vmhwm_kib,
// vmhwm_start_kib,period_ms; vmhwm_start_kib is the peak before the scene was built, vmhwm_kib the peak
// from the moment the engine's world is built and the bench's own copy of the
// scene freed (Linux resets the mark on request; elsewhere the copy counts
// too). --workers sets ours
// (WorldSettings::workers) and Box2D v3's workerCount; the other peers run on
// one thread.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "collision2d/scenes/standard_scenes.h"
#include "engine.h"
#include "stack_scenes.h"
#include "timing.h"

namespace
{
using namespace collision2d;
using namespace collision2d::bench;

constexpr int kWarmupFrames = 3;          // first frames build caches and scratch
constexpr int kRainWarmupFrames = 60;     // 1 s: the rain's lowest rows land and pile first
constexpr int kRestingWarmupFrames = 600; // 10 s: a settled pyramid has fallen asleep in either engine
constexpr double kFrameBudget = 1e5;      // body-frames per repetition: ~constant work per size
constexpr int kMinFrames = 5;
constexpr int kMaxFrames = 120;
constexpr int kDefaultRepetitions = 5;
constexpr double kStirrerRadius = 0.5;    // m
constexpr double kStirrerHeight = 2.0;    // m above the ground's top
constexpr double kStirrerInset = 2.0;     // m from the ground's left end
constexpr double kStirrerSpeed = 1.0;     // m/s to the right: 20 s of frames stay clear of the pyramid
/// What /proc/self/clear_refs takes to set VmHWM to the current resident set.
constexpr char kResetPeakResident[] = "5";

struct Arguments
{
  long bodies = 0;
  EngineKind engine = EngineKind::Collision2d;
  int repetitions = kDefaultRepetitions;
  bool header = false;
  std::string scene = "gas";
  int workers = 1;
  double period_ms = 0.0;
};

[[noreturn]] void usage(const std::string& problem)
{
  std::fprintf(stderr,
               "%s\nusage: collision2d_scaling_bench --bodies N [--scene gas|pyramid|rain|resting|stirred] [--workers W] "
               "[--engine collision2d|box2d|chipmunk|box2d_v3] [--reps R] [--period-ms P] [--header]\n",
               problem.c_str());
  std::exit(2);
}

EngineKind parse_engine(const std::string& name)
{
  EngineKind kind = EngineKind::Collision2d;
  if (!engine_from_name(name, kind))
  {
    usage("unknown engine '" + name + "'");
  }
  return kind;
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments args;
  for (int i = 1; i < argc; ++i)
  {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    if (flag == "--bodies" && has_value)
    {
      args.bodies = std::atol(argv[++i]);
    }
    else if (flag == "--engine" && has_value)
    {
      args.engine = parse_engine(argv[++i]);
    }
    else if (flag == "--scene" && has_value)
    {
      args.scene = argv[++i];
    }
    else if (flag == "--workers" && has_value)
    {
      args.workers = std::atoi(argv[++i]);
    }
    else if (flag == "--reps" && has_value)
    {
      args.repetitions = std::atoi(argv[++i]);
    }
    else if (flag == "--period-ms" && has_value)
    {
      args.period_ms = std::atof(argv[++i]);
    }
    else if (flag == "--header")
    {
      args.header = true;
    }
    else
    {
      usage("unknown or incomplete argument: " + flag);
    }
  }
  if (args.header)
  {
    return args;
  }
  if (args.bodies < 1 || args.repetitions < 1 || args.workers < 1)
  {
    usage("--bodies, --reps and --workers must be positive");
  }
  if (!(args.period_ms >= 0.0))
  {
    usage("--period-ms must be 0 or more");
  }
  if (args.workers > 1 && args.engine != EngineKind::Collision2d && args.engine != EngineKind::Box2dV3)
  {
    usage("--workers applies to collision2d and box2d_v3 only");
  }
  if (args.scene != "gas" && args.scene != "pyramid" && args.scene != "rain" && args.scene != "resting" &&
      args.scene != "stirred")
  {
    usage("unknown scene '" + args.scene + "'");
  }
  return args;
}

/// Peak resident set of this process (kB as /proc reports it, i.e. KiB); -1 if unreadable.
long peak_resident_kib()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == "VmHWM:")
    {
      long kib = -1;
      status >> kib;
      return kib;
    }
    status.ignore(4096, '\n');
  }
  return -1;
}

/// Lowers VmHWM to the current resident set (Linux 4.0 and later): the
/// world is built from the bench's scene, whose copy is not the world's
/// memory. False where the kernel refuses, and the peak then includes it.
bool reset_peak_resident()
{
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << kResetPeakResident << std::flush;
  return static_cast<bool>(clear_refs);
}

/// A kinematic disk near the ground's left end, sliding right at kStirrerSpeed:
/// it keeps the world from being wholly at rest without touching anything.
void add_stirrer(Scene& scene)
{
  double left = 0.0;
  for (const SceneBody& b : scene.bodies)
  {
    if (b.body.type() == BodyType::Static)
    {
      left = std::min(left, b.body.aabb().lo.x);
    }
  }
  Body disk(1.0, kStirrerRadius, Vec2{left + kStirrerInset, kStirrerHeight}, Vec2{kStirrerSpeed, 0.0});
  disk.set_type(BodyType::Kinematic);
  scene.bodies.push_back(SceneBody{disk, Material{}, "stirrer"});
}

}  // namespace

int main(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv);
  if (args.header)
  {
    std::printf("engine,scene,bodies,workers,frames,ms_per_step,cpu_ms_per_step,vmhwm_kib,vmhwm_start_kib,period_ms\n");
    return 0;
  }
  try
  {
    const long start_kib = peak_resident_kib();
    const bool resting = args.scene == "resting" || args.scene == "stirred";
    Scene scene = args.scene == "gas" ? scenes::elastic_gas(static_cast<int>(args.bodies))
                                      : make_throughput_scene(resting ? "pyramid" : args.scene, args.bodies);
    scene.settings.workers = args.workers;
    if (resting)
    {
      scene.settings.sleeping = Toggle::On;
    }
    if (args.scene == "stirred")
    {
      add_stirrer(scene);
    }
    const long bodies = std::count_if(scene.bodies.begin(), scene.bodies.end(),
                                      [](const SceneBody& b) { return b.body.type() == BodyType::Dynamic; });
    // The throughput scenes follow the stack comparison's rule: each peer with
    // its own defaults but our substeps and sleeping off, as the scene sets
    // ours; the resting pyramid takes the peers' defaults (sleeping on).
    const PeerVariant variant = args.scene == "gas" || resting ? PeerVariant::Defaults : PeerVariant::Substepped;
    EngineConfig config{args.engine, variant, scene.settings};
    std::unique_ptr<Engine> engine = make_engine(scene, config);
    // Every engine copies what it needs: the scene is the bench's input, not
    // the world's memory. It is freed, and its peak forgotten, before any step.
    scene = Scene{};
    if (!reset_peak_resident())
    {
      std::fprintf(stderr, "collision2d_scaling_bench: the peak could not be reset; it includes the scene\n");
    }
    const int warmup = resting ? kRestingWarmupFrames : args.scene == "rain" ? kRainWarmupFrames : kWarmupFrames;
    time_frames(*engine, warmup);
    const int frames = std::clamp(static_cast<int>(kFrameBudget / bodies), kMinFrames, kMaxFrames);
    std::vector<double> wall;
    std::vector<double> cpu;
    for (int r = 0; r < args.repetitions; ++r)
    {
      const FrameTime t = args.period_ms > 0.0 ? time_paced_frames(*engine, frames, args.period_ms)
                                               : time_frames(*engine, frames);
      wall.push_back(t.wall_ms);
      cpu.push_back(t.cpu_ms);
    }
    std::printf("%s,%s,%ld,%d,%d,%.6g,%.6g,%ld,%ld,%.6g\n", engine_name(args.engine).c_str(), args.scene.c_str(),
                bodies, args.workers, frames, median(wall), median(cpu), peak_resident_kib(), start_kib, args.period_ms);
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "collision2d_scaling_bench: %s\n", error.what());
    return 1;
  }
  return 0;
}
