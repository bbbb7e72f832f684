// Validation of a resolve's settings and the solver they configure.
#include "collision2d/resolve_settings.h"

namespace collision2d
{
void validate_resolve_settings(const ResolveSettings& settings)
{
  visit_resolve_settings(settings, SettingCheck("ResolveSettings"));
}

ContactSolver make_contact_solver(const ResolveSettings& s)
{
  validate_resolve_settings(s);
  ContactSolver solver(s.restitution, s.friction, s.iterations, s.tolerance, s.bias_factor, s.slop);
  solver.set_mode(s.mode);
  return solver;
}

}  // namespace collision2d
