// Dispatch to ours or to a peer; peers exist only when CMake found them.
#include <algorithm>
#include <stdexcept>

#include "engine.h"
#ifdef COLLISION2D_HAVE_BOX2D
#include "peers/box2d_engine.h"
#endif
#ifdef COLLISION2D_HAVE_CHIPMUNK
#include "peers/chipmunk_engine.h"
#endif
#ifdef COLLISION2D_HAVE_BOX2D_V3
#include "peers/box2d_v3_engine.h"
#endif

namespace collision2d
{
namespace bench
{
std::unique_ptr<Engine> make_collision2d_engine(const Scene& scene, const WorldSettings& settings);

bool engine_available(EngineKind kind)
{
  switch (kind)
  {
    case EngineKind::Collision2d:
      return true;
    case EngineKind::Box2d:
#ifdef COLLISION2D_HAVE_BOX2D
      return true;
#else
      return false;
#endif
    case EngineKind::Chipmunk:
#ifdef COLLISION2D_HAVE_CHIPMUNK
      return true;
#else
      return false;
#endif
    case EngineKind::Box2dV3:
#ifdef COLLISION2D_HAVE_BOX2D_V3
      return true;
#else
      return false;
#endif
  }
  return false;
}

std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineConfig& config)
{
  switch (config.kind)
  {
    case EngineKind::Collision2d:
      return make_collision2d_engine(scene, config.settings);
#ifdef COLLISION2D_HAVE_BOX2D
    case EngineKind::Box2d:
      return make_box2d_engine(scene, config);
#endif
#ifdef COLLISION2D_HAVE_CHIPMUNK
    case EngineKind::Chipmunk:
      return make_chipmunk_engine(scene, config);
#endif
#ifdef COLLISION2D_HAVE_BOX2D_V3
    case EngineKind::Box2dV3:
      return make_box2d_v3_engine(scene, config);
#endif
    default:
      throw std::runtime_error(engine_name(config.kind) + " was not found when this benchmark was built");
  }
}

std::string engine_name(EngineKind kind)
{
  switch (kind)
  {
    case EngineKind::Collision2d:
      return "collision2d";
    case EngineKind::Box2d:
      return "box2d";
    case EngineKind::Chipmunk:
      return "chipmunk";
    case EngineKind::Box2dV3:
      return "box2d_v3";
  }
  return "?";
}

bool engine_from_name(const std::string& name, EngineKind& kind)
{
  for (EngineKind k : kAllEngines)
  {
    if (engine_name(k) == name)
    {
      kind = k;
      return true;
    }
  }
  return false;
}

std::string variant_name(PeerVariant variant)
{
  switch (variant)
  {
    case PeerVariant::Defaults:
      return "defaults";
    case PeerVariant::Matched:
      return "matched";
    case PeerVariant::Substepped:
      return "substepped";
  }
  return "?";
}

void read_states(const Engine& engine, std::vector<BodyState>& states)
{
  for (std::size_t i = 0; i < states.size(); ++i)
  {
    states[i] = engine.state(i);
  }
}

double largest_move(const Scene& scene, const std::vector<BodyState>& from, const std::vector<BodyState>& to)
{
  double move = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i)
  {
    if (scene.bodies[i].body.type() == BodyType::Dynamic)
    {
      move = std::max(move, length(to[i].position - from[i].position));
    }
  }
  return move;
}

}  // namespace bench
}  // namespace collision2d
