// `generate:` entries of YAML scenes: each expands through the same building
// block (scene_parts.h) as the standard scene builders, with the fields of
// its *Params struct and the same defaults.
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

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
using Expander = void (*)(FieldReader&, const ParseContext&, Scene&);

void ground(FieldReader& f, const ParseContext& context, Scene& scene)
{
  GroundParams p;
  p.width = f.positive("width", p.width);
  p.thickness = f.positive("thickness", p.thickness);
  p.top = f.number("top", p.top);
  p.x = f.number("x", p.x);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_ground(scene, p);
}

void container(FieldReader& f, const ParseContext& context, Scene& scene)
{
  ContainerParams p;
  p.lower = f.vec2("lower", p.lower);
  p.upper = f.vec2("upper", p.upper);
  p.thickness = f.positive("thickness", p.thickness);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_container(scene, p);
}

/// Fails before building when `count` more bodies would pass the scene limit.
void reserve_bodies(const FieldReader& f, const std::string& key, const Scene& scene, long long count)
{
  if (static_cast<long long>(scene.bodies.size()) + count > kMaxSceneBodies)
  {
    f.fail_at(key, "would make the scene larger than " + std::to_string(kMaxSceneBodies) + " bodies");
  }
}

void pyramid(FieldReader& f, const ParseContext& context, Scene& scene)
{
  PyramidParams p;
  p.base = f.integer("base", p.base, 1);
  reserve_bodies(f, "base", scene, static_cast<long long>(p.base) * (p.base + 1) / 2);
  p.box = f.positive("box", p.box);
  p.mass = f.positive("mass", p.mass);
  p.at = f.vec2("at", p.at);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_pyramid(scene, p);
}

void column(FieldReader& f, const ParseContext& context, Scene& scene)
{
  ColumnParams p;
  p.count = f.integer("count", p.count, 1);
  reserve_bodies(f, "count", scene, p.count);
  p.box = f.positive("box", p.box);
  p.mass = f.positive("mass", p.mass);
  p.at = f.vec2("at", p.at);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_column(scene, p);
}

void cradle(FieldReader& f, const ParseContext& context, Scene& scene)
{
  CradleParams p;
  p.count = f.integer("count", p.count, 1);
  reserve_bodies(f, "count", scene, p.count);
  p.radius = f.positive("radius", p.radius);
  p.mass = f.positive("mass", p.mass);
  p.speed = f.number("speed", p.speed);
  p.at = f.vec2("at", p.at);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_cradle(scene, p);
}

void disk_row(FieldReader& f, const ParseContext& context, Scene& scene)
{
  DiskRowParams p;
  p.count = f.integer("count", p.count, 1);
  reserve_bodies(f, "count", scene, p.count);
  p.radius = f.positive("radius", p.radius);
  p.mass = f.positive("mass", p.mass);
  p.at = f.vec2("at", p.at);
  p.step = f.vec2("step", p.step);
  p.velocity = f.vec2("velocity", p.velocity);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_disk_row(scene, p);
}

void gas(FieldReader& f, const ParseContext& context, Scene& scene)
{
  GasParams p;
  p.count = f.integer("count", p.count, 1);
  reserve_bodies(f, "count", scene, p.count);
  p.seed = f.unsigned_integer("seed", p.seed);
  p.radius = f.positive("radius", p.radius);
  p.mass = f.positive("mass", p.mass);
  p.speed = f.non_negative("speed", p.speed);
  p.lower = f.vec2("lower", p.lower);
  p.upper = f.vec2("upper", p.upper);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_gas(scene, p);
}

void incline(FieldReader& f, const ParseContext& context, Scene& scene)
{
  InclineParams p;
  p.angle = f.number("angle", p.angle);
  p.length = f.positive("length", p.length);
  p.thickness = f.positive("thickness", p.thickness);
  p.box = f.positive("box", p.box);
  p.mass = f.positive("mass", p.mass);
  p.material = read_material(f, "material", p.material, context);
  f.finish();
  add_incline(scene, p);
}

const std::vector<std::pair<std::string, Expander>>& expanders()
{
  static const std::vector<std::pair<std::string, Expander>> kExpanders = {
      {"ground", ground}, {"container", container}, {"pyramid", pyramid}, {"column", column},
      {"cradle", cradle}, {"disk_row", disk_row},   {"gas", gas},         {"incline", incline},
  };
  return kExpanders;
}

std::string expander_names()
{
  std::string names;
  for (const auto& entry : expanders())
  {
    names += (names.empty() ? "" : ", ") + entry.first;
  }
  return names;
}

}  // namespace

void expand_generator(const YAML::Node& entry, const std::string& path, const ParseContext& context, Scene& scene)
{
  if (!entry.IsMap() || entry.size() != 1)
  {
    fail(context.source, line_of(entry), path, "must be one generator, e.g. '- pyramid: {base: 20}'");
  }
  const auto item = *entry.begin();
  const std::string kind = item.first.Scalar();
  const std::string kind_path = child_path(path, kind);
  for (const auto& expander : expanders())
  {
    if (expander.first != kind)
    {
      continue;
    }
    // `- ground:` with nothing after it means all defaults.
    const YAML::Node fields_node = item.second.IsNull() ? YAML::Node(YAML::NodeType::Map) : item.second;
    FieldReader fields(fields_node, kind_path, context.source);
    try
    {
      expander.second(fields, context, scene);
    }
    catch (const std::invalid_argument& error)
    {
      fail(context.source, line_of(item.first), kind_path, error.what());
    }
    return;
  }
  fail(context.source, line_of(item.first), kind_path, "unknown generator (expected one of: " + expander_names() + ")");
}

}  // namespace detail
}  // namespace scenes
}  // namespace collision2d
