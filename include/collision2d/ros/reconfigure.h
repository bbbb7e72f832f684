// dynamic_reconfigure (cfg/Collision2d.cfg) <-> the settings messages.
#pragma once

#include <collision2d/Collision2dConfig.h>
#include "collision2d/ros/messages.h"

#include "collision2d/world.h"

namespace collision2d
{
namespace ros_interface
{
/// Levels of cfg/Collision2d.cfg: which group a change touched.
constexpr unsigned kSolverLevel = 1;
constexpr unsigned kWorldLevel = 2;

SolverSettings solver_settings_from_config(const Collision2dConfig& config);
/// `base` with the fields the config carries replaced (the config leaves out
/// the rarely tuned ones). Throws InvalidRequest naming the field.
WorldSettings world_settings_from_config(const Collision2dConfig& config, const WorldSettings& base);
/// Shows the world's settings in the config (its solver fields untouched).
void world_settings_to_config(const WorldSettings& settings, Collision2dConfig& config);

}  // namespace ros_interface
}  // namespace collision2d
