// collision2d_stack_bench: the stack scenes (stack_scenes.h) in ours and in every peer
// built in (Box2D 2.4.1, Chipmunk 7, Box2D v3 when the build was given
// COLLISION2D_BOX2D_V3_DIR), all measured in this one process.
//
//   collision2d_stack_bench [--seconds S[,S...]] [--reps N] [--timing-seconds T]
//                           [--scene NAME]... [--engine NAME]... [--csv FILE]
//                           [--soft-step on|off|both] [--stiff on|off] [--set NAME=VALUE]...
//
// Each engine runs the scene with the comparison's rule (stack_scenes.h):
// ours with the scene's settings (our defaults, 4 substeps, sleeping off) in
// the soft step (on), the Fx2D pipeline (off) or both, one row each (both,
// the default; soft_step is always set, whichever pipeline is the default),
// each peer with its own defaults but 4 substeps and sleeping off
// (PeerVariant::Substepped). With --stiff on (the default) ours runs the soft
// step once more with_stiff_contacts (sweep.h), the setting for tall stacks,
// whose cost this shows beside the defaults' (CSV variant "stiff"). Each
// --set NAME=VALUE sets a WorldSettings field (a number, on/off/auto, true or
// false) on every scene's settings first: ours takes them all, a peer the dt
// and substeps it shares, the stiff row its own four over them (the table's
// heading lists them; the CSV does not). Per
// scene and engine it prints ms/frame (median of N fresh runs of T
// simulated seconds, wall and thread CPU; the engines
// take turns, one run each per round), then one run to the longest S: drift
// from 1 s to each S (largest displacement of any dynamic body between the
// two instants), its sway (the largest such displacement at any frame from
// 1 s to S) and the largest penetration up to each S (our detection on
// the engine's poses, as every benchmark measures it), and each engine's time
// over Box2D v3's: the median over the rounds of that round's ratio, so a
// machine whose speed drifts between rounds does not skew it. A table goes to stdout (the
// packaged Chipmunk prints a banner there too), CSV rows to FILE; the
// pipeline column says which pipeline a row of ours ran (soft, fx2d) and
// default_pipeline which one a default WorldSettings uses in this build.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "engine.h"
#include "stack_bench_args.h"
#include "stack_scenes.h"
#include "sweep.h"
#include "timing.h"

