// Internal to the core: what the World's stages hand each other besides the
// World's own state (world_impl.h): the step's context, the soft step's point
// preparation, the body census, the thresholds for sharing a stage among the
// workers, and the test hooks.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/world.h"
#include "contact_kernel.h"

namespace collision2d
{
namespace detail
{
/// What one substep needs to know, decided once per frame or substep.
struct StepContext
{
  double h = 0.0;      ///< substep length (s)
  double inv_h = 0.0;  ///< 1/s
  ActiveEffects effects;       ///< what this frame models
  bool warm_available = false; ///< warm starting on and a cache to start from
  bool first = false;          ///< first substep of the frame
  bool warm = false;           ///< this substep starts from cached impulses
};

/// Soft step, after the frame: a point's friction state as its contact
/// carries it to the next frame (WorldImpl::carry_slip).
struct CarriedSlip
{
  bool sliding = false;       ///< friction slips
  double anchor_drift = 0.0;  ///< m: slip since the point last stuck
};

/// One soft pass's parameters (world_soft_solve.cpp).
struct SoftPass;

/// Soft step: the fastest a body no contact touches can move in a frame,
/// held against its sweep reach (WorldImpl::may_turn_fast).
struct FreeSpeedBound
{
  double per_width = 0.0;   ///< reach speed per metre of the two thinnest half-widths (1/s)
  double frame_kick = 0.0;  ///< speed gravity adds in a frame (m/s)
  double spin_floor = 0.0;  ///< rad/s: the spin_floor of the frame's substeps
  double substep = 0.0;     ///< s
};

/// How a substep sweeps a body (WorldImpl::swept_, one byte each).
enum SweptAs : unsigned char
{
  kNotSwept = 0,
  kSweptMoving = 1,   ///< along its path, at its orientation
  kSweptTurning = 2,  ///< a dynamic polygon whose spin outruns its reach: turned too
};

/// How a pushing face moves in a substep: its translation (m) and its turn
/// about its centroid (rad), 0 for any face but a kinematic polygon.
struct FaceMove
{
  Vec2 move;
  double turn = 0.0;
};

/// Soft step: a contact point that can bounce (e > 0) and where its normal
/// impulses live during the substeps (world_soft_restitution.cpp).
struct BouncePoint
{
  std::size_t point = 0;
  ImpulseSlots impulses;        ///< its accumulated impulses: in its row, or the point's own
  double target = 0.0;          ///< this substep's Newton target (m/s), from its start
  bool apart = false;           ///< neither touching nor approaching at the substep's start
};

/// Soft step: a point that cannot bounce (e = 0) held at its speed while
/// restitution lets go of a point (world_soft_restitution.cpp).
struct HeldPoint
{
  std::size_t point = 0;
  ImpulseSlots impulses;      ///< its accumulated impulses: in its row, or the point's own
  double saved_target = 0.0;  ///< the point's own target, put back after restitution
};

/// Soft step: a point's accumulated impulses as restitution found them (N s),
/// put back if its bounce is dropped (world_soft_bounce_drop.cpp), and the
/// relative velocity there then (m/s) for the work restitution does.
struct SavedImpulses
{
  std::size_t point = 0;
  double normal = 0.0;
  double tangent = 0.0;
  Vec2 velocity;
};

/// Soft step: restitution's bookkeeping per group of bodies (sums at the
/// union-find root) and per body (`counted`), when it checks its answer.
struct BounceGroup
{
  double work = 0.0;          ///< J: what restitution's impulses did inside the group
  double energy_start = 0.0;  ///< J: kinetic, at the substep's solve's start
  double energy_after = 0.0;  ///< J: kinetic, after restitution
  double mass = 0.0;          ///< kg: the group's dynamic bodies
  double target = 0.0;        ///< m/s: the fastest target at its points
  bool kinematic = false;     ///< a moving kinematic body touches it
  bool dropped = false;
  bool counted = false;  ///< the body is in its group's sums
};

/// Soft step: a disk's contact point on the face of a kinematic body that
/// turns this frame, as it was prepared (world_turning_faces.cpp).
struct TurningFacePoint
{
  std::size_t point = 0;
  bool face_on_a = false;   ///< the face is body a's, else body b's
  Vec2 normal;              ///< unit, from a to b
  Vec2 r_a;                 ///< lever arms (m)
  Vec2 r_b;
  double separation = 0.0;  ///< gap (m)
  double anchor_drift = 0.0;  ///< slip since it stuck (m)
};

/// Soft step: a one-point contact between a disk and a vertex or another
/// disk, whose gap is followed as the distance between the two centres of
/// curvature (world_round_points.cpp).
struct RoundPoint
{
  std::size_t point = 0;
  Vec2 normal;          ///< as prepared: unit, from a to b
  Vec2 r_a;             ///< as prepared: lever arms (m)
  Vec2 r_b;
  double anchor_drift = 0.0;  ///< as prepared: slip since it stuck (m)
  double base_separation = 0.0;  ///< as prepared: its gap less the anchors' offset along its normal (m)
  Vec2 arm_a;           ///< from each body's centre to its centre of curvature (m): 0 for a disk
  Vec2 arm_b;
  double reach = 0.0;   ///< the centres' distance at prepare (m)
  double radius_a = 0.0;  ///< a disk's radius, 0 for a vertex (m)
  double radius_b = 0.0;
  /// A point that can bounce: whether this substep's aim turned it (else it
  /// keeps its prepared row this substep, its gap followed along the path).
  bool aimed = false;
};

/// Where a RoundPoint's centres of curvature are during a pass.
struct RoundPlace
{
  Vec2 arm_a;         ///< from each body's centre to its centre of curvature now (m)
  Vec2 arm_b;
  Vec2 apart;         ///< b's centre of curvature less a's (m)
  double reach = 0.0; ///< |apart| (m)
  double gap = 0.0;   ///< reach less the radii (m)
  Vec2 slide;         ///< b's centre of curvature's velocity less a's (m/s)
  bool on_face = false;  ///< a disk that slid off its vertex onto a face of the polygon
};

/// Bodies below which a per-body stage stays on the calling thread: each
/// body's update is a few operations, less than waking the workers costs.
constexpr std::size_t kMinSharedBodies = 2048;
/// No body (an index): pusher_ of a body nothing pushes this substep (world_kinematic_push.cpp),
/// and a core sweep that found no core touching already (world_toi.cpp).
constexpr std::size_t kNoBody = static_cast<std::size_t>(-1);
/// Contact points below which a per-point stage stays on the calling thread.
constexpr std::size_t kMinSharedPoints = 1024;
/// Broad-phase pairs below which filling their contact rows stays on the
/// calling thread.
constexpr std::size_t kMinSharedPairs = 1024;
/// A centroid core's radius as a fraction of its body's inner radius
/// (world_toi.cpp, world_static_crossing.cpp): small enough that an outline
/// stopped there overlaps its obstacle mostly on the centroid's side, so the
/// push out goes back the way the body came.
constexpr double kCoreFraction = 0.25;
/// Moves shorter than this fraction of a body's inner radius are not swept
/// against the static bodies (world_static_crossing.cpp): one cannot carry
/// the centroid of a body resting on a static face (the centroid an inner
/// radius away) past that face. A body a kinematic face pushes is swept
/// anyway: the push comes again each substep.
constexpr double kCrossingMoveFraction = 0.5;
/// kept_from_ of a pair whose manifold was found by the narrow phase.
constexpr std::size_t kNotKept = static_cast<std::size_t>(-1);

/// What select_effects needs to know of the bodies (world_effects.cpp).
struct BodyCensus
{
  std::size_t dynamic = 0;
  std::size_t rough = 0;           ///< bodies with friction
  std::size_t dynamic_rough = 0;
  std::size_t bouncy = 0;          ///< bodies with restitution
  std::size_t dynamic_bouncy = 0;
  // Bodies that turn under contacts: a polygon's impulses act off its
  // centroid; frictionless impulses on a disk act through its centre.
  std::size_t dynamic_polygons = 0;
  double widest_dynamic_polygon = 0.0;  ///< m: the largest bounding radius of a dynamic polygon
  std::size_t spinning_disks = 0;  ///< dynamic disks with a spin of their own
  std::size_t disks = 0;          ///< disks of any type (world_round_points.cpp)
  std::size_t turning_face_bodies = 0;  ///< kinematic polygons with a spin (world_turning_faces.cpp, world_toi.cpp)
  std::size_t moving_kinematic_bodies = 0;  ///< kinematic bodies with a velocity (world_kinematic_push.cpp)
  std::size_t kinematic_bodies = 0;  ///< any (the Fx2D order solves their contacts first)
  void add(const BodyCensus& other);
  /// Pairs combine materials by min, so a pair shows a property only when
  /// both bodies have it; a pair matters only when one of them is dynamic.
  bool rough_pair() const { return dynamic_rough > 0 && rough >= 2; }
  bool bouncy_pair() const { return dynamic_bouncy > 0 && bouncy >= 2; }
};

/// Narrow-phase outcome of a pair.
enum class Collided : unsigned char
{
  NotTried,
  Miss,
  Hit
};

/// What one part of place_pairs_in_parts found (world_contact_rows.cpp).
struct PairPlacement
{
  bool looked_up = false;       ///< it looked a pair up in the cache ...
  std::size_t last_lookup = 0;  ///< ... and its last lookup's answer
};

/// best = std::max(best, value) from several workers. A max is the same in
/// any order (std::max skips a NaN value), so the result does not depend on
/// how the work was split.
inline void raise_to(std::atomic<double>& best, double value)
{
  double seen = best.load();
  while (seen < value && !best.compare_exchange_weak(seen, value))
  {
  }
}

/// best = std::min(best, value) from several workers, in any order.
inline void lower_to(std::atomic<std::size_t>& best, std::size_t value)
{
  std::size_t seen = best.load();
  while (value < seen && !best.compare_exchange_weak(seen, value))
  {
  }
}

/// The root of island i in a union-find forest, halving the path on the way.
inline std::size_t island_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// Test hook (world_contacts.cpp): rebuild the resting grid and visit every
/// body in every frame, as if what rests had just changed.
void set_full_body_passes(bool full);

/// Test hooks (world_rest.cpp): turn the replay of rest frames off, and count
/// the frames replayed in this process.
void set_rest_replay_enabled(bool enabled);
std::uint64_t replayed_rest_frames();

}  // namespace detail
}  // namespace collision2d
