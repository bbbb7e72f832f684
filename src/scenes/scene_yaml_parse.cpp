// Reading YAML scenes: top level, settings, materials and explicit bodies.
// `generate:` entries are expanded in scene_yaml_generate.cpp.
#include <cmath>
#include <stdexcept>

#include "collision2d/scenes/scene_file.h"
#include "collision2d/scenes/scene_parts.h"
#include "scene_yaml_internal.h"

namespace collision2d
{
namespace scenes
{
namespace detail
{
namespace
{
/// Static and kinematic bodies never use their mass; Body needs a positive one.
constexpr double kDefaultMass = 1.0;  // kg

BodyType read_body_type(FieldReader& fields)
{
  const std::string text = fields.text("type", "dynamic");
  if (text == "dynamic")
  {
    return BodyType::Dynamic;
  }
  if (text == "static")
  {
    return BodyType::Static;
  }
  if (text == "kinematic")
  {
    return BodyType::Kinematic;
  }
  fields.fail_at("type", "must be dynamic, static or kinematic (got '" + text + "')");
}

std::vector<Vec2> read_vertices(FieldReader& fields)
{
  fields.require("vertices");
  const YAML::Node node = fields.node("vertices");
  if (!node.IsSequence())
  {
    fields.fail_at("vertices", "must be a list of [x, y] pairs");
  }
  std::vector<Vec2> vertices;
  for (std::size_t i = 0; i < node.size(); ++i)
  {
    vertices.push_back(read_vec2(node[i], item_path(fields.path("vertices"), i), fields.source()));
  }
  return vertices;
}

/// The shape-specific fields; fields of other shapes stay unknown, so
/// `radius` on a box is reported.
Body read_shape(FieldReader& f, double mass, Vec2 position, double theta, Vec2 velocity, double omega)
{
  f.require("shape");
  const std::string shape = f.text("shape", "");
  if (shape == "disk")
  {
    f.require("radius");
    Body body(mass, f.positive("radius", 1.0), position, velocity, omega);
    body.set_theta(theta);
    return body;
  }
  if (shape == "box")
  {
    f.require("size");
    const Vec2 size = f.vec2("size", Vec2{});
    if (!(size.x > 0.0 && size.y > 0.0))
    {
      f.fail_at("size", "width and height must be positive");
    }
    return make_box(mass, size.x, size.y, position, theta, velocity, omega);
  }
  if (shape == "polygon")
  {
    return Body(mass, read_vertices(f), position, velocity, theta, omega);
  }
  f.fail_at("shape", "must be disk, polygon or box (got '" + shape + "')");
}

SceneBody read_body(const YAML::Node& node, const std::string& path, const ParseContext& context)
{
  FieldReader f(node, path, context.source);
  const std::string name = f.text("name", "");
  const BodyType type = read_body_type(f);
  if (type == BodyType::Dynamic)
  {
    f.require("mass");
  }
  const double mass = f.positive("mass", kDefaultMass);
  const Vec2 position = f.vec2("position", Vec2{});
  const double theta = f.number("theta", 0.0);
  const Vec2 velocity = f.vec2("velocity", Vec2{});
  const double omega = f.number("omega", 0.0);
  if (type == BodyType::Static && (velocity != Vec2{} || omega != 0.0))
  {
    f.fail_at(f.has("velocity") ? "velocity" : "omega", "a static body cannot move (use type: kinematic)");
  }
  const Material material = read_material(f, "material", Material{}, context);
  try
  {
    Body body = read_shape(f, mass, position, theta, velocity, omega);
    body.set_type(type);
    f.finish();
    return SceneBody{body, material, name};
  }
  catch (const std::invalid_argument& error)
  {
    fail(context.source, f.line(), path, error.what());
  }
}

void read_materials(const YAML::Node& node, ParseContext& context)
{
  FieldReader table(node, "materials", context.source);
  for (const auto& item : node)
  {
    const std::string name = item.first.Scalar();
    context.materials[name] = read_material_map(item.second, table.path(name), context.source);
    table.node(name);
  }
  table.finish();
}

template <typename Visit>
void for_each_item(const YAML::Node& list, const std::string& path, const std::string& source, Visit visit)
{
  if (!list.IsSequence())
  {
    fail(source, line_of(list), path, "must be a list ('- ...' items)");
  }
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    visit(list[i], item_path(path, i));
  }
}

Scene read_scene(const YAML::Node& root, const std::string& source, const SceneReading& reading)
{
  if (root.IsNull())
  {
    fail(source, 0, "", "empty scene file");
  }
  FieldReader top(root, "", source);
  Scene scene;
  ParseContext context{source, {}};
  scene.name = top.text("name", "");
  scene.settings.gravity = top.vec2("gravity", Vec2{0.0, kGravity});
  if (top.has("settings"))
  {
    scene.settings = read_settings(top.node("settings"), source, reading, scene.settings);
  }
  if (top.has("materials"))
  {
    read_materials(top.node("materials"), context);
  }
  if (top.has("generate"))
  {
    for_each_item(top.node("generate"), "generate", source, [&](const YAML::Node& item, const std::string& path) {
      expand_generator(item, path, context, scene);
    });
  }
  if (top.has("bodies"))
  {
    for_each_item(top.node("bodies"), "bodies", source, [&](const YAML::Node& item, const std::string& path) {
      if (scene.bodies.size() >= static_cast<std::size_t>(kMaxSceneBodies))
      {
        fail(source, line_of(item), path, "more than " + std::to_string(kMaxSceneBodies) + " bodies");
      }
      scene.bodies.push_back(read_body(item, path, context));
    });
  }
  top.finish();
  return scene;
}

}  // namespace

Material read_material_map(const YAML::Node& node, const std::string& path, const std::string& source)
{
  FieldReader f(node, path, source);
  Material m;
  m.restitution = f.non_negative("restitution", m.restitution);
  if (m.restitution > 1.0)
  {
    f.fail_at("restitution", "must be in [0, 1]");
  }
  m.static_friction = f.non_negative("static_friction", m.static_friction);
  m.kinetic_friction = f.non_negative("kinetic_friction", m.kinetic_friction);
  f.finish();
  return m;
}

Material read_material(FieldReader& fields, const std::string& key, const Material& fallback,
                       const ParseContext& context)
{
  const YAML::Node node = fields.node(key);
  if (!node)
  {
    return fallback;
  }
  if (node.IsMap())
  {
    return read_material_map(node, fields.path(key), context.source);
  }
  const std::string name = fields.text(key, "");
  const auto found = context.materials.find(name);
  if (found == context.materials.end())
  {
    fields.fail_at(key, "unknown material '" + name + "' (define it under materials:)");
  }
  return found->second;
}

}  // namespace detail

Scene parse_scene_yaml(const std::string& text, const std::string& source_name)
{
  return parse_scene_yaml(text, source_name, SceneReading{});
}

Scene parse_scene_yaml(const std::string& text, const std::string& source_name, const SceneReading& reading)
{
  YAML::Node root;
  try
  {
    root = YAML::Load(text);
  }
  catch (const YAML::Exception& error)
  {
    detail::fail(source_name, error.mark.line + 1, "", "YAML syntax: " + error.msg);
  }
  return detail::read_scene(root, source_name, reading);
}

}  // namespace scenes
}  // namespace collision2d
