// Solver and world settings: messages <-> core, validated with messages that
// name the field ("settings: iterations = 0 must be in [1, 100000]").
#pragma once

#include "collision2d/ros/messages.h"

#include "collision2d/contact_solver.h"
#include "collision2d/resolve_settings.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace ros_interface
{
/// Every field but use_node_settings. Throws InvalidRequest naming the field.
ResolveSettings resolve_settings_from_msg(const SolverSettings& msg);
/// use_node_settings false.
SolverSettings resolve_settings_to_msg(const ResolveSettings& settings);
/// A solver configured as `msg` says (mode included). Throws InvalidRequest.
ContactSolver solver_from_msg(const SolverSettings& msg);

/// Throws InvalidRequest naming the field.
WorldSettings world_settings_from_msg(const WorldConfig& msg);
WorldConfig world_settings_to_msg(const WorldSettings& settings);

Effects effects_to_msg(const ActiveEffects& effects);

}  // namespace ros_interface
}  // namespace collision2d
