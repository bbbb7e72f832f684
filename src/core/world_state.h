// Internal to the core: the World's state, which the stages of its step
// (world_impl.h) read and write. A World is a value, so all of it is copied
// with the World; the scratch buffers keep their capacity from frame to
// frame, so a warmed-up step allocates nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/aabb.h"
#include "collision2d/body.h"
#include "collision2d/broad_phase.h"
#include "collision2d/collide.h"
#include "collision2d/world.h"
#include "contact_kernel.h"
#include "fat_box_pairs.h"
#include "resting_grid.h"
#include "soft_rows.h"
#include "worker_pool.h"
#include "world_rollback.h"
#include "world_stage_types.h"

namespace collision2d
{
namespace detail
{
/// How a body moves in a soft frame's substeps: not at all (static or
/// asleep), under gravity and its contacts, or at its set velocity.
enum class FrameMotion : unsigned char
{
  Still,
  Dynamic,
  Kinematic
};

struct WorldState
{
  explicit WorldState(const WorldSettings& settings) : settings_(settings) {}

  WorldSettings settings_;
  std::uint64_t version_ = 0;  ///< bumped by every edit through the World API
  bool rest_known_ = false;    ///< the last frame started and ended at rest at rest_version_
  std::uint64_t rest_version_ = 0;
  StepReport rest_frame_;      ///< that frame's own report
  bool rest_finish_known_ = false;  ///< the last step ended at the rest state; no frame stepped since
  StepReport rest_finish_;     ///< finish_report's figures at rest
  /// Contacts of pairs with a mover, in (a, b) order: published in pair
  /// order, put aside and woken by merging, sorted by set_step_state. The
  /// next detection reads them as its warm-start cache (every lookup relies
  /// on the order); the frame then publishes its own over them.
  std::vector<WorldContact> contacts_;
  /// Contacts of sleeping islands (with each other, static and still
  /// kinematic bodies), in (a, b) order: nothing in a step reads them until
  /// their island wakes.
  std::vector<WorldContact> sleeping_contacts_;
  double sleeping_penetration_ = 0.0;         ///< deepest of them (m)
  std::vector<IslandLabel> island_label_;     ///< a sleeping body's island (0: none)
  IslandLabel next_island_label_ = 0;
  std::vector<IslandLabel> root_label_;       ///< label_new_sleepers' scratch, by union-find root
  std::vector<WorldContact> moved_contacts_;  ///< scratch: contacts put aside or woken
  std::vector<WorldContact> merge_scratch_;
  mutable std::vector<WorldContact> all_contacts_;  ///< all_contacts()'s answer
  double time_ = 0.0;
  std::uint64_t frame_count_ = 0;

  // Bodies in ascending id order; a dense index is a position in these arrays.
  std::vector<Body> bodies_;
  std::vector<Material> materials_;
  std::vector<BodyId> ids_;
  BodyId next_id_ = 0;
  std::vector<unsigned char> asleep_;  ///< 1 while the body's island sleeps (bytes: read in every body pass)
  std::vector<double> rest_time_;     ///< how long each body has been resting (s)
  std::vector<double> inner_radius_;  ///< m, for the time-of-impact speed test
  std::vector<unsigned char> disk_;   ///< 1 for a disk: the soft step's contacts stay put as it turns (follow_pose)
  double min_inner_radius_ = 0.0;

