// Measurements of collision2d_world_bench.
#include "world_bench_metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "collision2d/contact_solver.h"
#include "timing.h"

namespace collision2d
{
namespace bench
{
namespace
{
/// Gap (relative to the pair's size) that still counts as resting contact.
constexpr double kTouchTolerance = 1e-9;
constexpr double kMillisecondsPerSecond = 1e3;

/// Wall time of one frame (ms), averaged over `frames` frames of a fresh world.
double time_per_frame(const Scene& scene, int frames)
{
  World world = make_world(scene);
  const auto start = std::chrono::steady_clock::now();
  world.step(frames);
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(stop - start).count() * kMillisecondsPerSecond / frames;
}

std::vector<Body> bodies_of(const Scene& scene)
{
  std::vector<Body> bodies;
  for (const SceneBody& entry : scene.bodies)
  {
    bodies.push_back(entry.body);
  }
  return bodies;
}

bool is_resting(const Scene& scene)
{
  const Vec2 g = scene.settings.gravity;
  if (g.x == 0.0 && g.y == 0.0)
  {
    return false;
  }
  const std::vector<Body> bodies = bodies_of(scene);
  std::vector<bool> touching(bodies.size(), false);
  for (const Contact& c : ContactSolver::detect_contacts(bodies, kTouchTolerance))
  {
    touching[c.a] = touching[c.b] = true;
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    const Body& b = bodies[i];
    const bool still = b.velocity() == Vec2{} && b.omega() == 0.0;
    if (b.type() == BodyType::Dynamic && !(still && touching[i]))
    {
      return false;
    }
  }
  return true;
}

bool is_conservative(const Scene& scene)
{
  const Vec2 g = scene.settings.gravity;
  return g.x == 0.0 && g.y == 0.0 &&
         std::all_of(scene.bodies.begin(), scene.bodies.end(), [](const SceneBody& e) {
           return e.material.restitution == 1.0 && e.material.static_friction == 0.0 &&
                  e.material.kinetic_friction == 0.0;
         });
}

double initial_kinetic_energy(const Scene& scene)
{
  double energy = 0.0;
  for (const SceneBody& entry : scene.bodies)
  {
    energy += entry.body.type() == BodyType::Dynamic ? entry.body.kinetic_energy() : 0.0;
  }
  return energy;
}

/// One run of settle_seconds under Auto, frame by frame.
void measure_accuracy(const Scene& scene, const BenchOptions& options, SceneMetrics& m)
{
  World world = make_world(scene);
  const std::vector<BodyId> ids = world.body_ids();
  const int frames = frames_for(options.settle_seconds, scene.settings.dt);
  double energy = initial_kinetic_energy(scene);
  const double energy_start = energy;
  for (int f = 0; f < frames; ++f)
  {
    const StepReport report = world.step(1);
    m.max_penetration = std::max(m.max_penetration, report.max_penetration);
    m.auto_effects |= report.active;
    energy = report.kinetic_energy;
  }
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    if (scene.bodies[i].body.type() == BodyType::Dynamic)
    {
      m.drift = std::max(m.drift, length(world.body(ids[i]).position() - scene.bodies[i].body.position()));
    }
  }
  m.energy_error = energy_start > 0.0 ? std::abs(energy - energy_start) / energy_start : 0.0;
}

}  // namespace

WorldSettings all_effects_on(WorldSettings s)
{
  // Sleeping is left as the scene sets it: forcing it On removes work and
  // freezes bodies, which would hide the cost of the physics forced on.
  s.rotation = s.friction = s.restitution = s.position_correction = Toggle::On;
  s.time_of_impact = s.warm_starting = Toggle::On;
  return s;
}

SceneMetrics measure_scene(const Scene& scene, const BenchOptions& options)
{
  SceneMetrics m;
  m.name = scene.name;
  m.bodies = scene.bodies.size();
  m.resting = is_resting(scene);
  m.conservative = is_conservative(scene);

  Scene forced = scene;
  forced.settings = all_effects_on(scene.settings);
  const int frames = frames_for(options.seconds, scene.settings.dt);
  std::vector<double> auto_ms;
  std::vector<double> on_ms;
  for (int r = 0; r < options.repetitions; ++r)
  {
    auto_ms.push_back(time_per_frame(scene, frames));
    on_ms.push_back(time_per_frame(forced, frames));
  }
  m.ms_per_step_auto = median(auto_ms);
  m.ms_per_step_on = median(on_ms);

  measure_accuracy(scene, options, m);
  return m;
}

}  // namespace bench
}  // namespace collision2d
