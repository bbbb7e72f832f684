// Helpers shared by the World tests: measurements taken while stepping, and
// bit-for-bit comparisons of worlds.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "collision2d/scene.h"
#include "collision2d/world.h"

namespace collision2d
{
namespace test
{
/// Steps `world` one frame at a time until body `id`, having bounced (moved
/// up), starts to fall again, and returns the highest centre height it reached
/// on that first rebound; -infinity if it did not bounce within max_frames.
inline double first_rebound_apex(World& world, BodyId id, int max_frames)
{
  double apex = -std::numeric_limits<double>::infinity();
  bool bounced = false;
  for (int f = 0; f < max_frames; ++f)
  {
    world.step();
    const Body& b = world.body(id);
    bounced = bounced || b.velocity().y > 0.0;
    if (bounced)
    {
      apex = std::max(apex, b.position().y);
      if (b.velocity().y < 0.0)
      {
        break;  // past the first apex
      }
    }
  }
  return apex;
}

/// The world's kinetic energy (J), every body's summed.
inline double kinetic_energy(const World& world)
{
  double e = 0.0;
  for (BodyId id : world.body_ids())
  {
    e += world.body(id).kinetic_energy();
  }
  return e;
}

/// Kinetic plus potential energy of the dynamic bodies (J), with gravity -g along y.
inline double mechanical_energy(const World& world, double g)
{
  double energy = kinetic_energy(world);
  for (BodyId id : world.body_ids())
  {
    const Body& b = world.body(id);
    energy += b.type() == BodyType::Dynamic ? b.mass() * g * b.position().y : 0.0;
  }
  return energy;
}

/// Every body's position, in body_ids() order.
inline std::vector<Vec2> positions(const World& world)
{
  std::vector<Vec2> out;
  for (BodyId id : world.body_ids())
  {
    out.push_back(world.body(id).position());
  }
  return out;
}

/// Largest displacement of a dynamic body between two positions() of the
/// same bodies (m).
inline double largest_move(const World& world, const std::vector<Vec2>& from, const std::vector<Vec2>& to)
{
  const std::vector<BodyId> ids = world.body_ids();
  double worst = 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    if (world.body(ids[i]).type() == BodyType::Dynamic)
    {
      worst = std::max(worst, length(to[i] - from[i]));
    }
  }
  return worst;
}

inline bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

inline bool same_bits(Vec2 x, Vec2 y) { return same_bits(x.x, y.x) && same_bits(x.y, y.y); }

/// Every field of every contact, bit for bit, in the same order.
inline bool same_contacts(const std::vector<WorldContact>& x, const std::vector<WorldContact>& y)
{
  if (x.size() != y.size())
  {
    return false;
  }
  for (std::size_t k = 0; k < x.size(); ++k)
  {
    const WorldContact& p = x[k];
    const WorldContact& q = y[k];
    if (p.a != q.a || p.b != q.b || p.contact.feature != q.contact.feature || p.sliding != q.sliding ||
        !same_bits(p.contact.normal, q.contact.normal) || !same_bits(p.contact.point, q.contact.point) ||
        !same_bits(p.contact.penetration, q.contact.penetration) || !same_bits(p.impulse.normal, q.impulse.normal) ||
        !same_bits(p.impulse.tangent, q.impulse.tangent) || !same_bits(p.anchor_drift, q.anchor_drift))
    {
      return false;
    }
  }
  return true;
}

/// Every bit of every body's motion, sleep flag and contact impulse, and the clock.
inline std::uint64_t state_hash(const World& world)
{
  std::uint64_t h = 14695981039346656037ULL;
  auto add = [&h](double value) {
    unsigned char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    for (unsigned char byte : bytes)
    {
      h = (h ^ byte) * 1099511628211ULL;
    }
  };
  for (BodyId id : world.body_ids())
  {
    const Body& b = world.body(id);
    add(b.position().x);
    add(b.position().y);
    add(b.theta());
    add(b.velocity().x);
    add(b.velocity().y);
    add(b.omega());
    add(world.is_sleeping(id) ? 1.0 : 0.0);
  }
  for (const WorldContact& c : world.contacts())
  {
    add(c.impulse.normal);
    add(c.impulse.tangent);
  }
  add(world.time());
  return h;
}

/// What a snapshot keeps (scene, ids, clock, step state), and a world rebuilt from it.
inline World rebuilt(const World& world)
{
  const Scene scene = to_scene(world);
  World copy(scene.settings);
  const std::vector<BodyId> ids = world.body_ids();
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    copy.add_body(ids[i], scene.bodies[i].body, scene.bodies[i].material);
  }
  copy.set_next_id(world.next_id());
  copy.set_clock(world.time(), world.frame_count());
  copy.set_step_state(world.step_state());
  return copy;
}

}  // namespace test
}  // namespace collision2d
