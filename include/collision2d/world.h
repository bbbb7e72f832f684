// A stateful world advanced in frames of substeps: gravity,
// materials, static and kinematic bodies, warm starting, and only the physics
// a scene needs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/solver_mode.h"
#include "collision2d/world_settings.h"
#include "collision2d/vec2.h"

namespace collision2d
{
/// Which effects the last step actually modelled.
struct ActiveEffects
{
  bool rotation = false;
  bool friction = false;
  bool restitution = false;
  bool position_correction = false;
  bool time_of_impact = false;
  bool warm_starting = false;
  bool sleeping = false;

  /// Accumulates over frames or runs: an effect counts as active if it was
  /// active in any of them.
  ActiveEffects& operator|=(const ActiveEffects& o)
  {
    rotation = rotation || o.rotation;
    friction = friction || o.friction;
    restitution = restitution || o.restitution;
    position_correction = position_correction || o.position_correction;
    time_of_impact = time_of_impact || o.time_of_impact;
    warm_starting = warm_starting || o.warm_starting;
    sleeping = sleeping || o.sleeping;
    return *this;
  }
};

struct StepReport
{
  int frames = 0;
  int substeps = 0;                 ///< substeps done in total
  std::size_t contact_count = 0;    ///< contact points in the last substep
  /// Largest depth left after correction at the poses the step ends with
  /// (m): in the Fx2D step the last substep's contact pairs detected again;
  /// in the soft step the frame's contact points followed by the bodies' pose
  /// changes (as the solver sees them; detection is once per frame).
  double max_penetration = 0.0;
  double kinetic_energy = 0.0;      ///< of the dynamic bodies after the step (J)
  ActiveEffects active;             ///< union over the step's frames

  // Additions beyond the original fields.
  double max_detected_penetration = 0.0;  ///< largest depth found by detection, before correction (m)
  /// Largest normal-velocity residual left by any substep's velocity solve (m/s):
  /// per contact |v_n - target| if it carries impulse, else max(0, target - v_n).
  double velocity_residual = 0.0;
  /// The same residual on the first substep of the last frame, the only one
  /// warm starting acts on (m/s).
  double warm_substep_residual = 0.0;
  std::size_t swept_bodies = 0;     ///< body sweeps done for time of impact
  std::size_t toi_clamps = 0;       ///< sweeps that stopped a body at its time of impact
  std::size_t sleeping_bodies = 0;  ///< asleep after the step
  /// Exact solver mode: island solves (velocity, and position with
  /// exact_position_correction) done by pivoting, and those that failed and
  /// were done by the Gauss-Seidel passes instead (summed over substeps).
  std::size_t exact_islands = 0;
  std::size_t exact_fallbacks = 0;
};

using BodyId = std::uint32_t;

/// Soft step: the frame that detected a contact point's manifold. While the
/// pair's relative pose stays within WorldSettings::contact_reuse_distance of
/// it, later frames keep that manifold (normal, lever arms, features) and
/// follow its gaps from the bodies' pose changes instead of detecting again.
struct ContactOrigin
{
  Vec2 r_a;                      ///< lever arm from a's centre to the point then (m)
  Vec2 r_b;                      ///< from b's centre (m)
  double separation = 0.0;       ///< the gap then (m), > 0 apart
  double theta_a = 0.0;          ///< a's angle then (rad)
  double theta_b = 0.0;          ///< b's angle then (rad)
  bool known = false;            ///< false: not recorded (detect again)
};

/// A contact point of the last substep with the impulses it carried.
struct WorldContact
{
  BodyId a = 0;
  BodyId b = 0;
  Contact contact;  ///< indices a/b refer to positions in body_ids()
  ContactImpulse impulse;
  /// Friction was at its bound (the contact slips); in the soft step only
  /// once it has also slipped WorldSettings::slop since it stuck.
  bool sliding = false;
  /// Soft step: how far b has slipped along the tangent relative to a at the
  /// point since the contact last stuck (m); static friction pulls it back.
  double anchor_drift = 0.0;
  ContactOrigin origin;  ///< soft step: where its manifold was detected
};

/// What a step carries into the next besides the bodies, settings and clock:
/// the last substep's contacts with their impulses and friction state (warm
/// starting and sleeping islands read them), the substep length those
/// impulses were made over, and each body's sleep state. A snapshot that
/// keeps it steps on bit for bit like the world it was taken from.
struct StepState
{
  std::vector<WorldContact> contacts;  ///< contact.a/b are ignored on restore (taken from the ids)
  double contact_substep = 0.0;        ///< s; 0 before the first step
  std::vector<BodyId> asleep;          ///< ids of sleeping bodies
  std::vector<double> rest_time;       ///< s, one per body in body_ids() order
};

}  // namespace collision2d

