// dynamic_reconfigure (cfg/Collision2d.cfg) <-> the settings tables. The cfg
// declares solver_<name> for each ResolveSettings field and world_<name> for
// each WorldSettings field (world_gravity_x / _y for the vector), read from the
// tables themselves, and sets no limits, so the node sees what the user sent.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <collision2d/Collision2dConfig.h>

#include "collision2d/resolve_settings.h"
#include "collision2d/ros/messages.h"
#include "collision2d/world_settings.h"

namespace collision2d
{
namespace ros_interface
{
/// Levels of cfg/Collision2d.cfg: which group a change touched.
constexpr unsigned kSolverLevel = 1;
constexpr unsigned kWorldLevel = 2;

/// The solver_* fields. Throws InvalidRequest "solver_x = v is outside [lo, hi]".
ResolveSettings resolve_settings_from_config(const Collision2dConfig& config);
void resolve_settings_to_config(const ResolveSettings& settings, Collision2dConfig& config);
/// The world_* fields, validated against the table. Throws InvalidRequest
/// "world_dt = -1 is outside (0, inf)".
WorldSettings world_settings_from_config(const Collision2dConfig& config);
void world_settings_to_config(const WorldSettings& settings, Collision2dConfig& config);

/// What the node keeps after a reconfigure request: the solver settings
/// `config` asks for, or, when one is out of range, `current` (the table's
/// defaults if `current` itself is invalid) after a WARN naming the field, the
/// value and the range, written back into `config` so clients see it.
SolverSettings accept_solver_config(Collision2dConfig& config, const SolverSettings& current);
/// `current` with each world_* field that `config` changes from `shown` (the
/// config the server last published, which the server merged the request
/// into). A scene load puts its settings in force before it publishes them:
/// a request arriving in between changes only what it asks, not the rest back
/// to the old scene's. Throws InvalidRequest naming a field out of range.
WorldSettings merge_world_config(const Collision2dConfig& config, const Collision2dConfig& shown,
                                 const WorldSettings& current);

/// Applies a change to the world's settings atomically; returns the settings then in force.
using WorldSettingsEditor =
    std::function<WorldSettings(const std::function<WorldSettings(const WorldSettings&)>& change)>;
/// Edits the world's settings with what `config` changes from `shown` and
/// writes the result into `config`; when a field is out of range (or the edit
/// throws InvalidRequest) WARNs and writes `shown`'s world fields back instead.
void accept_world_config(Collision2dConfig& config, const Collision2dConfig& shown, const WorldSettingsEditor& edit);

/// Names of the parameters the tables ask of the cfg, in table order.
std::vector<std::string> table_parameter_names();

}  // namespace ros_interface
}  // namespace collision2d
