// The Box2D v3 comparison stacks (see stack_scenes.h), built from the shared
// scene parts so the bodies are laid out exactly as the standard scenes lay
// theirs; only the sizes, material, ground and settings differ.
#include "stack_scenes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "collision2d/scenes/scene_parts.h"

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kGravity = -10.0;         // m/s^2, the comparison's round value
constexpr double kFrame = 1.0 / 60.0;      // s
constexpr int kSubsteps = 4;
constexpr double kFriction = 0.6;          // static and kinetic
constexpr double kBox = 1.0;               // m, edge of every box
constexpr double kBoxMass = 1.0;           // kg
constexpr double kGroundWidth = 200.0;     // m: wider than the base-100 pyramid
constexpr double kGroundThickness = 1.0;   // m
constexpr double kRunSeconds = 10.0;       // s: drift is measured from 1 s to here
constexpr int kColumnBoxes = 20;
constexpr double kGroundMargin = 1.5;      // ground width / widest row of a throughput scene

const char* const kPyramidPrefix = "stack_pyramid_";
const char* const kColumnName = "stack_column_20";
// The same column with its top box this far off centre (m, +x): the exact
// column stays symmetric to the last bit, so it cannot show whether a column
// tips once anything breaks the symmetry.
const char* const kNudgedColumnName = "stack_column_20_nudged";
constexpr double kColumnNudge = 1e-6;

Material stack_material()
{
  return Material{0.0, kFriction, kFriction};
}

Scene stack_base(const std::string& name, double ground_width = kGroundWidth)
{
  Scene scene;
  scene.name = name;
  scene.settings.gravity = Vec2{0.0, kGravity};
  scene.settings.dt = kFrame;
  scene.settings.substeps = kSubsteps;
  scene.settings.sleeping = Toggle::Off;
  scenes::GroundParams ground;
  ground.width = ground_width;
  ground.thickness = kGroundThickness;
  ground.top = 0.0;
  ground.material = stack_material();
  scenes::add_ground(scene, ground);
  return scene;
}

}  // namespace

std::vector<std::string> stack_scene_names()
{
  return {"stack_pyramid_20", kColumnName, kNudgedColumnName, "stack_pyramid_60", "stack_pyramid_100"};
}

bool is_stack_scene(const std::string& name)
{
  for (const std::string& n : stack_scene_names())
  {
    if (n == name)
    {
      return true;
    }
  }
  return false;
}

BenchScene make_stack_scene(const std::string& name)
{
  if (!is_stack_scene(name))
  {
    throw std::invalid_argument("unknown stack scene '" + name + "'");
  }
  Scene scene = stack_base(name);
  if (name == kColumnName || name == kNudgedColumnName)
  {
    scenes::ColumnParams column;
    column.count = kColumnBoxes;
    column.box = kBox;
    column.mass = kBoxMass;
    column.at = Vec2{0.0, 0.5 * kBox};
    column.material = stack_material();
    scenes::add_column(scene, column);
    if (name == kNudgedColumnName)
    {
      Body& top = scene.bodies.back().body;
      top.set_position(top.position() + Vec2{kColumnNudge, 0.0});
    }
  }
  else
  {
    scenes::PyramidParams pyramid;
    pyramid.base = std::stoi(name.substr(std::string(kPyramidPrefix).size()));
    pyramid.box = kBox;
    pyramid.mass = kBoxMass;
    pyramid.at = Vec2{0.0, 0.5 * kBox};
    pyramid.material = stack_material();
    scenes::add_pyramid(scene, pyramid);
  }
  return BenchScene{name, scene, SceneKind::Resting, kRunSeconds};
}

Scene make_throughput_scene(const std::string& kind, long bodies)
{
  if (bodies < 1)
  {
    throw std::invalid_argument("throughput scene: bodies must be at least 1");
  }
  if (kind == "pyramid")
  {
    // base (base + 1) / 2 <= bodies
    const int base = static_cast<int>((std::sqrt(8.0 * static_cast<double>(bodies) + 1.0) - 1.0) / 2.0);
    Scene scene = stack_base("pyramid_" + std::to_string(bodies), std::max(kGroundWidth, kGroundMargin * base));
    scenes::PyramidParams pyramid;
    pyramid.base = std::max(1, base);
    pyramid.box = kBox;
    pyramid.mass = kBoxMass;
    pyramid.at = Vec2{0.0, 0.5 * kBox};
    pyramid.material = stack_material();
    scenes::add_pyramid(scene, pyramid);
    return scene;
  }
  if (kind == "rain")
  {
    scenes::RainParams rain;
    rain.count = static_cast<int>(bodies);
    rain.material = stack_material();
    const double width = scenes::rain_columns(rain) * rain.spacing;
    Scene scene = stack_base("rain_" + std::to_string(bodies), std::max(kGroundWidth, kGroundMargin * width));
    scenes::add_rain(scene, rain);
    return scene;
  }
  throw std::invalid_argument("unknown throughput scene '" + kind + "' (pyramid, rain)");
}

}  // namespace bench
}  // namespace collision2d
