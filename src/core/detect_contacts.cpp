// ContactSolver::detect_contacts: bounding boxes,
// sort-and-sweep broad phase, then collide() on every candidate pair.
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision2d/broad_phase.h"
#include "collision2d/collide.h"
#include "collision2d/contact_solver.h"
#include "contact_rows.h"

namespace collision2d
{
namespace
{
bool both_non_dynamic(const Body& a, const Body& b)
{
  return a.type() != BodyType::Dynamic && b.type() != BodyType::Dynamic;
}

/// `relative_tolerance` scales with the pair's size: a pair counts when its gap
/// is at most relative_tolerance * (radius_a + radius_b). Each box is inflated
/// by its own share, so the two boxes of such a pair still overlap.
std::vector<Contact> detect(const std::vector<Body>& bodies, double relative_tolerance)
{
  detail::validate_bodies(bodies);
  std::vector<Aabb> boxes;
  boxes.reserve(bodies.size());
  for (const Body& body : bodies)
  {
    boxes.push_back(body.aabb().inflated(relative_tolerance * body.radius()));
  }
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  broad_phase.find_pairs(boxes, pairs);

  std::vector<Contact> contacts;
  contacts.reserve(pairs.size());
  Manifold manifold;
  for (const BodyPair& pair : pairs)
  {
    const Body& a = bodies[pair.first];
    const Body& b = bodies[pair.second];
    if (both_non_dynamic(a, b))
    {
      continue;  // neither can respond, so the contact would carry nothing
    }
    if (!collide(a, b, manifold, relative_tolerance * (a.radius() + b.radius())))
    {
      continue;
    }
    for (int k = 0; k < manifold.count; ++k)
    {
      const ManifoldPoint& p = manifold.points[k];
      contacts.push_back({pair.first, pair.second, manifold.normal, p.point, p.penetration, p.feature});
    }
  }
  return contacts;
}

}  // namespace

std::vector<Contact> ContactSolver::detect_contacts(const std::vector<Body>& bodies)
{
  return detect(bodies, 0.0);
}

std::vector<Contact> ContactSolver::detect_contacts(const std::vector<Body>& bodies, double touch_tolerance)
{
  if (!(std::isfinite(touch_tolerance) && touch_tolerance >= 0.0))
  {
    throw std::invalid_argument("detect_contacts: touch_tolerance must be finite and >= 0 (got " +
                                std::to_string(touch_tolerance) + ")");
  }
  return detect(bodies, touch_tolerance);
}

}  // namespace collision2d
