// The standard scenes, composed from the building blocks in scene_parts.h.
#include "collision2d/scenes/standard_scenes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "collision2d/scenes/scene_parts.h"

namespace collision2d
{
namespace scenes
{
namespace
{
constexpr double kBox = 1.0;       // edge of the standard box (m)
constexpr double kBoxMass = 1.0;   // kg

Scene empty_scene(const std::string& name, Vec2 gravity = Vec2{0.0, kGravity})
{
  Scene scene;
  scene.name = name;
  scene.settings.gravity = gravity;
  return scene;
}

/// Room for the widest standard stack (a base-20 pyramid) with margin.
GroundParams wide_ground()
{
  return GroundParams{};
}

}  // namespace

Scene resting_box()
{
  Scene scene = empty_scene("resting_box");
  add_ground(scene, wide_ground());
  scene.bodies.push_back(SceneBody{make_box(kBoxMass, kBox, kBox, {0.0, 0.5 * kBox}), rough_material(), "box"});
  return scene;
}

Scene pyramid(int base)
{
  Scene scene = empty_scene("pyramid");
  GroundParams ground = wide_ground();
  ground.width = std::max(ground.width, 3.0 * base * kBox);
  add_ground(scene, ground);
  PyramidParams params;
  params.base = base;
  add_pyramid(scene, params);
  return scene;
}

Scene column(int n)
{
  Scene scene = empty_scene("column");
  add_ground(scene, wide_ground());
  ColumnParams params;
  params.count = n;
  add_column(scene, params);
  return scene;
}

Scene newtons_cradle(int n)
{
  Scene scene = empty_scene("newtons_cradle", Vec2{0.0, 0.0});
  CradleParams params;
  params.count = n;
  add_cradle(scene, params);
  return scene;
}

Scene incline(double angle_rad, double mu_s, double mu_k)
{
  Scene scene = empty_scene("incline");
  InclineParams params;
  params.angle = angle_rad;
  params.material = Material{0.0, mu_s, mu_k};
  add_incline(scene, params);
  return scene;
}

Scene bouncing_disks(int n, double e)
{
  Scene scene = empty_scene("bouncing_disks");
  // Frictionless, and the floor shares e so the pair's min is e.
  const Material bouncy{e, 0.0, 0.0};
  GroundParams ground = wide_ground();
  ground.material = bouncy;
  add_ground(scene, ground);
  DiskRowParams disks;
  disks.count = n;
  disks.material = bouncy;
  add_disk_row(scene, disks);
  return scene;
}

Scene elastic_gas(int n, std::uint64_t seed)
{
  Scene scene = empty_scene("elastic_gas", Vec2{0.0, 0.0});
  GasParams gas;
  gas.count = n;
  gas.seed = seed;
  // A square box keeping the default density of one disk per 0.5 m cell.
  constexpr double kCell = 0.5;  // m
  const double side = kCell * std::ceil(std::sqrt(static_cast<double>(n)));
  gas.upper = Vec2{side, side};
  add_container(scene, ContainerParams{gas.lower, gas.upper, 1.0, elastic_material()});
  add_gas(scene, gas);
  return scene;
}

Scene bullet_wall(double speed)
{
  Scene scene = empty_scene("bullet_wall", Vec2{0.0, 0.0});
  constexpr double kWallThickness = 0.05;  // m: far less than one substep's travel
  constexpr double kWallHeight = 4.0;      // m
  constexpr double kWallX = 5.0;           // m
  constexpr double kBulletRadius = 0.05;   // m
  constexpr double kBulletMass = 0.1;      // kg
  scene.bodies.push_back(
      SceneBody{make_static_box(kWallThickness, kWallHeight, {kWallX, 0.0}), Material{}, "wall"});
  scene.bodies.push_back(
      SceneBody{Body(kBulletMass, kBulletRadius, {0.0, 0.0}, {speed, 0.0}), Material{}, "bullet"});
  return scene;
}

Scene heavy_on_light(double ratio)
{
  Scene scene = empty_scene("heavy_on_light");
  add_ground(scene, wide_ground());
  scene.bodies.push_back(SceneBody{make_box(kBoxMass, kBox, kBox, {0.0, 0.5 * kBox}), rough_material(), "light"});
  scene.bodies.push_back(
      SceneBody{make_box(ratio * kBoxMass, kBox, kBox, {0.0, 1.5 * kBox}), rough_material(), "heavy"});
  return scene;
}

Scene demo()
{
  Scene scene = empty_scene("demo");
  GroundParams ground = wide_ground();
  // Some bounce on the floor so the disks keep hopping (the pair takes the min).
  ground.material = Material{0.6, 0.6, 0.5};
  add_ground(scene, ground);
  PyramidParams pyramid_params;
  pyramid_params.base = 10;
  add_pyramid(scene, pyramid_params);
  DiskRowParams disks;
  disks.count = 4;
  disks.radius = 0.4;
  disks.at = Vec2{-14.0, 3.0};
  disks.step = Vec2{1.5, 1.5};
  disks.material = Material{0.8, 0.3, 0.2};
  add_disk_row(scene, disks);
  // A box thrown from the right, spinning, into the pyramid's flank.
  constexpr double kThrowSpeed = 12.0;  // m/s
  constexpr double kThrowSpin = 6.0;    // rad/s
  scene.bodies.push_back(SceneBody{make_box(2.0, 1.2, 0.8, {16.0, 6.0}, 0.0, {-kThrowSpeed, 2.0}, kThrowSpin),
                                   rough_material(), "projectile"});
  return scene;
}

namespace
{
using Builder = Scene (*)();

/// The registry: every standard scene with its default parameters, in the
/// order standard_scene_names() lists them.
const std::vector<std::pair<std::string, Builder>>& registry()
{
  static const std::vector<std::pair<std::string, Builder>> kBuilders = {
      {"resting_box", [] { return resting_box(); }},
      {"pyramid", [] { return pyramid(); }},
      {"column", [] { return column(); }},
      {"newtons_cradle", [] { return newtons_cradle(); }},
      {"incline", [] { return incline(); }},
      {"bouncing_disks", [] { return bouncing_disks(); }},
      {"elastic_gas", [] { return elastic_gas(); }},
      {"bullet_wall", [] { return bullet_wall(); }},
      {"heavy_on_light", [] { return heavy_on_light(); }},
      {"demo", [] { return demo(); }},
  };
  return kBuilders;
}

}  // namespace

std::vector<std::string> standard_scene_names()
{
  std::vector<std::string> names;
  for (const auto& entry : registry())
  {
    names.push_back(entry.first);
  }
  return names;
}

Scene make_standard_scene(const std::string& name)
{
  for (const auto& entry : registry())
  {
    if (entry.first == name)
    {
      return entry.second();
    }
  }
  throw std::invalid_argument("unknown scene '" + name + "'");
}

}  // namespace scenes
}  // namespace collision2d
