// A stateful world advanced in frames of substeps (SPEC section 3): gravity,
// materials, static and kinematic bodies, warm starting, and only the physics
// a scene needs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/broad_phase.h"
#include "collision2d/collide.h"
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
  /// Largest depth left after correction (m): the last substep's contact
  /// pairs measured again at the poses the step ends with.
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

/// A contact point of the last substep with the impulses it carried.
struct WorldContact
{
  BodyId a = 0;
  BodyId b = 0;
  Contact contact;  ///< indices a/b refer to positions in body_ids()
  ContactImpulse impulse;
  bool sliding = false;  ///< friction was at its bound (the contact slips)
};

}  // namespace collision2d

namespace collision2d
{
/// Bodies are kept by stable id; ids are never reused within one world.
/// A World is a value: copying it snapshots the whole state, which is how a
/// caller can try a change and roll back.
///
/// Each substep follows SPEC section 3 (integrate, detect, penetration
/// resolution with the previous-pose shift, velocities, velocity resolution,
/// warm starting), with these refinements, each explained where it is coded:
///  - warm starting also on later substeps, from the previous substep
///    (WorldSettings::warm_start_every_substep; false is SPEC's first-substep-only);
///  - a two-point manifold's normals are solved as one 2x2 block, and, when
///    it sticks, together with its friction (world_block.cpp); its friction
///    is one row at the manifold's midpoint against the summed normal impulse;
///  - stick or slip is a contact state: a sticking contact holds up to mu_s,
///    a sliding one is held at mu_k, and a sticking contact also takes back
///    the tangential part of its integration move (world_solve.cpp);
///  - penetration is resolved with the depth left after the corrections
///    already made in the pass;
///  - the velocity is the integrated one, which equals the derived
///    (pose - shifted previous pose) / h (world_step.cpp);
///  - WorldSettings::solver_mode Exact solves each island's velocities, and
///    (exact_position_correction) its penetrations, as one LCP by pivoting
///    (world_exact.cpp);
///  - WorldSettings::warm_start_before_integration advances the poses with
///    velocities predicted from the previous substep's contacts
///    (world_warm_integration.cpp).
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

  /// Advances `frames` frames of settings().dt. Never returns a NaN or inf
  /// state from finite input: a frame that overflows (speeds, sizes or masses
  /// far beyond the README's supported ranges) throws std::overflow_error
  /// naming the body. The world is then mid-frame and should be discarded;
  /// callers that must keep their world step a copy (the ROS node does).
  StepReport step(int frames = 1);
  /// Contact points of the last substep with their impulses (pairs of a
  /// sleeping island keep the values they had when it fell asleep).
  const std::vector<WorldContact>& contacts() const { return contacts_; }
  double time() const { return time_; }
  std::uint64_t frame_count() const { return frame_count_; }
  /// True while the body's island sleeps (never for static or kinematic bodies).
  bool is_sleeping(BodyId id) const;

private:
  /// One contact point prepared for the substep's solves.
  struct ContactRow
  {
    std::size_t a = 0;  ///< dense index, a < b
    std::size_t b = 0;
    Vec2 normal;        ///< unit, from a to b
    Vec2 point;
    Vec2 ra;            ///< lever arm from a's centre at detection (m)
    Vec2 rb;
    double penetration = 0.0;
    std::uint32_t feature = 0;
    int count = 1;                ///< points in this pair's manifold
    bool active = true;           ///< false: sleeping island, carried over unsolved
    double inv_mass_a = 0.0;      ///< 1/kg, 0 for static and kinematic bodies
    double inv_mass_b = 0.0;
    double inv_inertia_a = 0.0;   ///< 1/(kg m^2), 0 also when rotation is off
    double inv_inertia_b = 0.0;
    double normal_mass = 0.0;     ///< 1 / K_n without compliance (kg)
    double tangent_mass = 0.0;    ///< 1 / K_t (kg)
    double pair_tangent_mass = 0.0;  ///< 1 / K_t at a two-point manifold's midpoint (kg)
    double target = 0.0;          ///< post-solve normal speed (m/s)
    double mu_s = 0.0;
    double mu_k = 0.0;
    bool kinetic = false;         ///< slid in the previous substep: kinetic bound applies
    bool sliding = false;         ///< friction at its bound in this solve
    bool exact = false;           ///< solved by its island's LCP: no warm start, no passes
    bool position_solved = false; ///< penetration corrected by its island's LCP this substep
    ContactImpulse impulse;       ///< accumulated this substep (N s)
  };

  /// Which effects one frame models, decided once per frame.
  struct FrameEffects
  {
    ActiveEffects flags;
    bool warm_start_now = false;  ///< warm starting on and a cache to start from
  };

