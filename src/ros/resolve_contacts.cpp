// ResolveContacts: convert, run the core's detect / solve / correct (after the
// time-of-impact sweep when asked), convert back.
#include "collision2d/ros/resolve_contacts.h"

#include <exception>
#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/ros/conversions.h"
#include "collision2d/ros/reports.h"
#include "collision2d/ros/settings_conversions.h"
#include "collision2d/touch_tolerance.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
struct Resolution
{
  std::vector<Contact> contacts;
  std::vector<ContactImpulse> impulses;
  SolveReport report;
  Totals after;
  double time_of_impact = 0.0;
};

/// The core's resolve() (or step() with the sweep) spelled out, because the
/// response also carries the contacts and their impulses, which those calls
/// keep to themselves. Same calls in the same order, so the same results.
Resolution resolve(const ContactSolver& solver, bool sweep, std::vector<Body>& bodies)
{
  Resolution out;
  if (sweep)
  {
    out.time_of_impact = ContactSolver::time_of_impact(bodies);
    for (Body& body : bodies)
    {
      body.set_position(body.position() + out.time_of_impact * body.velocity());
    }
    out.contacts = ContactSolver::detect_contacts(bodies, kRelativeTouchTolerance);
  }
  else
  {
    out.contacts = ContactSolver::detect_contacts(bodies);
  }
  out.report = solver.solve(bodies, out.contacts, &out.impulses);
  // Angular momentum about the origin is conserved by the solve at the
  // positions it solved at; correction then moves bodies without changing any
  // velocity, so the totals are taken in between.
  out.after = totals_of(bodies);
  solver.correct_positions(bodies, out.contacts);
  out.report.time_of_impact = out.time_of_impact;
  return out;
}

void fill_response(const ResolveContacts::Request& request, const std::vector<Body>& bodies,
                   const Resolution& resolution, const Totals& before, ResolveContacts::Response& response)
{
  response.bodies.reserve(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    response.bodies.push_back(body_to_msg(bodies[i], request.bodies[i].id));
    response.bodies.back().material = request.bodies[i].material;
  }
  response.contacts.reserve(resolution.contacts.size());
  for (std::size_t k = 0; k < resolution.contacts.size(); ++k)
  {
    const Contact& contact = resolution.contacts[k];
    const ContactImpulse impulse = k < resolution.impulses.size() ? resolution.impulses[k] : ContactImpulse{};
    response.contacts.push_back(
        contact_to_msg(contact, impulse, request.bodies[contact.a].id, request.bodies[contact.b].id));
  }
  response.report = solver_report_to_msg(resolution.report, before, resolution.after);
  response.time_of_impact = resolution.time_of_impact;
  response.success = true;
  response.message = "resolved " + std::to_string(resolution.contacts.size()) + " contact points";
}

void fail(ResolveContacts::Response& response, const std::string& message)
{
  response = ResolveContacts::Response();
  response.success = false;
  response.message = message;
}

}  // namespace

void resolve_contacts(const ResolveContacts::Request& request, const SolverSettings& node_settings,
                      std::size_t max_bodies, ResolveContacts::Response& response)
{
  try
  {
    const SolverSettings& settings = request.settings.use_node_settings ? node_settings : request.settings;
    const ContactSolver solver = solver_from_msg(settings);
    std::vector<Body> bodies = bodies_from_msgs(request.bodies, max_bodies);
    const Totals before = totals_of(bodies);
    const Resolution resolution = resolve(solver, settings.use_time_of_impact, bodies);
    fill_response(request, bodies, resolution, before, response);
  }
  catch (const InvalidRequest& e)
  {
    fail(response, e.what());
  }
  catch (const std::exception& e)
  {
    // Validation should have caught everything the core refuses; whatever
    // slips through still must not take the node down.
    fail(response, std::string("resolve failed: ") + e.what());
  }
}

}  // namespace ros_interface
}  // namespace collision2d
