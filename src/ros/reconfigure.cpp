// The world_* fields of the config mirror WorldConfig, so the world settings
// go through the message conversion and share its validation.
#include "collision2d/ros/reconfigure.h"

#include "collision2d/ros/settings_conversions.h"

namespace collision2d
{
namespace ros_interface
{
SolverSettings solver_settings_from_config(const Collision2dConfig& config)
{
  SolverSettings msg;
  msg.restitution = config.solver_restitution;
  msg.friction = config.solver_friction;
  msg.iterations = config.solver_iterations;
  msg.tolerance = config.solver_tolerance;
  msg.bias_factor = config.solver_bias_factor;
  msg.slop = config.solver_slop;
  msg.use_time_of_impact = config.solver_use_time_of_impact;
  msg.mode = static_cast<std::uint8_t>(config.solver_mode);
  return msg;
}

WorldSettings world_settings_from_config(const Collision2dConfig& config, const WorldSettings& base)
{
  WorldConfig msg = world_settings_to_msg(base);
  msg.gravity.x = config.world_gravity_x;
  msg.gravity.y = config.world_gravity_y;
  msg.dt = config.world_dt;
  msg.substeps = config.world_substeps;
  msg.velocity_iterations = config.world_velocity_iterations;
  msg.solver_mode = static_cast<std::uint8_t>(config.world_solver_mode);
  msg.position_iterations = config.world_position_iterations;
  msg.position_block = config.world_position_block;
  msg.exact_position_correction = config.world_exact_position_correction;
  msg.warm_start_before_integration = config.world_warm_start_before_integration;
  msg.slop = config.world_slop;
  msg.compliance = config.world_compliance;
  msg.restitution_threshold = config.world_restitution_threshold;
  msg.rotation = static_cast<std::uint8_t>(config.world_rotation);
  msg.friction = static_cast<std::uint8_t>(config.world_friction);
  msg.restitution = static_cast<std::uint8_t>(config.world_restitution);
  msg.position_correction = static_cast<std::uint8_t>(config.world_position_correction);
  msg.time_of_impact = static_cast<std::uint8_t>(config.world_time_of_impact);
  msg.warm_starting = static_cast<std::uint8_t>(config.world_warm_starting);
  msg.sleeping = static_cast<std::uint8_t>(config.world_sleeping);
  msg.warm_start_factor = config.world_warm_start_factor;
  msg.warm_start_every_substep = config.world_warm_start_every_substep;
  msg.sleep_linear_speed = config.world_sleep_linear_speed;
  msg.sleep_angular_speed = config.world_sleep_angular_speed;
  msg.sleep_time = config.world_sleep_time;
  return world_settings_from_msg(msg);
}

void world_settings_to_config(const WorldSettings& settings, Collision2dConfig& config)
{
  const WorldConfig msg = world_settings_to_msg(settings);
  config.world_gravity_x = msg.gravity.x;
  config.world_gravity_y = msg.gravity.y;
  config.world_dt = msg.dt;
  config.world_substeps = msg.substeps;
  config.world_velocity_iterations = msg.velocity_iterations;
  config.world_solver_mode = msg.solver_mode;
  config.world_position_iterations = msg.position_iterations;
  config.world_position_block = msg.position_block;
  config.world_exact_position_correction = msg.exact_position_correction;
  config.world_warm_start_before_integration = msg.warm_start_before_integration;
  config.world_slop = msg.slop;
  config.world_compliance = msg.compliance;
  config.world_restitution_threshold = msg.restitution_threshold;
  config.world_rotation = msg.rotation;
  config.world_friction = msg.friction;
  config.world_restitution = msg.restitution;
  config.world_position_correction = msg.position_correction;
  config.world_time_of_impact = msg.time_of_impact;
  config.world_warm_starting = msg.warm_starting;
  config.world_sleeping = msg.sleeping;
  config.world_warm_start_factor = msg.warm_start_factor;
  config.world_warm_start_every_substep = msg.warm_start_every_substep;
  config.world_sleep_linear_speed = msg.sleep_linear_speed;
  config.world_sleep_angular_speed = msg.sleep_angular_speed;
  config.world_sleep_time = msg.sleep_time;
}

}  // namespace ros_interface
}  // namespace collision2d
