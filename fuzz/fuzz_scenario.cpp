// libFuzzer target: `.collision` text -> parse_scenario -> resolve -> report.
// Malformed text must be rejected with std::runtime_error; what parses must
// resolve (coincident disk centres may throw std::runtime_error, as
// documented) without sanitizer reports, and give finite bodies when the
// input lies in the ranges of fuzz_support.h.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scenario_io.h"
#include "fuzz_support.h"

using namespace collision2d;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  Scenario scenario;
  try
  {
    scenario = parse_scenario(in, "fuzz.collision");
  }
  catch (const std::runtime_error&)
  {
    return 0;  // rejected with a located message: the contract
  }
  const std::vector<Body> before = scenario.bodies;
  const ContactSolver solver(scenario.restitution, scenario.friction);
  std::vector<Body> after = scenario.bodies;
  try
  {
    const std::vector<Contact> contacts = ContactSolver::detect_contacts(after);
    const SolveReport report = solver.resolve(after);
    std::ostringstream text;
    write_report(text, before, after, contacts, report);
  }
  catch (const std::runtime_error&)
  {
    return 0;  // undefined normal (coincident centres)
  }
  if (fuzz::in_range(before))
  {
    fuzz::require_finite(after, "resolve of an in-range scenario gave a non-finite body");
  }
  return 0;
}
