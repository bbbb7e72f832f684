// Chipmunk adapter (see chipmunk_engine.h).
#include "chipmunk_engine.h"

#include <chipmunk/chipmunk.h>

#include <vector>

#include "peer_materials.h"

namespace collision2d
{
namespace bench
{
namespace
{
cpVect to_cp(Vec2 v)
{
  return cpv(v.x, v.y);
}

class ChipmunkEngine : public Engine
{
public:
  ChipmunkEngine(const Scene& scene, const EngineConfig& config) : space_(cpSpaceNew())
  {
    const bool matched = config.variant == PeerVariant::Matched;
    steps_per_frame_ = config.variant == PeerVariant::Defaults ? 1 : config.settings.substeps;
    step_ = config.settings.dt / steps_per_frame_;
    cpSpaceSetGravity(space_, to_cp(config.settings.gravity));
    if (matched)
    {
      cpSpaceSetIterations(space_, config.settings.velocity_iterations);
      cpSpaceSetCollisionSlop(space_, config.settings.slop);
    }
    for (const SceneBody& entry : scene.bodies)
    {
      add_body(entry);
    }
  }

  ChipmunkEngine(const ChipmunkEngine&) = delete;
  ChipmunkEngine& operator=(const ChipmunkEngine&) = delete;

  ~ChipmunkEngine() override
  {
    // cpSpaceFree does not free the bodies and shapes it holds.
    cpSpaceFree(space_);
    for (cpShape* s : shapes_)
    {
      cpShapeFree(s);
    }
    for (cpBody* b : bodies_)
    {
      cpBodyFree(b);
    }
  }

  void step_frame() override
  {
    for (int i = 0; i < steps_per_frame_; ++i)
    {
      cpSpaceStep(space_, step_);
    }
  }

  BodyState state(std::size_t index) const override
  {
    const cpBody* b = bodies_[index];
    const cpVect p = cpBodyGetPosition(b);
    const cpVect v = cpBodyGetVelocity(b);
    return BodyState{Vec2{p.x, p.y}, cpBodyGetAngle(b), Vec2{v.x, v.y}, cpBodyGetAngularVelocity(b)};
  }

private:
  void add_body(const SceneBody& entry)
  {
    const Body& body = entry.body;
    cpBody* b = nullptr;
    switch (body.type())
    {
      case BodyType::Dynamic:
        b = cpBodyNew(body.mass(), body.inertia());
        break;
      case BodyType::Static:
        b = cpBodyNewStatic();
        break;
      case BodyType::Kinematic:
        b = cpBodyNewKinematic();
        break;
    }
    // Pose first: a static body's shapes are indexed where they are added.
    cpBodySetPosition(b, to_cp(body.position()));
    cpBodySetAngle(b, body.theta());
    cpBodySetVelocity(b, to_cp(body.velocity()));
    cpBodySetAngularVelocity(b, body.omega());
    cpSpaceAddBody(space_, b);
    bodies_.push_back(b);

    cpShape* s = nullptr;
    if (body.shape() == Shape::Disk)
    {
      s = cpCircleShapeNew(b, body.radius(), cpvzero);
    }
    else
    {
      std::vector<cpVect> verts;
      for (const Vec2& v : body.local_vertices())
      {
        verts.push_back(to_cp(v));
      }
      s = cpPolyShapeNew(b, static_cast<int>(verts.size()), verts.data(), cpTransformIdentity, 0.0);
    }
    const PeerCoefficients c = peer_coefficients(entry.material, MixingRule::Chipmunk);
    cpShapeSetFriction(s, c.friction);
    cpShapeSetElasticity(s, c.restitution);
    cpSpaceAddShape(space_, s);
    shapes_.push_back(s);
  }

  cpSpace* space_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  int steps_per_frame_ = 1;
  double step_ = 0.0;
};

}  // namespace

std::unique_ptr<Engine> make_chipmunk_engine(const Scene& scene, const EngineConfig& config)
{
  return std::make_unique<ChipmunkEngine>(scene, config);
}

}  // namespace bench
}  // namespace collision2d
