// A neutral description of a scene: what the scene builders, the YAML loader
// and the .collision loader produce, and what the world, the benchmarks, the
// peer engines and the demo consume.
#pragma once

#include <string>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/world.h"

namespace collision2d
{
struct SceneBody
{
  Body body;  ///< shape, mass, pose, velocity and type (dynamic/static/kinematic)
  Material material;
  std::string name;  ///< optional label
};

struct Scene
{
  std::string name;
  std::vector<SceneBody> bodies;
  WorldSettings settings;
};

/// A world holding the scene's bodies in order (ids 0..n-1) with its settings.
World make_world(const Scene& scene);
/// The world's current bodies (ascending id), materials and settings.
Scene to_scene(const World& world, const std::string& name = "");

}  // namespace collision2d
