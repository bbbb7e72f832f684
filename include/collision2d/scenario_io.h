// `.collision` scenario files and the text report.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/contact_solver.h"

namespace collision2d
{
struct Scenario
{
  std::vector<Body> bodies;
  double restitution = 0.0;
  double friction = 0.0;
};

/// Parses the line-oriented format. Throws std::runtime_error naming the
/// source and line for malformed input, fewer than two bodies or a missing
/// restitution.
Scenario parse_scenario(std::istream& in, const std::string& source_name = "<input>");
Scenario load_scenario(const std::string& path);

/// Human-readable report of one resolve: contacts, solver iterations and
/// residual, momentum, angular momentum and kinetic energy before and after.
void write_report(std::ostream& out, const std::vector<Body>& before, const std::vector<Body>& after,
                  const std::vector<Contact>& contacts, const SolveReport& report);

}  // namespace collision2d
