// Helpers shared by the solver tests: hand-made contacts and the physical
// quantities the tests recompute from the bodies the solver returns.
#pragma once

#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/vec2.h"

namespace collision2d
{
namespace test
{
inline Contact make_contact(std::size_t a, std::size_t b, Vec2 normal, Vec2 point, double penetration)
{
  Contact c;
  c.a = a;
  c.b = b;
  c.normal = normal;
  c.point = point;
  c.penetration = penetration;
  return c;
}

/// Velocity of b relative to a at the contact point.
inline Vec2 relative_velocity(const std::vector<Body>& bodies, const Contact& c)
{
  return bodies[c.b].velocity_at(c.point) - bodies[c.a].velocity_at(c.point);
}

inline double normal_speed(const std::vector<Body>& bodies, const Contact& c)
{
  return dot(relative_velocity(bodies, c), c.normal);
}

inline double tangent_speed(const std::vector<Body>& bodies, const Contact& c)
{
  return dot(relative_velocity(bodies, c), perp(c.normal));
}

inline Vec2 total_momentum(const std::vector<Body>& bodies)
{
  Vec2 p;
  for (const Body& body : bodies)
    p += body.momentum();
  return p;
}

inline double total_angular_momentum(const std::vector<Body>& bodies)
{
  double l = 0.0;
  for (const Body& body : bodies)
    l += body.angular_momentum();
  return l;
}

inline double total_kinetic_energy(const std::vector<Body>& bodies)
{
  double e = 0.0;
  for (const Body& body : bodies)
    e += body.kinetic_energy();
  return e;
}

/// Newton target of a contact from the velocities before the solve.
inline double newton_target(const std::vector<Body>& before, const Contact& c, double e)
{
  const double approach = normal_speed(before, c);
  return approach < 0.0 ? -e * approach : 0.0;
}

}  // namespace test
}  // namespace collision2d
