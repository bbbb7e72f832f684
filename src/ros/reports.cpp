// Report and world-state messages.
#include "collision2d/ros/reports.h"

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/settings_conversions.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
void add_body(Totals& totals, const Body& body)
{
  totals.kinetic_energy += body.kinetic_energy();
  totals.momentum += body.momentum();
  totals.angular_momentum += body.angular_momentum();
}

geometry_msgs::Vector3 vector_to_msg(Vec2 v)
{
  geometry_msgs::Vector3 msg;
  msg.x = v.x;
  msg.y = v.y;
  return msg;
}

/// The before/after fields are named alike in both report messages.
template <typename ReportMsg>
void fill_totals(ReportMsg& msg, const Totals& before, const Totals& after)
{
  msg.kinetic_energy_before = before.kinetic_energy;
  msg.kinetic_energy_after = after.kinetic_energy;
  msg.momentum_before = vector_to_msg(before.momentum);
  msg.momentum_after = vector_to_msg(after.momentum);
  msg.angular_momentum_before = before.angular_momentum;
  msg.angular_momentum_after = after.angular_momentum;
}

}  // namespace

Totals totals_of(const std::vector<Body>& bodies)
{
  Totals totals;
  for (const Body& body : bodies)
  {
    add_body(totals, body);
  }
  return totals;
}

Totals totals_of(const World& world)
{
  Totals totals;
  for (BodyId id : world.body_ids())
  {
    add_body(totals, world.body(id));
  }
  return totals;
}

SolverReport solver_report_to_msg(const SolveReport& report, const Totals& before, const Totals& after)
{
  SolverReport msg;
  msg.iterations = report.iterations;
  msg.max_residual = report.max_residual;
  msg.total_normal_impulse = report.total_normal_impulse;
  msg.converged = report.converged;
  msg.exact_fallback = report.exact_fallback;
  msg.contact_count = static_cast<std::uint32_t>(report.contact_count);
  msg.island_count = static_cast<std::uint32_t>(report.island_count);
  fill_totals(msg, before, after);
  return msg;
}

StepSummary step_summary_to_msg(const StepReport& report, const Totals& before, const Totals& after)
{
  StepSummary msg;
  msg.frames = report.frames;
  msg.substeps = report.substeps;
  msg.contact_count = static_cast<std::uint32_t>(report.contact_count);
  msg.max_penetration = report.max_penetration;
  msg.max_detected_penetration = report.max_detected_penetration;
  msg.velocity_residual = report.velocity_residual;
  msg.swept_bodies = static_cast<std::uint32_t>(report.swept_bodies);
  msg.toi_clamps = static_cast<std::uint32_t>(report.toi_clamps);
  msg.sleeping_bodies = static_cast<std::uint32_t>(report.sleeping_bodies);
  msg.exact_islands = static_cast<std::uint32_t>(report.exact_islands);
  msg.exact_fallbacks = static_cast<std::uint32_t>(report.exact_fallbacks);
  fill_totals(msg, before, after);
  msg.active = effects_to_msg(report.active);
  return msg;
}

WorldState world_state_to_msg(const World& world, const ActiveEffects& active, const std::string& scene)
{
  WorldState msg;
  msg.frame_count = world.frame_count();
  msg.sim_time = world.time();
  msg.scene = scene;
  const std::vector<BodyId> ids = world.body_ids();
  msg.bodies.reserve(ids.size());
  for (BodyId id : ids)
  {
    msg.bodies.push_back(body_to_msg(world.body(id), id, world.material(id)));
  }
  msg.contacts.reserve(world.contacts().size());
  for (const WorldContact& contact : world.contacts())
  {
    msg.contacts.push_back(contact_to_msg(contact.contact, contact.impulse, contact.a, contact.b));
  }
  msg.settings = world_settings_to_msg(world.settings());
  msg.active = effects_to_msg(active);
  return msg;
}

}  // namespace ros_interface
}  // namespace collision2d
