// Material mapping and polygon inset for the peers (see peer_materials.h).
#include "peer_materials.h"

#include <cmath>

namespace collision2d
{
namespace bench
{
namespace
{
bool same_material(const Material& a, const Material& b)
{
  return a.restitution == b.restitution && a.static_friction == b.static_friction &&
         a.kinetic_friction == b.kinetic_friction;
}

}  // namespace

PeerCoefficients peer_coefficients(const Material& material, MixingRule rule)
{
  if (rule == MixingRule::Box2d)
  {
    return PeerCoefficients{material.static_friction, material.restitution};
  }
  return PeerCoefficients{std::sqrt(material.static_friction), std::sqrt(material.restitution)};
}

std::size_t mismatched_material_pairs(const Scene& scene)
{
  std::size_t count = 0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    for (std::size_t j = i + 1; j < scene.bodies.size(); ++j)
    {
      const bool both_fixed = scene.bodies[i].body.type() != BodyType::Dynamic &&
                              scene.bodies[j].body.type() != BodyType::Dynamic;
      if (!both_fixed && !same_material(scene.bodies[i].material, scene.bodies[j].material))
      {
        ++count;
      }
    }
  }
  return count;
}

std::vector<Vec2> inset_polygon(const std::vector<Vec2>& vertices, double distance)
{
  const std::size_t n = vertices.size();
  std::vector<Vec2> normals(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec2 edge = vertices[(i + 1) % n] - vertices[i];
    const double len = std::sqrt(length_sq(edge));
    normals[i] = Vec2{edge.y / len, -edge.x / len};  // outward for counter-clockwise
  }
  std::vector<Vec2> inset(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    // Vertex i joins face i-1 and face i; moving both faces in by d moves the
    // vertex along the bisector by d / cos(half angle) (the miter rule).
    const Vec2 a = normals[(i + n - 1) % n];
    const Vec2 b = normals[i];
    inset[i] = vertices[i] - (distance / (1.0 + dot(a, b))) * (a + b);
  }
  return inset;
}

}  // namespace bench
}  // namespace collision2d
