// The one table of the settings of a stateless resolve (ContactSolver plus the
// time-of-impact sweep): what the ResolveContacts service and the node's
// solver_* parameters carry. Same conventions as world_settings.h.
#pragma once

#include "collision2d/contact_solver.h"
#include "collision2d/setting_table.h"

namespace collision2d
{
/// Largest sweep cap: a cap beyond it only lets one request hold a thread for minutes.
constexpr double kMaxSolverIterations = 100000;
constexpr SettingRange kSolverIterationRange{1.0, kMaxSolverIterations, false};

// One line per setting, X(name, type, default, range, "unit", "doc"); the
// defaults are the node's (config/collision2d.yaml), not ContactSolver's
// constructor defaults. SolverSettings.msg needs a field of the same name.
// clang-format off
#define COLLISION2D_RESOLVE_SETTINGS(X) \
  X(restitution, double, 0.5, kUnitInterval, "", "Newton restitution e") \
  X(friction, double, 0.3, kNonNegative, "", "Coulomb friction mu") \
  X(iterations, int, 64, kSolverIterationRange, "", "Sweep cap: more buys accuracy on coupled stacks") \
  X(tolerance, double, 1e-9, kPositive, "m/s", "Residual that ends the solve") \
  X(bias_factor, double, 0.2, kUnitInterval, "", "Fraction of the penetration beyond slop removed") \
  X(slop, double, 1e-3, kNonNegative, "m", "Penetration left uncorrected") \
  X(use_time_of_impact, bool, false, kAnyFinite, "", "Sweep to the earliest impact before resolving") \
  X(mode, SolverMode, SolverMode::Iterative, kAnyFinite, "", "Velocity solve: iterative to a fixed point, or exact LCP per island")
// clang-format on

struct ResolveSettings
{
  COLLISION2D_RESOLVE_SETTINGS(COLLISION2D_DECLARE_SETTING)
};

/// Calls visit(info, field) for every field, in table order.
template <typename Settings, typename Visit>
void visit_resolve_settings(Settings& settings, Visit&& visit)
{
  COLLISION2D_RESOLVE_SETTINGS(COLLISION2D_VISIT_SETTING)
}

/// Throws std::invalid_argument "ResolveSettings.<field> must be ... (got ...)".
void validate_resolve_settings(const ResolveSettings& settings);
/// A solver as `settings` say (mode included); validates first.
ContactSolver make_contact_solver(const ResolveSettings& settings);

}  // namespace collision2d
