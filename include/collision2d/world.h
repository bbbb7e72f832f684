// A stateful world advanced in frames of substeps (SPEC section 3): gravity,
// materials, static and kinematic bodies, warm starting, and only the physics
// a scene needs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/vec2.h"

namespace collision2d
{
/// Per-body surface properties; a contact combines its two bodies' values by min.
struct Material
{
  double restitution = 0.0;       ///< Newton coefficient, [0, 1]
  double static_friction = 0.0;   ///< mu_s >= 0
  double kinetic_friction = 0.0;  ///< mu_k >= 0
};

/// Each physical effect is on when the scene needs it (Auto) unless forced.
enum class Toggle
{
  Auto,
  On,
  Off
};

struct WorldSettings
{
  Vec2 gravity{0.0, -9.81};               ///< m/s^2
  double dt = 1.0 / 60.0;                 ///< frame length (s)
  int substeps = 4;                       ///< substeps per frame
  int velocity_iterations = 2;            ///< passes over the contact points per substep
  double slop = 1e-3;                     ///< penetration left uncorrected (m)
  double compliance = 1e-8;               ///< contact compliance (m/N), softens K_n by compliance/h^2
  double restitution_threshold = 1e-3;    ///< approach speed below which e is ignored (m/s)
  Toggle rotation = Toggle::Auto;
  Toggle friction = Toggle::Auto;
  Toggle restitution = Toggle::Auto;
  Toggle position_correction = Toggle::Auto;
  Toggle time_of_impact = Toggle::Auto;
  Toggle warm_starting = Toggle::Auto;
  Toggle sleeping = Toggle::Auto;
};

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
};

struct StepReport
{
  int frames = 0;
  int substeps = 0;                 ///< substeps done in total
  std::size_t contact_count = 0;    ///< contact points in the last substep
  double max_penetration = 0.0;     ///< largest depth seen after correction (m)
  double kinetic_energy = 0.0;      ///< after the step (J)
  ActiveEffects active;
};

using BodyId = std::uint32_t;

/// A contact point of the last substep with the impulses it carried.
struct WorldContact
{
  BodyId a = 0;
  BodyId b = 0;
  Contact contact;  ///< indices a/b refer to positions in body_ids()
  ContactImpulse impulse;
};

}  // namespace collision2d

namespace collision2d
{
/// Bodies are kept by stable id; ids are never reused within one world.
/// A World is a value: copying it snapshots the whole state, which is how a
/// caller can try a change and roll back.
class World
{
public:
  /// Throws std::invalid_argument naming the field for an out-of-range setting.
  explicit World(const WorldSettings& settings = WorldSettings());

  /// Throws std::invalid_argument for an out-of-range or non-finite material.
  BodyId add_body(const Body& body, const Material& material = Material());
  /// Throws std::out_of_range for an unknown id.
  void remove_body(BodyId id);
  bool has_body(BodyId id) const;
  const Body& body(BodyId id) const;
  const Material& material(BodyId id) const;
  /// Sets the pose and velocity of a body between frames.
  void set_body_state(BodyId id, Vec2 position, double theta, Vec2 velocity, double omega);
  /// Ids in ascending order.
  std::vector<BodyId> body_ids() const;
  std::size_t body_count() const;
  void clear();

  const WorldSettings& settings() const { return settings_; }
  /// Validates like the constructor; the world is unchanged on failure.
  void set_settings(const WorldSettings& settings);
  /// Throws std::invalid_argument naming the field for an out-of-range setting.
  static void validate(const WorldSettings& settings);

  /// Advances `frames` frames of settings().dt. Never produces NaN from finite input.
  StepReport step(int frames = 1);
  /// Contact points of the last substep with their impulses.
  const std::vector<WorldContact>& contacts() const { return contacts_; }
  double time() const { return time_; }
  std::uint64_t frame_count() const { return frame_count_; }

private:
  WorldSettings settings_;
  std::vector<WorldContact> contacts_;
  double time_ = 0.0;
  std::uint64_t frame_count_ = 0;
  // Implementation state (bodies, materials, id map, broad phase, warm-start
  // cache, scratch buffers) is declared by the implementation.
};

}  // namespace collision2d
