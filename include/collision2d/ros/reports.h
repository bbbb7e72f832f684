// Reports and world state for responses: the core's reports plus the
// conserved quantities before and after, so callers can check the physics.
#pragma once

#include <string>
#include <vector>

#include "collision2d/ros/messages.h"

#include "collision2d/body.h"
#include "collision2d/contact_solver.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace ros_interface
{
/// Sums over all bodies (static and kinematic ones included).
struct Totals
{
  double kinetic_energy = 0.0;    ///< J
  Vec2 momentum;                  ///< kg m/s
  double angular_momentum = 0.0;  ///< kg m^2/s about the world origin
};

Totals totals_of(const std::vector<Body>& bodies);
Totals totals_of(const World& world);

SolverReport solver_report_to_msg(const SolveReport& report, const Totals& before, const Totals& after);
StepSummary step_summary_to_msg(const StepReport& report, const Totals& before, const Totals& after);

/// Everything but the header: bodies in ascending id, the last substep's
/// contacts, settings and the effects the last step modelled.
WorldState world_state_to_msg(const World& world, const ActiveEffects& active, const std::string& scene);

}  // namespace ros_interface
}  // namespace collision2d