  // world.cpp
  std::size_t index_of(BodyId id) const;
  void wake(std::size_t index);
  // world_effects.cpp
  FrameEffects select_effects() const;
  bool needs_rotation(bool friction) const;
  bool any_pair_with(double (*property)(const Material&)) const;
  bool sleeping_wanted() const;
  // world_step.cpp
  void step_frame(StepReport& report);
  /// Throws std::overflow_error naming the first body whose state is not finite.
  void require_finite_state() const;
  void substep(FrameEffects& effects, double h, bool first, bool warm, StepReport& report);
  void kick(double h);
  void advance(FrameEffects& effects, double h, StepReport& report);
  // world_warm_integration.cpp
  void predict_velocities(double h, bool friction);
  bool previous_row_matches(std::size_t k) const;
  void restore_velocities();
  // world_toi.cpp
  void refresh_inner_radii();
  /// O(1) update for a body just appended: building a world stays O(n).
  void append_inner_radius(const Body& body);
  Vec2 substep_displacement(std::size_t i, double h) const;
  bool is_fast(std::size_t i, Vec2 displacement) const;
  bool mark_swept_bodies(double h);
  bool sweep(double h, StepReport& report);
  bool clamped(std::size_t i) const;
  // world_contacts.cpp
  bool is_mover(std::size_t i) const;
  void detect(const ActiveEffects& effects, bool warm, double h, StepReport& report);
  bool collide_pair(std::size_t i, std::size_t j, double tolerance, Manifold& m) const;
  void add_manifold(std::size_t i, std::size_t j, double tolerance, double warm_scale, bool friction);
  void carry_sleeping_pair(std::size_t i, std::size_t j);
  const WorldContact* find_cached(BodyId a, BodyId b, std::uint32_t feature) const;
  void publish_contacts();
  double measure_penetration() const;
  // world_solve.cpp
  void prepare_rows(const ActiveEffects& effects);
  double effective_inverse_mass(const ContactRow& row, Vec2 direction) const;
  Vec2 relative_velocity(const ContactRow& row) const;
  Vec2 relative_velocity_at(const ContactRow& row, Vec2 ra, Vec2 rb) const;
  void correct_positions(double h, bool friction, StepReport& report);
  void correct_pass(double softness, bool hold, bool resting_only);
  Vec2 integration_move(std::size_t i, Vec2 r) const;
  void hold_static_friction(const ContactRow& first, const ContactRow& second);
  void hold_all_static_friction(bool friction);
  double current_depth(const ContactRow& row) const;
  void correct_point(const ContactRow& row, double depth, double softness);
  void displace(std::size_t i, double lambda, Vec2 n, Vec2 r, double inv_mass, double inv_inertia);
  void warm_start();
  void solve_velocities(bool friction);
  void solve_normal(ContactRow& row);
  // world_exact.cpp
  void solve_exact_islands(StepReport& report);
  void solve_position_islands(double softness, StepReport& report);
  // world_block.cpp
  void solve_pair(ContactRow& first, ContactRow& second, bool rough);
  bool solve_stick_pair(ContactRow& first, ContactRow& second);
  bool solve_normal_pair(ContactRow& first, ContactRow& second);
  double pair_coupling(const ContactRow& first, const ContactRow& second) const;
  bool correct_pair(const ContactRow& first, const ContactRow& second, double depth1, double depth2, double softness);
  void solve_friction(ContactRow& row);
  void solve_friction_pair(ContactRow& first, ContactRow& second);
  static double coulomb(ContactRow& row, double needed, double normal_impulse);
  void apply_impulse(const ContactRow& row, Vec2 impulse);
  void apply_impulse_at(const ContactRow& row, Vec2 ra, Vec2 rb, Vec2 impulse);
  double velocity_residual() const;
  // world_sleep.cpp
  void update_sleep();
  void update_rest_times();

  WorldSettings settings_;
  std::vector<WorldContact> contacts_;
  double time_ = 0.0;
  std::uint64_t frame_count_ = 0;

  // Bodies in ascending id order; a dense index is a position in these arrays.
  std::vector<Body> bodies_;
  std::vector<Material> materials_;
  std::vector<BodyId> ids_;
  BodyId next_id_ = 0;
  std::vector<bool> asleep_;
  std::vector<double> rest_time_;     ///< how long each body has been resting (s)
  std::vector<double> inner_radius_;  ///< m, for the time-of-impact speed test
  double min_inner_radius_ = 0.0;

  // Scratch reused across substeps and steps (no allocation once warmed up).
  BroadPhase broad_phase_;
  BroadPhase sweep_phase_;
  std::vector<Aabb> boxes_;
  std::vector<BodyPair> pairs_;
  std::vector<bool> swept_;           ///< bodies swept this substep
  std::vector<double> toi_;           ///< fraction of the substep each body travels
  bool clamping_ = false;             ///< some body stopped at its time of impact this substep
  std::vector<ContactRow> rows_;
  std::vector<Vec2> prev_position_;   ///< pose at the start of the substep
  std::vector<double> prev_theta_;
  std::vector<Vec2> moved_;           ///< position correction applied this substep (m)
  std::vector<double> turned_;        ///< rotation correction applied this substep (rad)
  std::vector<WorldContact> cache_;   ///< previous frame's contacts, for warm starting
  double cache_h_ = 0.0;              ///< substep length the cached impulses were made with (s)
  std::vector<Vec2> kicked_velocity_;  ///< velocities after the gravity kick, before a prediction
  std::vector<double> kicked_omega_;
  std::vector<std::size_t> island_;   ///< union-find parents for sleeping
  std::vector<bool> island_awake_;
};

}  // namespace collision2d
