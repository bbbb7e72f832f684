// Per-run measurements (see metrics.h). Everything is computed from the body
// states an engine reports at frame ends, with our own detection for overlap,
// so ours and the peers are judged by the same code.
#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "collision2d/contact_solver.h"
#include "timing.h"

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kInclineWindowStart = 0.5;  // s: the box has left its first-frame transient
/// Timed repetitions of one run at most, however short each is.
constexpr int kMaxRepetitions = 5000;

using States = std::vector<BodyState>;


bool is_dynamic(const Scene& scene, std::size_t i)
{
  return scene.bodies[i].body.type() == BodyType::Dynamic;
}

std::size_t first_dynamic(const Scene& scene)
{
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    if (is_dynamic(scene, i))
    {
      return i;
    }
  }
  throw std::invalid_argument("scene '" + scene.name + "' has no dynamic body");
}

double kinetic_energy(const Scene& scene, const States& states)
{
  double energy = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i)
  {
    if (is_dynamic(scene, i))
    {
      const Body& b = scene.bodies[i].body;
      energy += 0.5 * (b.mass() * length_sq(states[i].velocity) + b.inertia() * states[i].omega * states[i].omega);
    }
  }
  return energy;
}


/// Largest overlap at these states, by our detection; infinite when the
/// states are degenerate (coincident centres: the engine blew up).
class PenetrationProbe
{
public:
  explicit PenetrationProbe(const Scene& scene)
  {
    for (const SceneBody& entry : scene.bodies)
    {
      bodies_.push_back(entry.body);
    }
  }

  double measure(const States& states)
  {
    for (std::size_t i = 0; i < states.size(); ++i)
    {
      bodies_[i].set_position(states[i].position);
      bodies_[i].set_theta(states[i].theta);
    }
    try
    {
      double deepest = 0.0;
      for (const Contact& c : ContactSolver::detect_contacts(bodies_))
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

private:
  std::vector<Body> bodies_;
};

/// Restitution measured from the apex after the first bounce: the rebound
/// height over the drop height is e^2 (frame sampling errs by g dt^2 / 8 at
/// the apex, where the disk is slowest).
class BounceTracker
{
public:
  BounceTracker(const Scene& scene, const States& start) : start_(start)
  {
    phase_.assign(start.size(), Phase::Falling);
    apex_.assign(start.size(), 0.0);
    for (std::size_t i = 0; i < start.size(); ++i)
    {
      if (!is_dynamic(scene, i))
      {
        phase_[i] = Phase::Ignored;
      }
    }
  }

  void frame(const States& states)
  {
    for (std::size_t i = 0; i < states.size(); ++i)
    {
      const double vy = states[i].velocity.y;
      if (phase_[i] == Phase::Falling && vy > 0.0)
      {
        phase_[i] = Phase::Rising;
      }
      if (phase_[i] == Phase::Rising)
      {
        apex_[i] = std::max(apex_[i], states[i].position.y);
        phase_[i] = vy <= 0.0 ? Phase::Done : Phase::Rising;
      }
    }
  }

  /// The ground's top face is y = 0, so a disk touches it at y = radius.
  double error(const Scene& scene, double e) const
  {
    double worst = 0.0;
    for (std::size_t i = 0; i < start_.size(); ++i)
    {
      if (phase_[i] == Phase::Ignored)
      {
        continue;
      }
      const double r = scene.bodies[i].body.radius();
      const double drop = start_[i].position.y - r;
      const double measured = phase_[i] == Phase::Done ? std::sqrt(std::max(0.0, apex_[i] - r) / drop) : 0.0;
      worst = std::max(worst, std::abs(measured - e));
    }
    return worst;
  }

private:
  enum class Phase
  {
    Falling,
    Rising,
    Done,
    Ignored
  };
  States start_;
  std::vector<Phase> phase_;
  std::vector<double> apex_;
};

double downhill_speed(const BodyState& s, double angle)
{
  return -(s.velocity.x * std::cos(angle) + s.velocity.y * std::sin(angle));
}

/// Runs the accuracy pass and fills every metric of the scene's kind.
void measure_accuracy(const BenchScene& bs, const EngineConfig& config, double seconds, double settle_seconds,
                      RunMetrics& m)
{
  const Scene& scene = bs.scene;
  std::unique_ptr<Engine> engine = make_engine(scene, config);
  const double dt = scene.settings.dt;
  const int frames = frames_for(seconds, dt);
  const int settle_frame = frames_for(settle_seconds, dt);
  const int incline_frame = frames_for(kInclineWindowStart, dt);
  const std::size_t mover = first_dynamic(scene);

  States start(scene.bodies.size());
  read_states(*engine, start);
  States now = start;
  States settled = start;
  PenetrationProbe probe(scene);
  BounceTracker bounce(scene, start);
  const double energy_start = kinetic_energy(scene, start);
  double energy_error = 0.0;
  double incline_speed_start = 0.0;

  m.max_penetration = 0.0;
  for (int f = 1; f <= frames; ++f)
  {
    engine->step_frame();
    read_states(*engine, now);
    m.max_penetration = std::max(m.max_penetration, probe.measure(now));
    energy_error = std::max(energy_error, std::abs(kinetic_energy(scene, now) - energy_start));
    bounce.frame(now);
    settled = f == settle_frame ? now : settled;
    incline_speed_start = f == incline_frame ? downhill_speed(now[mover], bs.slope_angle) : incline_speed_start;
  }

  switch (bs.kind)
  {
    case SceneKind::Resting:
      m.sink = largest_move(scene, start, settled);
      m.drift = m.error = largest_move(scene, settled, now);
      break;
    case SceneKind::Conservative:
      m.energy_error = m.error = energy_start > 0.0 ? energy_error / energy_start : 0.0;
      break;
    case SceneKind::Bounce:
      m.bounce_error = m.error = bounce.error(scene, bs.restitution);
      break;
    case SceneKind::Incline:
    {
      const double window = (frames - incline_frame) * dt;
      const double accel = (downhill_speed(now[mover], bs.slope_angle) - incline_speed_start) / window;
      m.incline_error = m.error = std::abs(accel - bs.expected_accel);
      break;
    }
    case SceneKind::Bullet:
      m.tunnelled = m.error = now[mover].position.x > bs.wall_x ? 1.0 : 0.0;
      break;
  }
}

}  // namespace

FrameTime time_run(const BenchScene& scene, const EngineConfig& config, const RunOptions& options)
{
  const int frames = frames_for(options.timing_seconds, scene.scene.settings.dt);
  std::vector<double> wall;
  std::vector<double> cpu;
  double timed_ms = 0.0;
  for (int r = 0; r < options.repetitions || (timed_ms < options.min_timed_ms && r < kMaxRepetitions); ++r)
  {
    std::unique_ptr<Engine> engine = make_engine(scene.scene, config);
    const FrameTime t = time_frames(*engine, frames);
    wall.push_back(t.wall_ms);
    cpu.push_back(t.cpu_ms);
    timed_ms += t.wall_ms * frames;
  }
  return FrameTime{median(wall), median(cpu)};
}

RunMetrics measure_run(const BenchScene& scene, const EngineConfig& config, const RunOptions& options)
{
  RunMetrics m;
  const FrameTime t = time_run(scene, config, options);
  m.ms_per_step = t.wall_ms;
  m.cpu_ms_per_step = t.cpu_ms;
  const double seconds = options.seconds > 0.0 ? options.seconds : scene.seconds;
  measure_accuracy(scene, config, seconds, options.settle_seconds, m);
  return m;
}

}  // namespace bench
}  // namespace collision2d
