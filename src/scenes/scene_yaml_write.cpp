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

namespace collision2d
{
namespace scenes
{
namespace
{
constexpr int kShortestTried = 15;  // digits always exact for decimal literals

std::string format_number(double value)
{
  for (int digits = kShortestTried; digits <= std::numeric_limits<double>::max_digits10; ++digits)
  {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(digits);
    out << value;
    std::istringstream back(out.str());
    back.imbue(std::locale::classic());
    double parsed = 0.0;
    back >> parsed;
    if (parsed == value || digits == std::numeric_limits<double>::max_digits10)
    {
      return out.str();
    }
  }
  return "";  // unreachable: the loop returns at max_digits10
}

std::string pair(Vec2 v)
{
  return "[" + format_number(v.x) + ", " + format_number(v.y) + "]";
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

const char* toggle_name(Toggle toggle)
{
  switch (toggle)
  {
    case Toggle::On:
      return "on";
    case Toggle::Off:
      return "off";
    case Toggle::Auto:
    default:
      return "auto";
  }
}

const char* solver_mode_name(SolverMode mode)
{
  return mode == SolverMode::Exact ? "exact" : "iterative";
}

const char* flag_name(bool flag) { return flag ? "true" : "false"; }

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

void write_settings(std::ostream& out, const WorldSettings& s)
{
  out << "gravity: " << pair(s.gravity) << "\n";
  out << "settings:\n";
  out << "  dt: " << format_number(s.dt) << "\n";
  out << "  substeps: " << s.substeps << "\n";
  out << "  velocity_iterations: " << s.velocity_iterations << "\n";
  out << "  position_iterations: " << s.position_iterations << "\n";
  out << "  position_block: " << flag_name(s.position_block) << "\n";
  out << "  slop: " << format_number(s.slop) << "\n";
  out << "  compliance: " << format_number(s.compliance) << "\n";
  out << "  restitution_threshold: " << format_number(s.restitution_threshold) << "\n";
  out << "  rotation: " << toggle_name(s.rotation) << "\n";
  out << "  friction: " << toggle_name(s.friction) << "\n";
  out << "  restitution: " << toggle_name(s.restitution) << "\n";
  out << "  position_correction: " << toggle_name(s.position_correction) << "\n";
  out << "  time_of_impact: " << toggle_name(s.time_of_impact) << "\n";
  out << "  warm_starting: " << toggle_name(s.warm_starting) << "\n";
  out << "  sleeping: " << toggle_name(s.sleeping) << "\n";
  out << "  warm_start_factor: " << format_number(s.warm_start_factor) << "\n";
  out << "  warm_start_before_integration: " << flag_name(s.warm_start_before_integration) << "\n";
  out << "  toi_displacement_fraction: " << format_number(s.toi_displacement_fraction) << "\n";
  out << "  sleep_linear_speed: " << format_number(s.sleep_linear_speed) << "\n";
  out << "  sleep_angular_speed: " << format_number(s.sleep_angular_speed) << "\n";
  out << "  sleep_time: " << format_number(s.sleep_time) << "\n";
  out << "  sleep_auto_min_bodies: " << s.sleep_auto_min_bodies << "\n";
  out << "  solver_mode: " << solver_mode_name(s.solver_mode) << "\n";
  out << "  exact_position_correction: " << flag_name(s.exact_position_correction) << "\n";
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
    out << "shape: disk, radius: " << format_number(body.radius());
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
  out << ", mass: " << format_number(b.mass()) << ", position: " << pair(b.position())
      << ", theta: " << format_number(b.theta()) << ", velocity: " << pair(b.velocity())
      << ", omega: " << format_number(b.omega()) << ", material: m" << material << "}\n";
}

}  // namespace

std::string scene_to_yaml(const Scene& scene)
{
  std::ostringstream out;
  out << "# Written by collision2d: every body listed explicitly.\n";
  out << "name: " << quoted(scene.name) << "\n";
  write_settings(out, scene.settings);
  const std::vector<Material> materials = distinct_materials(scene);
  out << "materials:" << (materials.empty() ? " {}" : "") << "\n";
  for (std::size_t i = 0; i < materials.size(); ++i)
  {
    out << "  m" << i << ": {restitution: " << format_number(materials[i].restitution)
        << ", static_friction: " << format_number(materials[i].static_friction)
        << ", kinetic_friction: " << format_number(materials[i].kinetic_friction) << "}\n";
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
