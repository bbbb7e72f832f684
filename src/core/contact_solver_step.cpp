// Continuous collision for ContactSolver: the earliest time of impact over all
// pairs of a scene, and a step that advances to it and resolves there.
#include <algorithm>
#include <vector>

#include "collision2d/broad_phase.h"
#include "collision2d/contact_solver.h"
#include "collision2d/time_of_impact.h"
#include "collision2d/touch_tolerance.h"
#include "contact_rows.h"

namespace collision2d
{
namespace
{
/// A pair of bodies that contacts cannot push (static or kinematic) has no
/// impact to resolve, so it never limits the step.
bool either_dynamic(const Body& a, const Body& b)
{
  return a.type() == BodyType::Dynamic || b.type() == BodyType::Dynamic;
}

}  // namespace

double ContactSolver::time_of_impact(const std::vector<Body>& bodies)
{
  detail::validate_bodies(bodies);
  // Boxes swept over the whole step: a pair that meets anywhere in [0, 1]
  // has overlapping swept boxes, however thin or fast the bodies are.
  std::vector<Aabb> swept;
  swept.reserve(bodies.size());
  for (const Body& body : bodies)
  {
    swept.push_back(body.aabb().swept(body.velocity()));
  }
  std::vector<BodyPair> pairs;
  BroadPhase broad_phase;
  broad_phase.find_pairs(swept, pairs);

  double earliest = 1.0;
  for (const BodyPair& pair : pairs)
  {
    const Body& a = bodies[pair.first];
    const Body& b = bodies[pair.second];
    if (!either_dynamic(a, b))
    {
      continue;
    }
    earliest = std::min(earliest, collision2d::time_of_impact(a, a.velocity(), b, b.velocity()));
    if (earliest == 0.0)
    {
      break;
    }
  }
  return earliest;
}

SolveReport ContactSolver::step(std::vector<Body>& bodies) const
{
  Resolution out;
  return step(bodies, out);
}

SolveReport ContactSolver::step(std::vector<Body>& bodies, Resolution& out) const
{
  return detail::all_or_nothing(bodies, [&] {
    const double t = time_of_impact(bodies);
    for (Body& body : bodies)
    {
      body.set_position(body.position() + t * body.velocity());
    }
    // The impacting pair touches exactly at t, which strict detection would
    // miss: count pairs within the touch tolerance as contacts.
    SolveReport report = resolve_here(bodies, kRelativeTouchTolerance, &out);
    report.time_of_impact = t;
    out.report.time_of_impact = t;
    return report;
  });
}

}  // namespace collision2d
