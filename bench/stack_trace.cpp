// collision2d_stack_trace: where a stack's drift comes from. Steps one stack
// scene (stack_scenes.h) in one engine, with the stack bench's rule for
// peers, and prints every N frames the top body's pose and the stack's
// drift so far (largest displacement of any dynamic body since 1 s, as the
// stack bench measures it), so a settling sway can be told from a creep.
//
//   collision2d_stack_trace --scene NAME [--engine NAME] [--seconds S] [--every N]
//                           [--substeps K]
//
// Prints CSV: t_s,top_x_m,top_y_m,top_theta_rad,drift_since_1s_m
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine.h"
#include "stack_scenes.h"
#include "timing.h"

namespace
{
using namespace collision2d::bench;

struct Arguments
{
  std::string scene;
  EngineKind engine = EngineKind::Collision2d;
  double seconds = 8.0;
  int every = 5;     ///< frames between rows
  int substeps = 0;  ///< 0: the scene's (4)
};

Arguments parse_arguments(int argc, char** argv)
{
  Arguments a;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    const bool engine = key == "--engine" && engine_from_name(value, a.engine);
    if (key == "--scene")
    {
      a.scene = value;
    }
    else if (key == "--seconds" && std::atof(value.c_str()) > 0.0)
    {
      a.seconds = std::atof(value.c_str());
    }
    else if (key == "--every" && std::atoi(value.c_str()) > 0)
    {
      a.every = std::atoi(value.c_str());
    }
    else if (key == "--substeps" && std::atoi(value.c_str()) > 0)
    {
      a.substeps = std::atoi(value.c_str());
    }
    else if (!engine)
    {
      throw std::invalid_argument("unknown or bad argument: " + key + " " + value);
    }
  }
  if (a.scene.empty() || argc % 2 == 0)
  {
    throw std::invalid_argument("--scene NAME is required, and every option takes a value");
  }
  return a;
}

}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const Arguments args = parse_arguments(argc, argv);
    collision2d::Scene scene = make_stack_scene(args.scene).scene;
    if (args.substeps > 0)
    {
      scene.settings.substeps = args.substeps;  // the peers take it too (PeerVariant::Substepped)
    }
    std::unique_ptr<Engine> engine = make_engine(scene, EngineConfig{args.engine, PeerVariant::Substepped, scene.settings});
    // The scene builds its stack bottom up: the last dynamic body is the top.
    std::size_t top = 0;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
      top = scene.bodies[i].body.type() == collision2d::BodyType::Dynamic ? i : top;
    }
    const double dt = scene.settings.dt;
    const int settle_frame = frames_for(kStackSettleSeconds, dt);
    const int frames = frames_for(args.seconds, dt);
    std::vector<BodyState> settled(scene.bodies.size());
    std::vector<BodyState> now(scene.bodies.size());
    std::printf("t_s,top_x_m,top_y_m,top_theta_rad,drift_since_1s_m\n");
    for (int f = 1; f <= frames; ++f)
    {
      engine->step_frame();
      if (f == settle_frame)
      {
        read_states(*engine, settled);
      }
      if (f % args.every != 0)
      {
        continue;
      }
      read_states(*engine, now);
      const double drift = f < settle_frame ? 0.0 : largest_move(scene, settled, now);
      const BodyState& s = now[top];
      std::printf("%.4f,%.6g,%.6g,%.6g,%.6g\n", f * dt, s.position.x, s.position.y, s.theta, drift);
    }
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "collision2d_stack_trace: %s\n", error.what());
    return 2;
  }
  return 0;
}
