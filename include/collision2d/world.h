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
