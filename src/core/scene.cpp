// Conversions between the neutral Scene description and a World.
#include "collision2d/scene.h"

namespace collision2d
{
World make_world(const Scene& scene)
{
  World world(scene.settings);
  for (const SceneBody& entry : scene.bodies)
  {
    world.add_body(entry.body, entry.material);
  }
  return world;
}

Scene to_scene(const World& world, const std::string& name)
{
  Scene scene;
  scene.name = name;
  scene.settings = world.settings();
  for (BodyId id : world.body_ids())
  {
    scene.bodies.push_back(SceneBody{world.body(id), world.material(id), ""});
  }
  return scene;
}

}  // namespace collision2d