  // Scratch reused across substeps and steps (no allocation once warmed up).
  BroadPhase broad_phase_;
  FatBoxPairs fat_pairs_;  ///< the movers' pairs kept while their boxes stay inside enlarged ones
  BroadPhase sweep_phase_;
  std::vector<Aabb> boxes_;
  std::vector<double> reach_;         ///< soft step: frame_reach of each moving body (m)
  double margin_ = 0.0;               ///< this detection's speculative margin (m)
  /// Scratch that buffers with lives apart take in turn (FrameBlock): the
  /// pair stage's buffers below (place_pair_buffers) until the bodies are
  /// prepared after detection, then the soft step's rows until the contacts
  /// are published.
  FrameBlock frame_block_;
  FrameSpan<Manifold> manifolds_;
  FrameSpan<Collided> collided_;  ///< each pair's narrow-phase outcome, found by the workers
  /// Soft step: each pair's first cached contact when its manifold is kept, else kNotKept.
  FrameSpan<std::size_t> kept_from_;
  FrameSpan<std::size_t> pair_rows_;   ///< each pair's first row in points_, and the total last
  FrameSpan<std::size_t> pair_cache_;  ///< each pair's first cached contact in contacts_
  double reuse_distance_ = 0.0;         ///< this detection's contact_reuse_distance (m), 0: none
  /// Polygon i's world vertices, then its face normals, from posed_offset_[i]
  /// in posed_vertices_ (2 vertex_count() entries).
  std::vector<std::size_t> posed_offset_;
  std::vector<Vec2> posed_vertices_;
  std::uint64_t posed_version_ = 0;       ///< version_ when posed_offset_ was laid out
  std::vector<double> partial_max_;      ///< max_over's result of each part
  std::vector<PairPlacement> placements_;
  std::vector<BodyCensus> census_parts_;  ///< take_census's count of each part
  BodyCensus census_;                     ///< the last take_census, at census_version_
  bool census_known_ = false;
  std::uint64_t census_version_ = 0;
  std::vector<double> block_energies_;    ///< kinetic_energy: each block's sum
  WorkerPool workers_;
  std::vector<BodyPair> pairs_;
  // The broad phase looks from the movers (world_contacts.cpp).
  std::vector<std::size_t> movers_;     ///< bodies that move, ascending
  std::vector<std::size_t> resting_;    ///< the others
  std::vector<unsigned char> is_resting_;  ///< by body: in resting_
  BodyCensus resting_census_;           ///< count_body over resting_
  RestingGrid resting_grid_;            ///< resting_' boxes
  bool resting_built_ = false;          ///< ... built at these:
  std::uint64_t resting_version_ = 0;
  std::uint64_t resting_stamp_ = 0;
  double resting_margin_ = 0.0;
  std::uint64_t sleep_stamp_ = 0;       ///< bumped whenever a body falls asleep or wakes
  bool body_pass_full_ = true;          ///< this frame's per-body stages visit every body (for_each_body)
  std::vector<std::size_t> looked_;     ///< movers_ and the large resting bodies, ascending
  std::vector<Aabb> mover_boxes_;       ///< their boxes
  std::vector<BodyPair> mover_pairs_;
  std::vector<BodyPair> resting_pairs_;
  std::vector<unsigned char> swept_;  ///< SweptAs per body this substep (bytes: set by the workers)
  std::vector<double> swept_reach_sq_;  ///< soft step: sweep_reach_sq per body, set for the frame
  /// Soft step: the visited bodies a contact touches this frame, which alone
  /// a substep can make fast unless sweep_every_body_ (mark_swept_bodies).
  std::vector<std::size_t> sweep_candidates_;
  bool sweep_every_body_ = true;
  std::vector<double> toi_;           ///< fraction of the substep each body travels
  std::vector<BodyPair> crossing_pairs_;  ///< static_crossing_time's grid query
  bool clamping_ = false;             ///< some body stopped at its time of impact in the last sweep (toi_ follows edits)
  /// A fast kinematic body was swept this substep (world_kinematic_push.cpp).
  bool pushing_ = false;
  std::vector<std::size_t> pusher_;   ///< ... what pushes each body (a face or a pushed body), or kNoBody
  std::vector<double> pushed_at_;     ///< ... when in the substep (fraction) it meets the body
  std::vector<Vec2> push_;            ///< ... how far it pushes that body on (m)
  std::vector<BodyPair> touching_faces_;  ///< ... (face, body) pairs with no impact in the substep (they may touch)
  std::vector<std::size_t> last_pushed_;  ///< ... the bodies the last round of the chain pushed
  std::vector<std::size_t> next_pushed_;
  std::vector<unsigned char> in_last_round_;  ///< ... by body: in last_pushed_
  ContactPoints points_;  ///< this substep's contact points
  std::vector<BodyVelocity> velocity_;  ///< velocities during the velocity stage
  std::vector<Vec2> prev_position_;   ///< pose at the start of the substep
  std::vector<Vec2> prepared_position_;  ///< soft step: pose when the frame's contacts were prepared
  std::vector<double> prepared_theta_;
  std::vector<Vec2> frame_position_;     ///< soft step: each body's pose during the substeps (place_bodies)
  std::vector<double> frame_theta_;
  std::vector<FrameMotion> frame_motion_;  ///< soft step: how each body moves this frame
  bool poses_pending_ = false;           ///< frame_position_ and frame_theta_ hold poses not yet on the bodies
  /// soft step: stopped at its time of impact this frame (bytes, not bits:
  /// the workers set their own bodies' flags at once)
  std::vector<unsigned char> stopped_;
  std::vector<unsigned char> touching_;  ///< soft step: has a contact point this frame (bytes: the workers reset it)
  std::vector<double> exact_targets_;    ///< soft step, exact mode: each point's velocity target (m/s)
  /// soft step: the velocities the substep's solve began from (the exact
  /// relax solves again from them; restitution checks its energy against them)
  std::vector<BodyVelocity> solve_start_;
  ContactSprings springs_;               ///< soft step: this frame's contact springs (a point's: springs_.of(p))
  SoftRows soft_rows_;                   ///< soft step, iterative mode: the frame's manifolds in colours
  std::vector<Vec2> held_position_;      ///< ... and the pose it stopped at
  std::vector<double> held_theta_;
  std::vector<double> prev_theta_;
  std::vector<Vec2> moved_;           ///< position correction applied this substep (m)
  std::vector<double> turned_;        ///< rotation correction applied this substep (rad)
  double cache_h_ = 0.0;              ///< substep length the cached impulses were made with (s)
  bool bounces_ = false;               ///< soft step: some point of the frame can bounce
  std::vector<BouncePoint> bounce_points_;  ///< ... those points
  std::vector<TurningFacePoint> turning_faces_;  ///< soft step: the frame's disks on turning kinematic faces
  std::vector<RoundPoint> round_points_;  ///< soft step: the frame's round contacts followed exactly
  std::vector<std::size_t> bouncing_;   ///< scratch: the bounce_points_ a substep's restitution drives
  std::vector<std::size_t> released_;   ///< scratch: the bounce_points_ it lets go of
  std::vector<HeldPoint> held_;         ///< scratch: the points it holds while it does
  bool some_cannot_bounce_ = false;     ///< soft step: the frame has active points with e = 0
  std::vector<unsigned char> holding_body_;  ///< scratch: a body of a released or bouncing point
  std::vector<SavedImpulses> bounce_start_;  ///< scratch: the impulses of the points restitution drives, at its start
  std::vector<std::size_t> bounce_group_;    ///< scratch: union-find parents over their bodies, when restitution checks its answer
  std::vector<BounceGroup> bounce_groups_;  ///< scratch: by union-find root, what restitution did in the group
  /// Soft step: followed_penetration() of the step's last frame, worked out
  /// by publish_contacts (nothing changes the points or poses after it).
  bool followed_known_ = false;
  double followed_deepest_ = 0.0;  ///< m
  mutable std::size_t cache_cursor_ = 0;  ///< the rows' cached_pair cursor in contacts_, kept between lookups
  std::vector<Vec2> kicked_velocity_;  ///< velocities after the gravity kick, before a prediction
  std::vector<double> kicked_omega_;
  std::vector<std::size_t> island_;   ///< union-find parents for sleeping
  std::vector<unsigned char> island_awake_;  ///< by union-find root: some body of the island rests too little
  std::size_t asleep_count_ = 0;        ///< bodies asleep, counted at this sleep stamp and version:
  std::uint64_t asleep_counted_stamp_ = ~std::uint64_t{0};
  std::uint64_t asleep_counted_version_ = 0;

  Rollback rollback_;  ///< what a failed step puts back (world_rollback.h)
};

}  // namespace detail
}  // namespace collision2d