namespace
{
using namespace collision2d;
using namespace collision2d::bench;

/// What one engine shows at one checkpoint of the accuracy run.
struct Checkpoint
{
  double seconds = 0.0;
  double drift = 0.0;            ///< m, from kStackSettleSeconds to `seconds`
  double max_penetration = 0.0;  ///< m, largest over the frames up to `seconds`
  /// m, the largest displacement of any dynamic body from its pose at
  /// kStackSettleSeconds over every frame up to `seconds`: a stack that
  /// still rings after 1 s can end near where it was and show little drift.
  double sway = 0.0;
};

struct EngineResult
{
  EngineKind kind = EngineKind::Collision2d;
  Pipeline pipeline_asked = Pipeline::Fx2d;
  bool stiff = false;    ///< ours: the stiff soft-step setting
  std::string pipeline;  ///< ours: "soft" or "fx2d"; peers: empty
  std::vector<double> wall_rounds;  ///< ms/frame of each round's run
  std::vector<double> cpu_rounds;
  double ms_per_frame = 0.0;
  double cpu_ms_per_frame = 0.0;
  double wall_over_v3 = NAN;  ///< median over the rounds of this run's time over Box2D v3's
  double cpu_over_v3 = NAN;
  std::vector<Checkpoint> checkpoints;
};

EngineConfig config_for(EngineKind kind, const BenchScene& scene, Pipeline pipeline, bool stiff = false)
{
  // Ours takes the scene's settings as they are (with the pipeline asked
  // for); a peer its defaults with the scene's substeps and sleeping off.
  const PeerVariant variant = kind == EngineKind::Collision2d ? PeerVariant::Matched : PeerVariant::Substepped;
  const WorldSettings settings = with_pipeline(scene.scene.settings, pipeline);
  return EngineConfig{kind, variant, stiff ? with_stiff_contacts(settings) : settings};
}

EngineConfig config_for(const EngineResult& r, const BenchScene& scene)
{
  return config_for(r.kind, scene, r.pipeline_asked, r.stiff);
}

std::string run_name(const EngineResult& r)
{
  return engine_name(r.kind) + (r.pipeline.empty() ? "" : " " + r.pipeline) + (r.stiff ? " stiff" : "");
}

/// Deepest overlap at these poses by our detection; infinite when the poses
/// are degenerate (the engine blew up).
double deepest_overlap(std::vector<Body>& bodies, const std::vector<BodyState>& states)
{
  for (std::size_t i = 0; i < states.size(); ++i)
  {
    bodies[i].set_position(states[i].position);
    bodies[i].set_theta(states[i].theta);
  }
  try
  {
    double deepest = 0.0;
    for (const Contact& c : ContactSolver::detect_contacts(bodies))
    {
      deepest = std::max(deepest, c.penetration);
    }
    return deepest;
  }
  catch (const std::runtime_error&)
  {
    return std::numeric_limits<double>::infinity();
  }
}

std::vector<Checkpoint> accuracy_run(const BenchScene& bs, const EngineConfig& config,
                                     const std::vector<double>& seconds)
{
  const Scene& scene = bs.scene;
  const double dt = scene.settings.dt;
  std::unique_ptr<Engine> engine = make_engine(scene, config);
  std::vector<Body> probe;
  for (const SceneBody& entry : scene.bodies)
  {
    probe.push_back(entry.body);
  }
  const int settle_frame = frames_for(kStackSettleSeconds, dt);
  std::vector<BodyState> settled(scene.bodies.size());
  read_states(*engine, settled);
  std::vector<BodyState> now(scene.bodies.size());
  std::vector<Checkpoint> out;
  double deepest = 0.0;
  double sway = 0.0;
  std::size_t next = 0;
  for (int f = 1; next < seconds.size(); ++f)
  {
    engine->step_frame();
    read_states(*engine, now);
    deepest = std::max(deepest, deepest_overlap(probe, now));
    settled = f == settle_frame ? now : settled;
    const double drift = largest_move(scene, settled, now);
    sway = f >= settle_frame ? std::max(sway, drift) : sway;
    while (next < seconds.size() && f == frames_for(seconds[next], dt))
    {
      out.push_back(Checkpoint{seconds[next], drift, deepest, sway});
      ++next;
    }
  }
  return out;
}

/// One fresh run of each engine per round, the engines in turn; then each
/// one's medians and its ratios to Box2D v3's run of the same round.
void time_in_rounds(const BenchScene& scene, std::vector<EngineResult>& results, const StackBenchArguments& args)
{
  for (int round = 0; round < args.repetitions; ++round)
  {
    for (EngineResult& r : results)
    {
      std::unique_ptr<Engine> engine = make_engine(scene.scene, config_for(r, scene));
      const FrameTime t = time_frames(*engine, frames_for(args.timing_seconds, scene.scene.settings.dt));
      r.wall_rounds.push_back(t.wall_ms);
      r.cpu_rounds.push_back(t.cpu_ms);
    }
  }
  const EngineResult* v3 = nullptr;
  for (EngineResult& r : results)
  {
    r.ms_per_frame = median(r.wall_rounds);
    r.cpu_ms_per_frame = median(r.cpu_rounds);
    v3 = r.kind == EngineKind::Box2dV3 ? &r : v3;
  }
  const auto over = [&](const std::vector<double>& ours, const std::vector<double>& theirs) {
    std::vector<double> ratios;
    for (std::size_t i = 0; i < ours.size(); ++i)
    {
      if (theirs[i] > 0.0)
      {
        ratios.push_back(ours[i] / theirs[i]);
      }
    }
    return ratios.empty() ? NAN : median(ratios);
  };
  for (EngineResult& r : results)
  {
    if (v3 != nullptr)
    {
      r.wall_over_v3 = over(r.wall_rounds, v3->wall_rounds);
      r.cpu_over_v3 = over(r.cpu_rounds, v3->cpu_rounds);
    }
  }
}

std::vector<EngineResult> measure(const BenchScene& scene, const StackBenchArguments& args)
{
  // Ours once per pipeline asked for; a peer once.
  std::vector<EngineResult> results;
  for (EngineKind kind : args.engines)
  {
    const std::vector<Pipeline> pipelines =
        kind == EngineKind::Collision2d ? args.pipelines : std::vector<Pipeline>{Pipeline::Fx2d};
    for (Pipeline pipeline : pipelines)
    {
      EngineResult r;
      r.kind = kind;
      r.pipeline_asked = pipeline;
      r.pipeline = kind == EngineKind::Collision2d ? pipeline_name(config_for(kind, scene, pipeline).settings) : "";
      results.push_back(r);
      if (kind == EngineKind::Collision2d && pipeline == Pipeline::Soft && args.stiff)
      {
        r.stiff = true;
        results.push_back(r);
      }
    }
  }
  std::fprintf(stderr, "stack %s: timing, %d rounds\n", scene.name.c_str(), args.repetitions);
  time_in_rounds(scene, results, args);
  for (EngineResult& r : results)
  {
    std::fprintf(stderr, "stack %s %s\n", scene.name.c_str(), run_name(r).c_str());
    r.checkpoints = accuracy_run(scene, config_for(r, scene), args.seconds);
  }
  return results;
}

std::size_t dynamic_bodies(const Scene& scene)
{
  return static_cast<std::size_t>(std::count_if(scene.bodies.begin(), scene.bodies.end(), [](const SceneBody& b) {
    return b.body.type() == BodyType::Dynamic;
  }));
}

void print_scene(const BenchScene& scene, const std::vector<EngineResult>& results, FILE* csv)
{
  const std::size_t boxes = dynamic_bodies(scene.scene);
  for (const EngineResult& r : results)
  {
    const double ratio = r.wall_over_v3;
    const double cpu_ratio = r.cpu_over_v3;
    for (const Checkpoint& c : r.checkpoints)
    {
      const std::string engine = run_name(r);
      std::printf("| %s | %zu | %s | %.3g | %.3g | %.3g | %.3g | %g | %.3g | %.3g | %.3g |\n", scene.name.c_str(),
                  boxes, engine.c_str(), r.ms_per_frame, r.cpu_ms_per_frame, ratio, cpu_ratio, c.seconds,
                  c.drift, c.sway, c.max_penetration);
      if (csv != nullptr)
      {
        std::fprintf(csv, "%s,%zu,%s,%s,%s,%s,%.6g,%.6g,%.6g,%.6g,%g,%.6g,%.6g,%.6g\n", scene.name.c_str(), boxes,
                     engine_name(r.kind).c_str(),
                     r.stiff ? "stiff" : variant_name(config_for(r.kind, scene, Pipeline::Fx2d).variant).c_str(),
                     r.pipeline.c_str(),
                     default_pipeline_name().c_str(), r.ms_per_frame, r.cpu_ms_per_frame, ratio, cpu_ratio, c.seconds,
                     c.drift, c.max_penetration, c.sway);
      }
    }
  }
  std::fflush(stdout);
  if (csv != nullptr)
  {
    std::fflush(csv);
  }
}

}  // namespace

