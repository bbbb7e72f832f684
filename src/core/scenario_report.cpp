// The text report of one resolve or step: what touched, how the solver did,
// and the conserved (or dissipated) totals before and after, side by side.
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "collision2d/scenario_io.h"

namespace collision2d
{
namespace
{
/// Significant digits: enough to see round-off in conserved totals, few
/// enough to read.
constexpr int kDigits = 10;
constexpr int kLabelWidth = 28;
constexpr int kNumberWidth = 20;
/// Relative energy gain below which a rise is round-off of an elastic impact.
constexpr double kEnergyRoundOff = 1e-12;

/// Fixed formatting independent of the stream's state; -0 prints as 0.
std::string number(double value)
{
  std::ostringstream out;
  out << std::setprecision(kDigits) << (value == 0.0 ? 0.0 : value);
  return out.str();
}

std::string vec(Vec2 v) { return "(" + number(v.x) + ", " + number(v.y) + ")"; }

struct Totals
{
  Vec2 momentum;
  double angular_momentum = 0.0;
  double kinetic_energy = 0.0;
};

Totals totals(const std::vector<Body>& bodies)
{
  Totals sum;
  for (const Body& body : bodies)
  {
    sum.momentum += body.momentum();
    sum.angular_momentum += body.angular_momentum();
    sum.kinetic_energy += body.kinetic_energy();
  }
  return sum;
}

void write_contacts(std::ostream& out, const std::vector<Contact>& contacts)
{
  out << "contacts: " << contacts.size() << "\n";
  for (const Contact& c : contacts)
  {
    out << "  " << std::left << std::setw(8) << (std::to_string(c.a) + "-" + std::to_string(c.b)) << "point "
        << std::setw(2 * kNumberWidth) << vec(c.point) << "normal " << std::setw(2 * kNumberWidth) << vec(c.normal)
        << "depth " << number(c.penetration) << "\n";
  }
}

void write_solver(std::ostream& out, const SolveReport& report)
{
  out << "solver: " << report.iterations << " iterations, residual " << number(report.max_residual)
      << " m/s, converged " << (report.converged ? "yes" : "no") << ", total normal impulse "
      << number(report.total_normal_impulse) << " N s\n";
  if (report.time_of_impact < 1.0)
  {
    out << "time of impact: " << number(report.time_of_impact) << " of the step\n";
  }
}

void write_row(std::ostream& out, const std::string& label, double before, double after)
{
  out << std::left << std::setw(kLabelWidth) << label << std::setw(kNumberWidth) << number(before)
      << std::setw(kNumberWidth) << number(after) << number(after - before) << "\n";
}

void write_totals(std::ostream& out, const Totals& before, const Totals& after)
{
  out << std::left << std::setw(kLabelWidth) << "" << std::setw(kNumberWidth) << "before" << std::setw(kNumberWidth)
      << "after"
      << "change\n";
  write_row(out, "momentum x (kg m/s)", before.momentum.x, after.momentum.x);
  write_row(out, "momentum y (kg m/s)", before.momentum.y, after.momentum.y);
  write_row(out, "angular momentum (kg m^2/s)", before.angular_momentum, after.angular_momentum);
  write_row(out, "kinetic energy (J)", before.kinetic_energy, after.kinetic_energy);
}

void write_energy_change(std::ostream& out, double before, double after)
{
  const double change = after - before;
  out << "energy change: " << number(change) << " J";
  if (before > 0.0)
  {
    out << " (" << number(100.0 * change / before) << " %)";
  }
  if (change > kEnergyRoundOff * before)
  {
    // By the solver's contract, a contact that was resting or separating before the
    // solve, pushed by its neighbours, has target 0 and can add energy.
    out << ": energy rose, a resting contact was pushed into action by its neighbours";
  }
  out << "\n";
}

}  // namespace

void write_report(std::ostream& out, const std::vector<Body>& before, const std::vector<Body>& after,
                  const std::vector<Contact>& contacts, const SolveReport& report)
{
  std::ostringstream text;  // built apart so the caller's stream flags stay untouched
  const Totals t0 = totals(before);
  const Totals t1 = totals(after);
  write_contacts(text, contacts);
  write_solver(text, report);
  write_totals(text, t0, t1);
  write_energy_change(text, t0.kinetic_energy, t1.kinetic_energy);
  out << text.str();
}

}  // namespace collision2d
