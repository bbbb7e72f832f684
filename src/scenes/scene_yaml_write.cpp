// Writing scenes as YAML that reads back exactly: every body is listed
// explicitly and each double is written with the fewest digits (at most
// max_digits10) that parse back to the same value. One caveat is Body's, not
// the format's: a general polygon is recentred on its centroid again when
// read, and a centroid computed in floating point can move its vertices by
// an ulp; boxes and disks come back bit for bit.
#include <cstdlib>
#include <limits>
#include <locale>
#include <sstream>
#include <string>
#include <vector>

#include "collision2d/scenes/scene_file.h"
#include "collision2d/scenes/scene_parts.h"
#include "scene_yaml_internal.h"

namespace collision2d
{
namespace scenes
{
namespace
{
std::string pair(Vec2 v)
{
  return "[" + number_text(v.x) + ", " + number_text(v.y) + "]";
}

/// Double-quoted YAML string, so any name survives.
std::string quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (c == '\n')
    {
      out += "\\n";
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

const char* type_name(BodyType type)
{
  switch (type)
  {
    case BodyType::Static:
      return "static";
    case BodyType::Kinematic:
      return "kinematic";
    case BodyType::Dynamic:
    default:
      return "dynamic";
  }
}

bool same_material(const Material& a, const Material& b)
{
  return a.restitution == b.restitution && a.static_friction == b.static_friction &&
         a.kinetic_friction == b.kinetic_friction;
}

/// Distinct materials in order of first use; bodies refer to them by index.
std::vector<Material> distinct_materials(const Scene& scene)
{
  std::vector<Material> table;
  for (const SceneBody& entry : scene.bodies)
  {
    bool found = false;
    for (const Material& m : table)
    {
      found = found || same_material(m, entry.material);
    }
    if (!found)
    {
      table.push_back(entry.material);
    }
  }
  return table;
}

std::size_t material_index(const std::vector<Material>& table, const Material& material)
{
  std::size_t i = 0;
  while (i < table.size() && !same_material(table[i], material))
  {
    ++i;
  }
  return i;
}

/// A centred, axis-aligned rectangle that box_outline reproduces bit for bit.
bool is_plain_box(const Body& body)
{
  if (body.shape() != Shape::Polygon || body.vertex_count() != 4)
  {
    return false;
  }
  const Vec2 corner = body.local_vertices()[2];
  return body.local_vertices() == box_outline(2.0 * corner.x, 2.0 * corner.y);
}

void write_shape(std::ostream& out, const Body& body)
{
  if (body.shape() == Shape::Disk)
  {
    out << "shape: disk, radius: " << number_text(body.radius());
    return;
  }
  if (is_plain_box(body))
  {
    out << "shape: box, size: " << pair(2.0 * body.local_vertices()[2]);
    return;
  }
  out << "shape: polygon, vertices: [";
  for (std::size_t i = 0; i < body.vertex_count(); ++i)
  {
    out << (i == 0 ? "" : ", ") << pair(body.local_vertices()[i]);
  }
  out << "]";
}

void write_body(std::ostream& out, const SceneBody& entry, std::size_t material)
{
  const Body& b = entry.body;
  out << "  - {name: " << quoted(entry.name) << ", type: " << type_name(b.type()) << ", ";
  write_shape(out, b);
  out << ", mass: " << number_text(b.mass()) << ", position: " << pair(b.position())
      << ", theta: " << number_text(b.theta()) << ", velocity: " << pair(b.velocity())
      << ", omega: " << number_text(b.omega()) << ", material: m" << material << "}\n";
}

}  // namespace

std::string scene_to_yaml(const Scene& scene)
{
  std::ostringstream out;
  out << "# Written by collision2d: every body listed explicitly.\n";
  out << "name: " << quoted(scene.name) << "\n";
  detail::write_settings(out, scene.settings);
  const std::vector<Material> materials = distinct_materials(scene);
  out << "materials:" << (materials.empty() ? " {}" : "") << "\n";
  for (std::size_t i = 0; i < materials.size(); ++i)
  {
    out << "  m" << i << ": {restitution: " << number_text(materials[i].restitution)
        << ", static_friction: " << number_text(materials[i].static_friction)
        << ", kinetic_friction: " << number_text(materials[i].kinetic_friction) << "}\n";
  }
  out << "bodies:" << (scene.bodies.empty() ? " []" : "") << "\n";
  for (const SceneBody& entry : scene.bodies)
  {
    write_body(out, entry, material_index(materials, entry.material));
  }
  return out.str();
}

}  // namespace scenes
}  // namespace collision2d
