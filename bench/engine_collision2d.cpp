// Our World behind the Engine interface.
#include <vector>

#include "engine.h"

namespace collision2d
{
namespace bench
{
namespace
{
class Collision2dEngine : public Engine
{
public:
  Collision2dEngine(const Scene& scene, const WorldSettings& settings) : world_(make_world(scene))
  {
    world_.set_settings(settings);
    ids_ = world_.body_ids();
  }

  void step_frame() override { world_.step(1); }

  BodyState state(std::size_t index) const override
  {
    const Body& b = world_.body(ids_[index]);
    return BodyState{b.position(), b.theta(), b.velocity(), b.omega()};
  }

private:
  World world_;
  std::vector<BodyId> ids_;
};

}  // namespace

std::unique_ptr<Engine> make_collision2d_engine(const Scene& scene, const WorldSettings& settings)
{
  return std::make_unique<Collision2dEngine>(scene, settings);
}

}  // namespace bench
}  // namespace collision2d
