// One scene built in one physics engine (ours or a peer), advanced frame by
// frame and read back body by body in the scene's order, so that every
// measurement in the benchmarks is computed the same way for every engine.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "collision2d/scene.h"

namespace collision2d
{
namespace bench
{
struct BodyState
{
  Vec2 position;
  double theta = 0.0;
  Vec2 velocity;
  double omega = 0.0;
};

enum class EngineKind
{
  Collision2d,
  Box2d,     ///< Box2D 2.4.1
  Chipmunk,  ///< Chipmunk 7
  Box2dV3    ///< Box2D v3, only when the build was given COLLISION2D_BOX2D_V3_DIR
};

/// How a peer is configured. Defaults: the engine's own recommended values
/// (one step per frame, its iteration counts, slop and sleeping). Matched:
/// the substeps, velocity iterations and slop of `settings`, sleeping off.
/// Substepped: the engine's defaults except `settings.substeps` steps (or
/// substeps) per frame and sleeping off, the rule the stack comparison with
/// Box2D v3 states for every engine. Ours always runs with `settings` exactly.
enum class PeerVariant
{
  Defaults,
  Matched,
  Substepped
};

struct EngineConfig
{
  EngineKind kind = EngineKind::Collision2d;
  PeerVariant variant = PeerVariant::Matched;
  WorldSettings settings;  ///< ours; peers take dt (always) and the matched knobs
};

class Engine
{
public:
  virtual ~Engine() = default;
  /// Advances one frame of settings.dt.
  virtual void step_frame() = 0;
  /// State of scene.bodies[index].
  virtual BodyState state(std::size_t index) const = 0;
};

/// Throws std::runtime_error when the peer was not found at build time.
std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineConfig& config);
/// The states of bodies 0 .. states.size() - 1, in the scene's order.
void read_states(const Engine& engine, std::vector<BodyState>& states);
/// Largest displacement of any dynamic body of `scene` between two states (m).
double largest_move(const Scene& scene, const std::vector<BodyState>& from, const std::vector<BodyState>& to);
/// Whether make_engine can build this kind in this build.
bool engine_available(EngineKind kind);

/// Every engine kind, in the order the benchmarks list them.
constexpr EngineKind kAllEngines[] = {EngineKind::Collision2d, EngineKind::Box2d, EngineKind::Chipmunk,
                                      EngineKind::Box2dV3};

std::string engine_name(EngineKind kind);
/// The kind engine_name gives `name`; false for any other name.
bool engine_from_name(const std::string& name, EngineKind& kind);
std::string variant_name(PeerVariant variant);

}  // namespace bench
}  // namespace collision2d
