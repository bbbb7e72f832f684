// libFuzzer target: `.collision` text -> parse_scenario -> resolve -> report.
// Malformed text must be rejected with std::runtime_error; what parses must
// resolve (coincident disk centres may throw std::runtime_error, as
// documented) without sanitizer reports and give finite bodies. Far outside
// the ranges of fuzz_support.h the solve may overflow: it must then throw
// std::overflow_error and leave the bodies as they were.
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
  catch (const std::overflow_error&)
  {
    // Refused, with the bodies left as they came in; only allowed far
    // outside the promised ranges.
    fuzz::require(!fuzz::in_range(before), "resolve of an in-range scenario overflowed");
    fuzz::require(fuzz::same_state(before, after), "an overflowed resolve changed the bodies");
    return 0;
  }
  catch (const std::runtime_error&)
  {
    return 0;  // undefined normal (coincident centres)
  }
  // resolve() never hands back a non-finite body: it throws instead.
  fuzz::require_finite(after, "resolve gave a non-finite body");
  return 0;
}
