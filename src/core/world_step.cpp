// The frame and substep pipeline of SPEC section 3: integrate, detect,
// penetration resolution, velocity derivation, velocity resolution, with warm
// starting on a frame's first substep.
//
// Velocity derivation (SPEC step 4): the penetration resolution shifts the
// previous pose by exactly the correction it applies, so (pose - previous) / h
// equals the velocity integrated in step 1. We therefore keep that integrated
// velocity instead of recomputing the difference quotient, which would lose
// digits far from the origin (large |p|, small h) and would turn a time-of-
// impact clamp (a shortened move) into a spurious loss of speed. With
// WorldSettings::warm_start_before_integration the pose is advanced with a
// predicted velocity (world_warm_integration.cpp), so that identity then no
// longer holds.
#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "collision2d/world.h"

namespace collision2d
{

StepReport World::step(int frames)
{
  if (frames < 1)
  {
    std::ostringstream msg;
    msg << "step: frames must be >= 1 (got " << frames << ")";
    throw std::invalid_argument(msg.str());
  }
  StepReport report;
  for (int f = 0; f < frames; ++f)
  {
    step_frame(report);
    require_finite_state();
  }
  report.max_penetration = measure_penetration();
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (bodies_[i].type() == BodyType::Dynamic)
    {
      report.kinetic_energy += bodies_[i].kinetic_energy();
    }
    report.sleeping_bodies += asleep_[i] ? 1 : 0;
  }
  return report;
}

void World::require_finite_state() const
{
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (non_finite_state_field(bodies_[i]) == nullptr)
    {
      continue;
    }
    std::ostringstream msg;
    msg << "step: body " << ids_[i] << " overflowed to a non-finite state in frame " << frame_count_
        << " (its speed, size or mass lies far beyond the supported ranges)";
    throw std::overflow_error(msg.str());
  }
}

void World::step_frame(StepReport& report)
{
  FrameEffects effects = select_effects();
  if (!effects.flags.sleeping)
  {
    asleep_.assign(bodies_.size(), false);
  }
  const double h = settings_.dt / settings_.substeps;
  for (int k = 0; k < settings_.substeps; ++k)
  {
    // The contacts of the previous substep (or frame) become the cache that
    // warm starting and the friction state read; swapping keeps both
    // buffers' capacity.
    cache_.swap(contacts_);
    const bool warm = effects.warm_start_now && (k == 0 || settings_.warm_start_every_substep);
    substep(effects, h, k == 0, warm, report);
    publish_contacts();
    cache_h_ = h;
  }
  if (effects.flags.sleeping)
  {
    update_sleep();
  }
  time_ += settings_.dt;
  ++frame_count_;
  ++report.frames;
  report.active |= effects.flags;
}

void World::substep(FrameEffects& effects, double h, bool first, bool warm, StepReport& report)
{
  kick(h);
  const bool predict = warm && settings_.warm_start_before_integration;
  if (predict)
  {
    predict_velocities(h, effects.flags.friction);
  }
  advance(effects, h, report);
  detect(effects.flags, warm, h, report);
  if (predict)
  {
    restore_velocities();
  }
  prepare_rows(effects.flags);
  if (effects.flags.position_correction)
  {
    correct_positions(h, effects.flags.friction, report);
  }
  if (settings_.solver_mode == SolverMode::Exact)
  {
    solve_exact_islands(report);
  }
  if (warm)
  {
    warm_start();
  }
  solve_velocities(effects.flags.friction);
  const double residual = velocity_residual();
  report.velocity_residual = std::max(report.velocity_residual, residual);
  if (first)
  {
    report.warm_substep_residual = residual;
  }
  ++report.substeps;
  report.contact_count = rows_.size();
}

void World::kick(double h)
{
  const Vec2 gravity_kick = settings_.gravity * h;
  prev_position_.resize(bodies_.size());
  prev_theta_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    prev_position_[i] = bodies_[i].position();
    prev_theta_[i] = bodies_[i].theta();
    if (bodies_[i].type() == BodyType::Dynamic && !asleep_[i])
    {
      bodies_[i].set_velocity(bodies_[i].velocity() + gravity_kick);
    }
  }
}

void World::advance(FrameEffects& effects, double h, StepReport& report)
{
  const bool swept = sweep(h, report);
  effects.flags.time_of_impact = effects.flags.time_of_impact || swept;
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    Body& b = bodies_[i];
    if (b.type() == BodyType::Static || asleep_[i])
    {
      continue;
    }
    const double travel = swept ? toi_[i] * h : h;
    b.set_position(b.position() + b.velocity() * travel);
    // Kinematic bodies follow their set spin whatever the rotation toggle says.
    const bool turns = effects.flags.rotation || b.type() == BodyType::Kinematic;
    if (turns && b.omega() != 0.0)
    {
      b.set_theta(b.theta() + b.omega() * h);
    }
  }
}

}  // namespace collision2d
