// ResolveContacts: convert, run the core's resolve (or step, with the
// time-of-impact sweep), convert back.
#include "collision2d/ros/resolve_contacts.h"

#include <string>
#include <vector>

#include "collision2d/contact_solver.h"
#include "collision2d/ros/conversions.h"
#include "collision2d/ros/reports.h"
#include "collision2d/ros/settings_conversions.h"
#include "service_reply.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
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
  // Angular momentum about the origin is conserved by the solve at the
  // positions it solved at; correction then moves bodies without changing any
  // velocity, so the totals after are taken in between.
  response.report = solver_report_to_msg(resolution.report, before, totals_of(resolution.after_solve));
  response.time_of_impact = resolution.report.time_of_impact;
  response.success = true;
  response.message = "resolved " + std::to_string(resolution.contacts.size()) + " contact points";
}

}  // namespace

void resolve_contacts(const ResolveContacts::Request& request, const SolverSettings& node_settings,
                      std::size_t max_bodies, ResolveContacts::Response& response)
{
  // A refused request is answered and logged as the world services' are;
  // whatever slips past validation still must not take the node down.
  serve(response, "resolve_contacts", [&] {
    const SolverSettings& settings = request.settings.use_node_settings ? node_settings : request.settings;
    const ContactSolver solver = solver_from_msg(settings);
    std::vector<Body> bodies = bodies_from_msgs(request.bodies, max_bodies);
    const Totals before = totals_of(bodies);
    Resolution resolution;
    if (settings.use_time_of_impact)
    {
      solver.step(bodies, resolution);
    }
    else
    {
      solver.resolve(bodies, resolution);
      resolution.report.time_of_impact = 0.0;  // no sweep: the bodies did not move (the message says 0)
    }
    fill_response(request, bodies, resolution, before, response);
  });
}

}  // namespace ros_interface
}  // namespace collision2d
