// Box2D v3 adapter (see box2d_v3_engine.h). This file sees only Box2D v3's
// headers: Box2D 2.4.1 spells its types the same, so its adapter lives in
// another target.
#include "box2d_v3_engine.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "peer_materials.h"

namespace collision2d
{
namespace bench
{
namespace
{
constexpr int kDefaultSubsteps = 4;  // Box2D v3's recommended subStepCount
constexpr float kShapeDensity = 1.0f;  // kg/m^2; replaced by our exact mass below

b2Vec2 to_b2(Vec2 v)
{
  return b2Vec2{static_cast<float>(v.x), static_cast<float>(v.y)};
}

/// b2Pos is b2Vec2 in the default float build and doubles in its large-world
/// build; filling the fields works for both.
b2Pos to_b2_pos(Vec2 v)
{
  b2Pos p{};
  p.x = static_cast<decltype(p.x)>(v.x);
  p.y = static_cast<decltype(p.y)>(v.y);
  return p;
}

b2BodyType body_type(BodyType type)
{
  switch (type)
  {
    case BodyType::Dynamic:
      return b2_dynamicBody;
    case BodyType::Static:
      return b2_staticBody;
    case BodyType::Kinematic:
      return b2_kinematicBody;
  }
  return b2_staticBody;
}

class Box2dV3Engine : public Engine
{
public:
  Box2dV3Engine(const Scene& scene, const EngineConfig& config)
  {
    const bool defaults = config.variant == PeerVariant::Defaults;
    substeps_ = defaults ? kDefaultSubsteps : config.settings.substeps;
    step_ = static_cast<float>(config.settings.dt);
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = to_b2(config.settings.gravity);
    def.enableSleep = defaults;
    // One worker steps on the caller's thread; more start Box2D v3's own
    // scheduler and threads (no task callbacks given).
    def.workerCount = std::max(1, config.settings.workers);
    if (config.variant == PeerVariant::Matched)
    {
      def.restitutionThreshold = static_cast<float>(config.settings.restitution_threshold);
    }
    world_ = b2CreateWorld(&def);
    for (const SceneBody& entry : scene.bodies)
    {
      bodies_.push_back(add_body(entry));
    }
  }

  Box2dV3Engine(const Box2dV3Engine&) = delete;
  Box2dV3Engine& operator=(const Box2dV3Engine&) = delete;

  ~Box2dV3Engine() override { b2DestroyWorld(world_); }

  void step_frame() override { b2World_Step(world_, step_, substeps_); }

  BodyState state(std::size_t index) const override
  {
    const b2BodyId b = bodies_[index];
    const b2Pos p = b2Body_GetPosition(b);
    const b2Vec2 v = b2Body_GetLinearVelocity(b);
    return BodyState{Vec2{static_cast<double>(p.x), static_cast<double>(p.y)},
                     b2Rot_GetAngle(b2Body_GetRotation(b)), Vec2{v.x, v.y}, b2Body_GetAngularVelocity(b)};
  }

private:
  b2BodyId add_body(const SceneBody& entry)
  {
    const Body& body = entry.body;
    b2BodyDef def = b2DefaultBodyDef();
    def.type = body_type(body.type());
    def.position = to_b2_pos(body.position());
    def.rotation = b2MakeRot(static_cast<float>(body.theta()));
    def.linearVelocity = to_b2(body.velocity());
    def.angularVelocity = static_cast<float>(body.omega());
    const b2BodyId b = b2CreateBody(world_, &def);

    b2ShapeDef shape = b2DefaultShapeDef();
    const PeerCoefficients c = peer_coefficients(entry.material, MixingRule::Box2d);
    shape.material.friction = static_cast<float>(c.friction);
    shape.material.restitution = static_cast<float>(c.restitution);
    shape.density = body.type() == BodyType::Dynamic ? kShapeDensity : 0.0f;
    if (body.shape() == Shape::Disk)
    {
      const b2Circle circle{b2Vec2{0.0f, 0.0f}, static_cast<float>(body.radius())};
      b2CreateCircleShape(b, &shape, &circle);
    }
    else
    {
      // Box2D v3 polygons need no skin (radius 0): the outline is ours as is.
      std::vector<b2Vec2> points;
      for (const Vec2& v : body.local_vertices())
      {
        points.push_back(to_b2(v));
      }
      if (points.size() > B2_MAX_POLYGON_VERTICES)
      {
        throw std::runtime_error("box2d v3: polygon with more than B2_MAX_POLYGON_VERTICES vertices");
      }
      const b2Hull hull = b2ComputeHull(points.data(), static_cast<int>(points.size()));
      if (hull.count == 0)
      {
        throw std::runtime_error("box2d v3: b2ComputeHull rejected a polygon");
      }
      const b2Polygon polygon = b2MakePolygon(&hull, 0.0f);
      b2CreatePolygonShape(b, &shape, &polygon);
    }
    if (body.type() == BodyType::Dynamic)
    {
      // Our exact mass and inertia about the centroid (the body's origin).
      b2MassData mass{};
      mass.mass = static_cast<float>(body.mass());
      mass.center = b2Vec2{0.0f, 0.0f};
      mass.rotationalInertia = static_cast<float>(body.inertia());
      b2Body_SetMassData(b, mass);
    }
    return b;
  }

  b2WorldId world_{};
  std::vector<b2BodyId> bodies_;
  int substeps_ = kDefaultSubsteps;
  float step_ = 0.0f;
};

}  // namespace

std::unique_ptr<Engine> make_box2d_v3_engine(const Scene& scene, const EngineConfig& config)
{
  return std::make_unique<Box2dV3Engine>(scene, config);
}

}  // namespace bench
}  // namespace collision2d
