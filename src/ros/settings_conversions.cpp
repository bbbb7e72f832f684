// SolverSettings / WorldConfig <-> ContactSolver / WorldSettings.
#include "collision2d/ros/settings_conversions.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
const char* const kSettings = "settings";

SolverMode solver_mode_from_msg(std::uint8_t mode)
{
  switch (mode)
  {
    case SolverSettings::ITERATIVE:
      return SolverMode::Iterative;
    case SolverSettings::EXACT:
      return SolverMode::Exact;
    default:
      reject(kSettings, "mode = " + std::to_string(mode) + " is not ITERATIVE (0) or EXACT (1)");
  }
}

SolverMode world_solver_mode_from_msg(std::uint8_t mode)
{
  switch (mode)
  {
    case WorldConfig::SOLVER_ITERATIVE:
      return SolverMode::Iterative;
    case WorldConfig::SOLVER_EXACT:
      return SolverMode::Exact;
    default:
      reject(kSettings,
             "solver_mode = " + std::to_string(mode) + " is not SOLVER_ITERATIVE (0) or SOLVER_EXACT (1)");
  }
}

std::uint8_t world_solver_mode_to_msg(SolverMode mode)
{
  return mode == SolverMode::Exact ? WorldConfig::SOLVER_EXACT : WorldConfig::SOLVER_ITERATIVE;
}

Toggle toggle_from_msg(std::uint8_t value, const char* field)
{
  switch (value)
  {
    case WorldConfig::AUTO:
      return Toggle::Auto;
    case WorldConfig::ON:
      return Toggle::On;
    case WorldConfig::OFF:
      return Toggle::Off;
    default:
      reject(kSettings, std::string(field) + " = " + std::to_string(value) + " is not AUTO (0), ON (1) or OFF (2)");
  }
}

std::uint8_t toggle_to_msg(Toggle toggle)
{
  switch (toggle)
  {
    case Toggle::On:
      return WorldConfig::ON;
    case Toggle::Off:
      return WorldConfig::OFF;
    case Toggle::Auto:
      break;
  }
  return WorldConfig::AUTO;
}

}  // namespace

ContactSolver solver_from_msg(const SolverSettings& msg)
{
  require_in_range(msg.restitution, 0.0, 1.0, kSettings, "restitution");
  require_non_negative(msg.friction, kSettings, "friction");
  if (msg.iterations < 1 || msg.iterations > kMaxSolverIterations)
  {
    reject(kSettings, "iterations = " + std::to_string(msg.iterations) + " must be in [1, " +
                          std::to_string(kMaxSolverIterations) + "]");
  }
  require_positive(msg.tolerance, kSettings, "tolerance");
  require_in_range(msg.bias_factor, 0.0, 1.0, kSettings, "bias_factor");
  require_non_negative(msg.slop, kSettings, "slop");
  const SolverMode mode = solver_mode_from_msg(msg.mode);
  try
  {
    ContactSolver solver(msg.restitution, msg.friction, msg.iterations, msg.tolerance, msg.bias_factor, msg.slop);
    solver.set_mode(mode);
    return solver;
  }
  catch (const std::invalid_argument& e)
  {
    reject(kSettings, e.what());
  }
}

WorldSettings world_settings_from_msg(const WorldConfig& msg)
{
  require_finite(msg.gravity.x, kSettings, "gravity.x");
  require_finite(msg.gravity.y, kSettings, "gravity.y");
  WorldSettings settings;
  settings.gravity = Vec2{msg.gravity.x, msg.gravity.y};
  settings.dt = msg.dt;
  settings.substeps = msg.substeps;
  settings.velocity_iterations = msg.velocity_iterations;
  settings.slop = msg.slop;
  settings.compliance = msg.compliance;
  settings.restitution_threshold = msg.restitution_threshold;
  settings.solver_mode = world_solver_mode_from_msg(msg.solver_mode);
  settings.position_iterations = msg.position_iterations;
  settings.position_block = msg.position_block;
  settings.exact_position_correction = msg.exact_position_correction;
  settings.warm_start_before_integration = msg.warm_start_before_integration;
  settings.rotation = toggle_from_msg(msg.rotation, "rotation");
  settings.friction = toggle_from_msg(msg.friction, "friction");
  settings.restitution = toggle_from_msg(msg.restitution, "restitution");
  settings.position_correction = toggle_from_msg(msg.position_correction, "position_correction");
  settings.time_of_impact = toggle_from_msg(msg.time_of_impact, "time_of_impact");
  settings.warm_starting = toggle_from_msg(msg.warm_starting, "warm_starting");
  settings.sleeping = toggle_from_msg(msg.sleeping, "sleeping");
  settings.warm_start_factor = msg.warm_start_factor;
  settings.warm_start_every_substep = msg.warm_start_every_substep;
  settings.toi_displacement_fraction = msg.toi_displacement_fraction;
  settings.sleep_linear_speed = msg.sleep_linear_speed;
  settings.sleep_angular_speed = msg.sleep_angular_speed;
  settings.sleep_time = msg.sleep_time;
  settings.sleep_auto_min_bodies = msg.sleep_auto_min_bodies;
  try
  {
    // The world's own ranges are the authority; its message names the field.
    World::validate(settings);
  }
  catch (const std::invalid_argument& e)
  {
    reject(kSettings, e.what());
  }
  return settings;
}

WorldConfig world_settings_to_msg(const WorldSettings& settings)
{
  WorldConfig msg;
  msg.gravity.x = settings.gravity.x;
  msg.gravity.y = settings.gravity.y;
  msg.dt = settings.dt;
  msg.substeps = settings.substeps;
  msg.velocity_iterations = settings.velocity_iterations;
  msg.slop = settings.slop;
  msg.compliance = settings.compliance;
  msg.restitution_threshold = settings.restitution_threshold;
  msg.solver_mode = world_solver_mode_to_msg(settings.solver_mode);
  msg.position_iterations = settings.position_iterations;
  msg.position_block = settings.position_block;
  msg.exact_position_correction = settings.exact_position_correction;
  msg.warm_start_before_integration = settings.warm_start_before_integration;
  msg.rotation = toggle_to_msg(settings.rotation);
  msg.friction = toggle_to_msg(settings.friction);
  msg.restitution = toggle_to_msg(settings.restitution);
  msg.position_correction = toggle_to_msg(settings.position_correction);
  msg.time_of_impact = toggle_to_msg(settings.time_of_impact);
  msg.warm_starting = toggle_to_msg(settings.warm_starting);
  msg.sleeping = toggle_to_msg(settings.sleeping);
  msg.warm_start_factor = settings.warm_start_factor;
  msg.warm_start_every_substep = settings.warm_start_every_substep;
  msg.toi_displacement_fraction = settings.toi_displacement_fraction;
  msg.sleep_linear_speed = settings.sleep_linear_speed;
  msg.sleep_angular_speed = settings.sleep_angular_speed;
  msg.sleep_time = settings.sleep_time;
  msg.sleep_auto_min_bodies = static_cast<std::uint32_t>(
      std::min<std::size_t>(settings.sleep_auto_min_bodies, std::numeric_limits<std::uint32_t>::max()));
  return msg;
}

Effects effects_to_msg(const ActiveEffects& effects)
{
  Effects msg;
  msg.rotation = effects.rotation;
  msg.friction = effects.friction;
  msg.restitution = effects.restitution;
  msg.position_correction = effects.position_correction;
  msg.time_of_impact = effects.time_of_impact;
  msg.warm_starting = effects.warm_starting;
  msg.sleeping = effects.sleeping;
  return msg;
}

}  // namespace ros_interface
}  // namespace collision2d