namespace collision2d
{
namespace detail
{
struct WorldImpl;
}

/// Bodies are kept by stable id; ids are never reused within one world.
/// A World is a value: copying it snapshots the whole state, which is how a
/// caller can try a change and roll back.
///
/// A frame runs one of two pipelines on the shared contact-solver kernel
/// (WorldSettings::soft_step). The soft step, the default, collides once per
/// frame and solves the contacts as damped springs in substeps
/// (src/core/world_soft_step.cpp lists its stages); the Fx2D order detects,
/// corrects penetration and resolves velocities every substep
/// (src/core/world_step.cpp lists its stages and refinements).
class World
{
public:
  /// Throws std::invalid_argument naming the field for an out-of-range setting.
  explicit World(const WorldSettings& settings = WorldSettings());
  World(const World& other);
  World(World&& other) noexcept;
  World& operator=(const World& other);
  World& operator=(World&& other) noexcept;
  ~World();

  /// Throws std::invalid_argument for an out-of-range or non-finite material.
  BodyId add_body(const Body& body, const Material& material = Material());
  /// Adds a body under a given id, for restoring a snapshot: `id` must be at
  /// least next_id() (ids stay ascending and are never reused); next_id()
  /// becomes id + 1. Throws std::invalid_argument otherwise.
  void add_body(BodyId id, const Body& body, const Material& material = Material());
  /// Throws std::out_of_range for an unknown id.
  void remove_body(BodyId id);
  bool has_body(BodyId id) const;
  const Body& body(BodyId id) const;
  const Material& material(BodyId id) const;
  /// Sets the pose and velocity of a body between frames; a sleeping body
  /// wakes with its whole island.
  void set_body_state(BodyId id, Vec2 position, double theta, Vec2 velocity, double omega);
  /// Makes a body dynamic, static or kinematic between frames (a static one
  /// loses its velocity); it wakes (with its island), and its contacts keep
  /// their impulses.
  void set_body_type(BodyId id, BodyType type);
  /// Ids in ascending order.
  std::vector<BodyId> body_ids() const;
  std::size_t body_count() const;
  /// The id the next add_body(body) gives.
  BodyId next_id() const;
  /// Raises the next id (snapshots keep ids of removed bodies unused); throws
  /// std::invalid_argument when `id` is below next_id().
  void set_next_id(BodyId id);
  void clear();

  const WorldSettings& settings() const;
  /// Validates like the constructor; the world is unchanged on failure.
  void set_settings(const WorldSettings& settings);
  /// Throws std::invalid_argument naming the field for an out-of-range setting.
  static void validate(const WorldSettings& settings);

  /// Advances `frames` frames of settings().dt. Never returns a NaN or inf
  /// state from finite input: a frame that overflows (speeds, sizes or masses
  /// far beyond the README's supported ranges) throws std::overflow_error
  /// naming the body, and the world is then put back exactly as it was before
  /// the call (bodies' motion, contacts, sleep and clock). Running out of
  /// memory, on any worker, throws std::bad_alloc with the world put back the
  /// same way; so do add_body, remove_body, set_body_type and set_step_state.
  StepReport step(int frames = 1);
  /// Contact points of the last substep with their impulses, in (a, b)
  /// order. A sleeping island's contacts keep the values they had when it
  /// fell asleep: they are kept out of the step until a moving body reaches
  /// the island, which then wakes whole in that frame. With sleeping islands
  /// the list is assembled on each call; the reference holds until the next
  /// call or edit.
  const std::vector<WorldContact>& contacts() const;
  double time() const;
  std::uint64_t frame_count() const;
  /// Sets the sim time (s) and frame count, for restoring a snapshot.
  void set_clock(double time, std::uint64_t frame_count);
  /// True while the body's island sleeps (never for static or kinematic bodies).
  bool is_sleeping(BodyId id) const;
  StepState step_state() const;
  /// Restores what step_state() gave, after the bodies. Throws
  /// std::invalid_argument naming the entry that names an unknown body or is
  /// not finite; the world is unchanged then. With
  /// warm_start_before_integration the first substep after a restore starts
  /// without its prediction (it reads the previous substep's solver points,
  /// which a snapshot does not keep).
  void set_step_state(const StepState& state);

private:
  std::unique_ptr<detail::WorldImpl> impl_;
};

}  // namespace collision2d
