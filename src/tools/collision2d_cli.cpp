// collision2d_cli: load a `.collision` scenario, resolve it (or take one
// continuous step with --step) and print the report.
//
//   collision2d_cli <file.collision> [--iterations N] [--tol X] [--step]
//
// Exit codes: 0 done, 1 the scenario could not be loaded or resolved,
// 2 bad command-line arguments.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/scenario_io.h"
#include "collision2d/touch_tolerance.h"

namespace
{
using namespace collision2d;

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

/// Thrown for anything wrong with the command line (exit code 2).
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string path;
  // Defaults are the solver's own.
  int iterations = ContactSolver(0.0, 0.0).max_iterations();
  double tol = ContactSolver(0.0, 0.0).tolerance();
  bool step = false;
  bool help = false;
};

void print_usage(std::ostream& out)
{
  out << "usage: collision2d_cli <file.collision> [--iterations N] [--tol X] [--step]\n"
         "  --iterations N  solver sweep cap, N >= 1\n"
         "  --tol X         complementarity residual to stop at (m/s), X > 0\n"
         "  --step          move to the time of impact first, then resolve there\n";
}

/// The whole argument must be a number; `what` names it in the error.
double parse_number(const std::string& text, const std::string& what)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
  {
    throw UsageError(what + " expects a finite number, got '" + text + "'");
  }
  return value;
}

Options parse_options(const std::vector<std::string>& args)
{
  Options options;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& arg = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 == args.size())
      {
        throw UsageError(arg + " expects a value");
      }
      return args[++i];
    };
    if (arg == "--help" || arg == "-h")
    {
      options.help = true;
    }
    else if (arg == "--step")
    {
      options.step = true;
    }
    else if (arg == "--iterations")
    {
      const double n = parse_number(value(), arg);
      if (n < 1.0 || n != std::floor(n) || n > 1e9)
      {
        throw UsageError("--iterations expects a whole number >= 1");
      }
      options.iterations = static_cast<int>(n);
    }
    else if (arg == "--tol")
    {
      options.tol = parse_number(value(), arg);
      if (options.tol <= 0.0)
      {
        throw UsageError("--tol expects a number > 0");
      }
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      throw UsageError("unknown option '" + arg + "'");
    }
    else if (options.path.empty())
    {
      options.path = arg;
    }
    else
    {
      throw UsageError("more than one scenario file given ('" + options.path + "', '" + arg + "')");
    }
  }
  if (options.path.empty() && !options.help)
  {
    throw UsageError("no scenario file given");
  }
  return options;
}

/// Largest distance any body moved between two snapshots of the same scene (m).
double largest_move(const std::vector<Body>& from, const std::vector<Body>& to)
{
  double largest_sq = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i)
  {
    largest_sq = std::max(largest_sq, length_sq(to[i].position() - from[i].position()));
  }
  return std::sqrt(largest_sq);
}

/// Resolves (or steps) the scenario and prints the report. When resolving,
/// the totals are taken after the velocity solve: position correction then
/// moves bodies, which shifts the angular momentum about the origin
/// (m p x v) without any impulse, so it is reported as a distance instead.
void run(const Options& options)
{
  const Scenario scenario = load_scenario(options.path);
  const ContactSolver solver(scenario.restitution, scenario.friction, options.iterations, options.tol);
  std::vector<Body> bodies = scenario.bodies;
  Resolution out;
  std::cout << "scenario: " << options.path << (options.step ? " (one step)" : " (resolve)") << "\n";
  if (options.step)
  {
    solver.step(bodies, out);
    write_report(std::cout, scenario.bodies, bodies, out.contacts, out.report);
    return;
  }
  solver.resolve(bodies, out);
  write_report(std::cout, scenario.bodies, out.after_solve, out.contacts, out.report);
  std::cout << "position correction: largest move " << largest_move(out.after_solve, bodies) << " m\n";
}

}  // namespace

int main(int argc, char** argv)
{
  Options options;
  try
  {
    options = parse_options(std::vector<std::string>(argv + 1, argv + argc));
  }
  catch (const UsageError& e)
  {
    std::cerr << "collision2d_cli: " << e.what() << "\n";
    print_usage(std::cerr);
    return kExitUsage;
  }
  if (options.help)
  {
    print_usage(std::cout);
    return EXIT_SUCCESS;
  }
  try
  {
    run(options);
  }
  catch (const std::exception& e)
  {
    std::cerr << "collision2d_cli: " << e.what() << "\n";
    return kExitBadInput;
  }
  return EXIT_SUCCESS;
}