int main(int argc, char** argv)
{
  StackBenchArguments args = parse_stack_bench_arguments(argc, argv);
  FILE* csv = nullptr;
  if (!args.csv.empty() && (csv = std::fopen(args.csv.c_str(), "w")) == nullptr)
  {
    stack_bench_usage("cannot write " + args.csv);
  }
  if (args.engines.empty())
  {
    for (EngineKind kind : kAllEngines)
    {
      if (engine_available(kind))
      {
        args.engines.push_back(kind);
      }
    }
  }
  const std::vector<std::string> names = args.scenes.empty() ? stack_scene_names() : args.scenes;
  if (csv != nullptr)
  {
    std::fprintf(csv, "scene,boxes,engine,variant,pipeline,default_pipeline,ms_per_frame,cpu_ms_per_frame,"
                      "ms_over_box2d_v3,cpu_ms_over_box2d_v3,seconds,drift_m,max_penetration_m,sway_m\n");
  }
  if (!args.settings.empty())
  {
    std::printf("Set on every scene (--set):");
    for (const auto& [name, value] : args.settings)
    {
      std::printf(" %s=%s", name.c_str(), value.c_str());
    }
    std::printf("\n\n");
  }
  std::printf("| scene | boxes | engine | ms/frame | CPU ms/frame | time / Box2D v3 | CPU time / Box2D v3 | "
              "run (s) | drift 1 s -> run end (m) | sway 1 s -> run end (m) | largest penetration (m) |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n");
  try
  {
    for (const std::string& name : names)
    {
      BenchScene scene = make_bench_scene(name);
      scene.scene.settings = with_set_fields(scene.scene.settings, args);
      print_scene(scene, measure(scene, args), csv);
    }
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "collision2d_stack_bench: %s\n", error.what());
    return 1;
  }
  return 0;
}
