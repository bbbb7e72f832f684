// Box2D adapter (see box2d_engine.h).
#include "box2d_engine.h"

#include <box2d/box2d.h>

#include <stdexcept>
#include <vector>

#include "peer_materials.h"

namespace collision2d
{
namespace bench
{
namespace
{
constexpr int kDefaultVelocityIterations = 8;  // Box2D manual's recommendation
constexpr int kDefaultPositionIterations = 3;  // Box2D manual's recommendation

b2Vec2 to_b2(Vec2 v)
{
  return b2Vec2(static_cast<float>(v.x), static_cast<float>(v.y));
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

class Box2dEngine : public Engine
{
public:
  Box2dEngine(const Scene& scene, const EngineConfig& config) : world_(to_b2(config.settings.gravity))
  {
    const bool matched = config.variant == PeerVariant::Matched;
    const bool defaults = config.variant == PeerVariant::Defaults;
    steps_per_frame_ = defaults ? 1 : config.settings.substeps;
    velocity_iterations_ = matched ? config.settings.velocity_iterations : kDefaultVelocityIterations;
    step_ = static_cast<float>(config.settings.dt / steps_per_frame_);
    world_.SetAllowSleeping(defaults);
    for (const SceneBody& entry : scene.bodies)
    {
      bodies_.push_back(add_body(entry, matched ? config.settings.restitution_threshold : -1.0));
    }
  }

  void step_frame() override
  {
    for (int i = 0; i < steps_per_frame_; ++i)
    {
      world_.Step(step_, velocity_iterations_, kDefaultPositionIterations);
    }
  }

  BodyState state(std::size_t index) const override
  {
    const b2Body* b = bodies_[index];
    const b2Vec2 p = b->GetPosition();
    const b2Vec2 v = b->GetLinearVelocity();
    return BodyState{Vec2{p.x, p.y}, b->GetAngle(), Vec2{v.x, v.y}, b->GetAngularVelocity()};
  }

private:
  /// restitution_threshold < 0 keeps Box2D's default.
  b2Body* add_body(const SceneBody& entry, double restitution_threshold)
  {
    const Body& body = entry.body;
    b2BodyDef def;
    def.type = body_type(body.type());
    def.position = to_b2(body.position());
    def.angle = static_cast<float>(body.theta());
    def.linearVelocity = to_b2(body.velocity());
    def.angularVelocity = static_cast<float>(body.omega());
    b2Body* b = world_.CreateBody(&def);

    b2CircleShape circle;
    b2PolygonShape polygon;
    b2FixtureDef fixture;
    if (body.shape() == Shape::Disk)
    {
      circle.m_radius = static_cast<float>(body.radius());
      fixture.shape = &circle;
    }
    else
    {
      if (body.vertex_count() > b2_maxPolygonVertices)
      {
        throw std::runtime_error("box2d: polygon with more than b2_maxPolygonVertices vertices");
      }
      std::vector<b2Vec2> points;
      for (const Vec2& v : inset_polygon(body.local_vertices(), b2_polygonRadius))
      {
        points.push_back(to_b2(v));
      }
      polygon.Set(points.data(), static_cast<int32>(points.size()));
      fixture.shape = &polygon;
    }
    const PeerCoefficients c = peer_coefficients(entry.material, MixingRule::Box2d);
    fixture.friction = static_cast<float>(c.friction);
    fixture.restitution = static_cast<float>(c.restitution);
    if (restitution_threshold >= 0.0)
    {
      fixture.restitutionThreshold = static_cast<float>(restitution_threshold);
    }
    fixture.density = body.type() == BodyType::Dynamic ? 1.0f : 0.0f;
    b->CreateFixture(&fixture);
    if (body.type() == BodyType::Dynamic)
    {
      // Our exact mass and inertia (the inset outline would be slightly lighter).
      b2MassData mass;
      mass.mass = static_cast<float>(body.mass());
      mass.center.SetZero();
      mass.I = static_cast<float>(body.inertia());
      b->SetMassData(&mass);
    }
    return b;
  }

  b2World world_;
  std::vector<b2Body*> bodies_;
  int steps_per_frame_ = 1;
  int velocity_iterations_ = kDefaultVelocityIterations;
  float step_ = 0.0f;
};

}  // namespace

std::unique_ptr<Engine> make_box2d_engine(const Scene& scene, const EngineConfig& config)
{
  return std::make_unique<Box2dEngine>(scene, config);
}

}  // namespace bench
}  // namespace collision2d
