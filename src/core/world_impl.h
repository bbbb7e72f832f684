// Internal to the core: the stages of the World's step, on its state
// (world_state.h). The stages run in the order world_step.cpp lists them;
// each file below holds one topic.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/body.h"
#include "collision2d/collide.h"
#include "collision2d/world.h"
#include "contact_kernel.h"
#include "posed_polygon.h"
#include "turn.h"
#include "world_stage_types.h"
#include "world_state.h"

namespace collision2d
{
namespace detail
{
struct WorldImpl : WorldState
{
  explicit WorldImpl(const WorldSettings& settings) : WorldState(settings) {}

  // world.cpp: bodies by id.
  std::size_t index_of(BodyId id) const;
  void append_body(BodyId id, const Body& body, const Material& material);
  void remove_body(BodyId id);
  void wake(std::size_t index);
  void clear();

  // world_step.cpp: the step, top-down.
  StepReport step(int frames);
  void step_frame(StepReport& report);
  void fx2d_frame(StepContext& ctx, StepReport& report);
  void substep(StepContext& ctx, StepReport& report);
  void kick(const StepContext& ctx);
  void advance(StepContext& ctx, StepReport& report);
  /// Bodies [begin, end) moved over the substep (up to their time of impact when `swept`).
  void advance_bodies(std::size_t begin, std::size_t end, const StepContext& ctx, bool swept);
  /// Body i's move over the substep (up to its time of impact when
  /// `swept`); true when it turns, by omega turn_time, which the caller adds
  /// to the angle it keeps (advance_body: the body's own).
  bool move_body(std::size_t i, const StepContext& ctx, bool swept);
  void advance_body(std::size_t i, const StepContext& ctx, bool swept);
  /// How long body i turns in the substep (s): h, or up to its time of
  /// impact when its sweep turned it.
  double turn_time(std::size_t i, const StepContext& ctx, bool swept) const;
  void solve_velocity_stage(const StepContext& ctx, StepReport& report);
  void finish_report(StepReport& report);
  /// Of the dynamic bodies after the step (J), summed in body order.
  double kinetic_energy();
  /// Throws std::overflow_error naming the first body whose state is not
  /// finite. Each frame checks before it publishes its contacts: a step that
  /// publishes once then keeps its starting contacts in place (save_motion).
  void require_finite_state();
  /// Lowers first_bad to i when body i's state is not finite.
  void note_non_finite(std::size_t i, std::atomic<std::size_t>& first_bad) const;
  /// Throws that overflow_error for body i (an index).
  [[noreturn]] void throw_non_finite(std::size_t i) const;
  // world_rollback.cpp: what a refused step puts back.
  /// Keeps aside what a step of `frames` frames changes.
  void save_motion(int frames);
  void restore_motion();
  /// Body i's motion and rest time into the rollback buffers.
  void keep_body(std::size_t i);

  // Sharing a stage among the workers (worker_pool.h): results are the same
  // for any number of them.
  /// Calls f(begin, end) over the contact points split across the workers
  /// at body-pair boundaries, so each manifold's points stay on one worker.
  template <class F>
  void for_point_ranges(F f);
  /// Splits [0, count) into parts, one per worker (one part when count <
  /// min_shared), and folds answer(begin, end) of each part into `start` in
  /// part order: fold(fold(start, first), second)... `answers` is scratch.
  template <class T, class F, class Fold>
  T fold_in_parts(std::size_t count, std::size_t min_shared, std::vector<T>& answers, T start, F answer, Fold fold);
  /// The fold best = std::max(best, value(k)) over k in [0, count) from
  /// `start`, in parts on the workers when count >= min_shared.
  template <class F>
  double max_over(std::size_t count, std::size_t min_shared, double start, F value);
  /// Calls f(i) on the workers for every body the frame's per-body stages
  /// visit: all of them in a frame that changed which bodies rest, else only
  /// the movers (a resting body's state and scratch stay as that frame left them).
  template <class F>
  void for_each_body(F f);
  /// The same bodies on this thread, in ascending order.
  template <class F>
  void visit_bodies(F f)
  {
    if (body_pass_full_)
    {
      for (std::size_t i = 0; i < bodies_.size(); ++i)
      {
        f(i);
      }
      return;
    }
    for (const std::size_t i : movers_)
    {
      f(i);
    }
  }
  /// A dynamic body that is awake: gravity and contacts move it.
  bool awake_dynamic(std::size_t i) const { return bodies_[i].type() == BodyType::Dynamic && !asleep_[i]; }
  /// How many bodies sleep now (counted again after a sleep, wake or edit).
  std::size_t asleep_bodies();
  /// The first point at or after k that starts a new body pair (or the end).
  std::size_t pair_boundary(std::size_t k) const;

  // world_soft_step.cpp: the soft step, top-down.
  void soft_frame(StepContext& ctx, StepReport& report);
  /// The frame's two contact springs (springs_), at most a quarter of the
  /// substep rate in frequency, twice that against a body that cannot move.
  ContactSprings contact_springs(const StepContext& ctx) const;
  /// Pair k's points (added by add_manifold) prepared; whether any can bounce (e > 0).
  bool prepare_pair_points(const ActiveEffects& effects, std::size_t k);
  /// prepare_pair_points' soft terms on points [begin, end) (whole pairs).
  bool prepare_soft_range(std::size_t begin, std::size_t end);
  /// The bodies' side of the preparation: poses at prepare and which bodies
  /// touch; `rotation`: whether dynamic bodies turn this frame.
  void prepare_soft_bodies(bool rotation);
  /// Body i's pose at prepare, no pose change yet, not stopped or touching.
  void reset_body_motion(std::size_t i);
  /// After move_body: a stopped body held, a free one on its parabola,
  /// and the pose change its contacts follow.
  void follow_body(std::size_t i, const StepContext& ctx);
  /// The pose change since prepare that body i's contact points follow.
  /// Inline: the move pass calls it for every touching body.
  void follow_pose(std::size_t i)
  {
    BodyVelocity& state = velocity_[i];
    state.moved = frame_position_[i] - prepared_position_[i];
    const double turn = frame_theta_[i] - prepared_theta_[i];
    if (disk_[i])
    {
      // A disk's lever arms lie along its contacts' normals: turned by the
      // arc it rolls, not rotated, its gaps stay put and its slips count
      // that arc, at any spin.
      state.turned_cos = 1.0;
      state.turned_sin = turn;
      return;
    }
    turn_of(turn, state.turned_cos, state.turned_sin);
  }
  /// How body i moves in this frame's substeps (world_step.cpp).
  FrameMotion frame_motion(std::size_t i) const;
  /// Whether a body that moves so, at spin omega, turns in a substep.
  static bool turns(const StepContext& ctx, FrameMotion motion, double omega);
  /// move_body on the frame's poses (frame_position_, frame_theta_).
  void move_in_frame(std::size_t i, const StepContext& ctx, bool swept);
  /// The poses in frame_position_ and frame_theta_ set on the bodies, with
  /// their velocities when `velocities`. Returns the first body it visited
  /// whose state is not finite (as require_finite_state), else the body count.
  std::size_t place_bodies(bool velocities);
  void integrate_velocities(const StepContext& ctx, bool first);
  /// The soft passes, or in exact mode each island's LCP (the passes then
  /// take only the islands it could not solve).
  void solve_contacts(const StepContext& ctx, bool use_bias, StepReport& report);
  void aim_exact_targets(const StepContext& ctx, bool use_bias);
  // world_soft_solve.cpp: the soft passes.
  /// A warm start (with `warm`) and one soft pass over the frame's manifolds:
  /// by colour on the rows (iterative mode, shared among the workers), else
  /// in point order.
  void soft_pass(const StepContext& ctx, bool use_bias, bool warm);
  /// Stage `stage` of a soft pass (a colour, or the overflow after the
  /// colours; the warm start's stages first), part `part` of `parts` of it.
  void soft_stage(const SoftPass& pass, std::size_t stage, std::size_t part, std::size_t parts);
  /// Whether the soft step solves on its rows (the exact mode keeps the points).
  bool rows_on() const { return settings_.solver_mode != SolverMode::Exact; }
  void warm_start_manifold(std::size_t first);
  void solve_soft_manifold(std::size_t first, const StepContext& ctx, bool use_bias);
  /// A sticking point's slip from its anchor now (m), at its anchor offset; 0 for a sliding one.
  double anchor_drift(const ContactPoint& p, Vec2 offset) const;
  /// The tangential speed (m/s) that pulls `drift` back at the contact's rate.
  double anchor_pull(const ContactPoint& p, double drift, double max_push) const;
  /// After the frame: an active point's slip carried to the next frame, and
  /// whether it now slides (`sliding`: it ended at its friction bound): only
  /// past `slop` from where it stuck. publish_contacts asks on its way
  /// through the points; the outcome goes to the contact, not the point.
  CarriedSlip carry_slip(const ContactPoint& p, bool sliding, Vec2 offset) const;
  /// Unless `last`, another substep follows, whose gravity kick a body no
  /// contact touches takes here (integrate_velocities then skips it). On the
  /// last, returns whether some body moved far in the frame
  /// (moved_far_in_frame): only then may stop_static_crossings have work.
  bool integrate_positions(StepContext& ctx, StepReport& report, bool last);
  // Points the frame follows exactly, kept on the point verbs: disks on the
  // faces of turning kinematic bodies (world_turning_faces.cpp), and
  // contacts between a disk and a vertex or a disk whose centres slide past
  // each other (world_round_points.cpp).
  /// After prepare, before the rows are packed. Inline: most frames have
  /// neither, by the census (counted at each edit, census_for_frame); a
  /// pair bounces, and is not followed, unless one of its bodies does not.
  void find_followed_points()
  {
    turning_faces_.clear();
    round_points_.clear();
    if (census_.turning_face_bodies > 0)
    {
      list_turning_faces();
    }
    if (census_.disks > 0 && census_.bouncy < bodies_.size())
    {
      list_round_points();
    }
  }
  /// Before each pass (substeps of h seconds). `as_prepared`: after the
  /// passes, their gaps and slips on the normals and lever arms they were
  /// prepared with, which the contacts publish.
  void follow_points(double h, bool as_prepared = false)
  {
    if (!turning_faces_.empty())
    {
      follow_turning_points(h, as_prepared);
    }
    if (!round_points_.empty())
    {
      follow_round_points(h, as_prepared);
    }
  }
  __attribute__((noinline, cold)) void list_turning_faces();
  /// Disks on turning faces: their normals turned with their faces, their
  /// face anchors moved under the disk's nearest point, their gaps and slips
  /// measured on the turned faces.
  __attribute__((noinline, cold)) void follow_turning_points(double h, bool as_prepared);
  void follow_turning_point(const TurningFacePoint& t, double h, bool as_prepared);
  /// Round contacts whose centres slide past each other by more than
  /// kRoundSlideFraction of their distance in a frame (the straight gap would err).
  __attribute__((noinline, cold)) void list_round_points();
  /// Round contacts: their normals along the line between their centres now,
  /// their gaps the centres' distance less the radii, a speculative gap only
  /// as far as their path closes before they touch.
  __attribute__((noinline, cold)) void follow_round_points(double h, bool as_prepared);
  // world_soft_restitution.cpp: restitution, substep by substep.
  /// The frame's points that can bounce, after the rows are packed.
  void find_bounce_points();
  /// At a substep's start: each bouncing point's Newton target from the
  /// velocities now.
  void aim_bounces();
  /// How fast gravity closes p's gap (m/s^2, > 0 closing): only bodies that
  /// fall feel it.
  double closing_gravity(const ContactPoint& p) const;
  /// At a substep's end: the points it pushed driven to their targets,
  /// iterated to the fixed point.
  void restitute(StepReport& report);
  /// The points restitute drives, into bouncing_; returns their fastest |target| (m/s).
  double take_bouncing();
  /// The deepest overlap of the frame's contact points at the poses now,
  /// followed from the pose changes since they were prepared (m).
  double followed_penetration();

  // world_effects.cpp
  StepContext select_effects();
  /// take_census, kept while no edit changes the bodies (census_).
  const BodyCensus& census_for_frame();
  /// The bodies counted for select_effects, in parts on the workers.
  BodyCensus take_census();
  void count_body(std::size_t i, BodyCensus& census) const;

  // world_warm_integration.cpp
  void predict_velocities(const StepContext& ctx);
  bool previous_point_matches(std::size_t k) const;
  void restore_velocities();

  // world_toi.cpp
  /// What the step keeps of each body's shape: its inner radius (and the
  /// smallest of them) and whether it is a disk.
  void refresh_body_shapes();
  /// O(1) update for a body just appended: building a world stays O(n).
  void append_body_shape(const Body& body);
  Vec2 substep_displacement(std::size_t i, double h) const;
  /// How far body i's outline turns in a sweep of h seconds (rad): a
  /// kinematic polygon's spin (face_turn) or a dynamic polygon's marked
  /// kSweptTurning, 0 for any other body.
  double substep_turn(std::size_t i, double h) const;
  /// A turning kinematic polygon's turn in h seconds (rad), else 0.
  double face_turn(std::size_t i, double h) const;
  /// Body i's box for the sweep's broad phase: a turning outline's is its
  /// bounding circle's.
  Aabb sweep_box(std::size_t i, double h) const;
  /// `rotation`: whether dynamic bodies turn this substep (the active effect).
  bool sweep(double h, StepReport& report, bool stored, bool rotation);
  bool clamped(std::size_t i) const;
  /// Fx2D: the broad-phase boxes of the bodies stopped at their time of
  /// impact, grown by their touch tolerance (world_contacts.cpp calls it).
  __attribute__((noinline, cold)) void grow_stopped_boxes();
  /// Soft step: whether the frame's contact points (in pair order) hold pair (i, j).
  bool has_frame_contact(std::size_t i, std::size_t j) const;
  /// time_of_impact of a disk of `radius` at `from` standing for body i (a
  /// centroid core, or its centroid), moved by d, against `other` moved by d_other.
  double disk_time_of_impact(std::size_t i, double radius, Vec2 from, Vec2 d, const Body& other, Vec2 d_other) const;
  /// Earliest time of impact in (0, 1) of a fast body's centroid core
  /// against the other body of pair (i, j) moved by di and dj, else 1. A
  /// core that touches the other body already and closes on it is not
  /// counted: it is `on_face` (i or j, else kNoBody), for release_core.
  double core_time_of_impact(std::size_t i, std::size_t j, Vec2 di, Vec2 dj, bool stored,
                             std::size_t& on_face) const;
  /// Body k's core touches body `other` and closes on it: their approach
  /// along the normal there leaves both velocities (take_out_approach),
  /// instead of a stop at time 0 that would come again each substep.
  void release_core(std::size_t k, std::size_t other, bool stored);
  /// Body k's centroid touches `other` at `point` (kNoBody: a static face)
  /// and closes on it along n (unit, from `other` out to k): that approach
  /// leaves both velocities, shared by inverse mass so momentum is kept; a
  /// static, kinematic or sleeping `other` keeps its own. `stored`: the
  /// bodies hold the velocities (the Fx2D order), else velocity_ does.
  void take_out_approach(std::size_t k, std::size_t other, Vec2 n, Vec2 point, bool stored);

  // world_static_crossing.cpp: no centroid passes into a static body.
  /// Earliest time of impact in (0, 1) of body i's centroid core (or, if
  /// that touches already, its centroid), moved from `from` by d (a move
  /// that moved_far), against the static bodies; 1 if none. Exactly
  /// 0 when the centroid is on a static face already and d goes into it;
  /// `face` is then that face's outward normal.
  double static_crossing_time(std::size_t i, Vec2 from, Vec2 d, Vec2& face);
  /// Whether a move by d could carry body i's centroid into a static body
  /// it was clear of (stop_static_crossings sweeps only such moves).
  bool moved_far(std::size_t i, Vec2 d) const
  {
    const double least = kCrossingMoveFraction * inner_radius_[i];
    return length_sq(d) > least * least;
  }
  /// Soft step: moved_far for a dynamic body's move since prepare.
  bool moved_far_in_frame(std::size_t i) const
  {
    return frame_motion_[i] == FrameMotion::Dynamic && moved_far(i, frame_position_[i] - prepared_position_[i]);
  }
  /// When body i's centroid, moved from `from` by d, would first pass into
  /// static `obstacle`: the fraction of d its core (or centroid) moves clear;
  /// 1 if never; 0 on the obstacle's face (its normal into `face`), as static_crossing_time.
  double centroid_entry_time(std::size_t i, Vec2 from, Vec2 d, const Body& obstacle, Vec2& face) const;
  /// Each body's move stopped where static_crossing_time says: after the
  /// soft step's substeps (`soft`; its frame move, its contacts following)
  /// or after an Fx2D substep (its move from the substep's start).
  void stop_static_crossings(StepContext& ctx, StepReport& report, bool soft);

  // world_sweep_marks.cpp: which bodies a substep sweeps.
  /// The squared substep move above which body i is swept in Auto (m^2);
  /// -1 for a body that is neither awake and dynamic nor kinematic (never swept).
  double sweep_reach_sq(std::size_t i) const;
  /// The squared substep move (m^2) beyond which body i counts as fast: the Fx2D
  /// order's (stored) or the soft step's threshold for the frame.
  double fast_reach_sq(std::size_t i, bool stored) const;
  /// Whether body i spinning at `omega` (rad/s) for h seconds moves its far
  /// points past `reach_sq` (its fast_reach_sq): then its sweep turns it.
  /// `floor`: the spin_floor, below which no body can.
  bool turn_outruns(std::size_t i, double omega, double h, double floor, double reach_sq) const;
  /// The spin (rad/s) below which no dynamic polygon's turn in a substep of
  /// h seconds outruns its reach; infinity when dynamic bodies do not turn
  /// (`rotation` false) or none is a polygon.
  double spin_floor(double h, bool rotation) const;
  /// Soft step: the frame's bound on a free body's speed and spin for
  /// substeps of `h` (s); `rotation`: whether dynamic bodies turn this frame.
  FreeSpeedBound free_speed_bound(double h, bool rotation) const;
  /// Soft step: whether body i, were no contact to touch it this frame,
  /// could move farther than its reach in a substep (mark_swept_bodies).
  bool may_turn_fast(std::size_t i, const FreeSpeedBound& bound) const;
  /// Soft step: whether body i, were no contact to touch it this frame,
  /// could turn its far points past its reach in a substep.
  bool may_spin_fast(std::size_t i, const FreeSpeedBound& bound) const;
  /// Soft step: whether choosing sweep candidates can pay this frame.
  bool sweep_candidates_pay() const;
  /// Soft step: marks body i touched by a contact this frame, and lists it
  /// as a sweep candidate unless every body is checked.
  void note_touching(std::size_t i);
  /// Soft step: whether mark_swept_bodies checks every body this frame or
  /// only the candidates.
  void choose_sweep_pass(bool any_may_turn_fast);
  /// `stored`: the bodies hold their velocities; otherwise (the soft
  /// substep) they are read from velocity_ and stored only if a sweep runs.
  /// `rotation`: whether dynamic bodies turn this substep.
  bool mark_swept_bodies(double h, bool stored, bool rotation);
  /// mark_swept_bodies over sweep_candidates_ only.
  bool mark_sweep_candidates(double h, bool rotation);
  /// mark_swept_bodies over every body by its translation and spin.
  bool mark_every_body(double h, bool stored, bool rotation);
  /// Marks the turning kinematic polygons whose points move past their
  /// reach in a substep of h seconds; true if any.
  __attribute__((noinline, cold)) bool mark_turning_faces(double h);

  // world_kinematic_push.cpp: fast kinematic bodies swept, and what they strike pushed ahead.
  /// Body i's earliest impact so far is with `other`: pushed on if that is kinematic.
  void note_pusher(std::size_t i, std::size_t other);
  /// Pair (i, j) has no impact in the substep: listed if it is a fast
  /// kinematic face and an awake dynamic body (they may touch already).
  void note_touching_face(std::size_t i, std::size_t j);
  /// Once every stop is known: a listed face that meets its body's path
  /// pushes the body from there (in the soft step, only a stopped body).
  void press_touching_faces(double h, bool soft_substep);
  /// Whether the face, touching the body now, closes on it as it moves
  /// `face_move` (m) while the body moves `path` (m).
  bool closes_now(std::size_t face, std::size_t body, Vec2 face_move, Vec2 path);
  /// push_ for every body a kinematic body strikes in this substep of h
  /// seconds, and for every body a pushed body strikes in turn.
  void find_pushes(double h);
  /// Those pushes added to the poses the substep moves on from, substeps of
  /// h seconds (`stored`: the bodies' own, the Fx2D order; otherwise the
  /// soft step's frame poses).
  void apply_pushes(double h, bool stored);
  /// One round of that chain: the bodies last_pushed_ strike; false if none.
  bool pass_pushes_on(double h);
  /// Pushed body p meets body q on its way: q is pushed if p reaches it first.
  void push_on(std::size_t p, std::size_t q, double h);
  /// How far face k, moving and turning by `face` in the substep, pushes
  /// body i (m) from the time t (fraction) at which it meets the body,
  /// moved `body_move` (m) by then: along their contact normal by a face
  /// that only moves; round with it, or back onto it, by one that turns.
  Vec2 push_ahead(std::size_t i, std::size_t k, double t, Vec2 body_move, FaceMove face);
  /// push_ahead for a free body touching turning face k at the substep's
  /// start (manifold m), moved `body_move` (m) on its own.
  Vec2 lift_on_turning_face(std::size_t i, std::size_t k, Vec2 body_move, FaceMove face, const Manifold& m);
  /// push_ahead for a body that turning face k strikes at time t along `normal`.
  Vec2 carry_on_turning_face(std::size_t i, std::size_t k, double t, Vec2 body_move, FaceMove face, Vec2 normal);
  /// How far the material points of face k at manifold m's points move
  /// along its normal (m) as the face, offset by `k_offset`, moves `move`
  /// and turns `turn` (rad): the fastest of them.
  double face_advance(std::size_t k, const Manifold& m, Vec2 k_offset, Vec2 move, double turn) const;
  /// The manifold from body k into body i with i moved by `i_move`, k by
  /// `k_move` and turned by `k_turn`, if they touch there within
  /// impact_tolerance (false otherwise).
  bool touch_manifold(std::size_t i, std::size_t k, Vec2 i_move, Vec2 k_move, double k_turn, Manifold& m);
  /// How near (m) bodies i and k count as touching at a time of impact:
  /// the touch tolerance, widened for the round-off of posing them there.
  double impact_tolerance(std::size_t i, std::size_t k) const;
  /// Where body i's substep takes it (m): its move up to its impact, then its push.
  Vec2 pushed_path(std::size_t i, double h) const;

  // world_contacts.cpp
  bool is_mover(std::size_t i) const;
  /// Contacts at the current poses; pairs within `margin` (m) are kept too.
  /// With `prepare` (the soft step), each pair's points are prepared with
  /// ctx's effects as they are added, while they are in cache, and bounces_
  /// says whether any can bounce.
  void detect(const StepContext& ctx, double margin, StepReport& report, bool prepare = false);
  /// Broad and narrow phase of the pairs with a mover, within margin_.
  void find_mover_pairs();
  /// pairs_: the movers' pairs merged with the resting grid's, in (i, j) order.
  void merge_pairs();
  /// movers_ and the resting bodies' grid, again if what rests or its boxes
  /// changed; true if they were (the frame's per-body stages then visit every body).
  bool refresh_resting_grid();
  /// movers_ lists the bodies that move now (no sleep, wake or edit since it was made).
  bool movers_current() const
  {
    return resting_built_ && resting_version_ == version_ && resting_stamp_ == sleep_stamp_;
  }
  /// The bodies a per-body stage visits this frame (for_each_body's list):
  /// body k of them is visited(k).
  std::size_t visited_count() const { return body_pass_full_ ? bodies_.size() : movers_.size(); }
  std::size_t visited(std::size_t k) const { return body_pass_full_ ? k : movers_[k]; }
  /// How far any point of the body can travel in one frame (m).
  double frame_reach(const Body& b) const;
  /// With `posed`, the polygons' outlines come from pose_bodies (the poses
  /// must not have changed since).
  bool collide_pair(std::size_t i, std::size_t j, double tolerance, Manifold& m, bool posed_now) const;
  // world_pose.cpp: the outlines.
  /// Every polygon's outline at its pose now, into posed_vertices_ (workers share it).
  void pose_bodies();
  /// Poses bodies [begin, end), all but the static ones with `skip_static`.
  void pose_range(std::size_t begin, std::size_t end, bool skip_static);
  /// Body i's tight box, read from its outline (pose_bodies) when it has one.
  Aabb posed_box(std::size_t i) const;
  PosedPolygon posed(std::size_t i) const;
  /// The pair stage's buffers for n pairs, in the frame block.
  void place_pair_buffers(std::size_t n);
  /// Narrow phase of pairs_[begin, end) into manifolds_ and collided_ (the workers share it).
  void collide_range(std::size_t begin, std::size_t end);
  bool dynamic_pair(std::size_t i, std::size_t j) const;
  /// Pair k of this frame hit and has contact points: its bodies touch.
  bool pair_touches(std::size_t k) const { return collided_[k] == Collided::Hit && pair_rows_[k + 1] > pair_rows_[k]; }
  /// Soft step: pair k's manifold from its cached contacts when the pair has
  /// moved little since they were detected (world_contact_reuse.cpp);
  /// `cursor` as cached_pair's.
  bool keep_manifold(std::size_t k, std::size_t i, std::size_t j, std::size_t& cursor);
  /// A point's lever arms and where it was detected (world_contact_reuse.cpp):
  /// for a manifold the narrow phase found this frame, from the bodies now;
  /// for a kept one, from its cached contact. Both set the point in place.
  void set_new_origin(std::size_t k, ContactPoint& row) const;
  static void set_kept_origin(const ContactOrigin& origin, ContactPoint& row)
  {
    row.r_a = origin.r_a;
    row.r_b = origin.r_b;
    row.origin_separation = origin.separation;
    row.origin_theta_a = origin.theta_a;
    row.origin_theta_b = origin.theta_b;
    row.origin_known = origin.known;
  }
  /// The point's origin as its published contact carries it.
  static void publish_origin(const ContactPoint& row, ContactOrigin& origin)
  {
    origin.r_a = row.r_a;
    origin.r_b = row.r_b;
    origin.separation = row.origin_separation;
    origin.theta_a = row.origin_theta_a;
    origin.theta_b = row.origin_theta_b;
    origin.known = row.origin_known;
  }
  /// Whether pair k's manifold was kept (its points are contacts_ from kept_from_[k]).
  bool kept(std::size_t k) const { return kept_from_[k] != kNotKept; }
  /// How far apart the pair's points are kept (m): margin and reach, or touching.
  double pair_tolerance(std::size_t i, std::size_t j) const;
  /// Each pair's first row (pair_rows_) and cache entry (pair_cache_), as one
  /// pass in pair order finds them (with wakes and late collisions); returns
  /// the rows in all. `cached`: whether hit pairs look up their cached impulses.
  std::size_t place_pair_rows(bool cached);
  /// place_pair_rows in parts on the workers.
  void place_pairs_in_parts(bool cached);
  void place_pairs_part(std::size_t part, std::size_t parts, bool cached);
  void place_pairs_in_order(bool cached);
  /// Pair k's manifold into its rows, impulses matched from the cache;
  /// returns its deepest penetration (m).
  double add_manifold(std::size_t k, double warm_scale, bool friction);
  /// Index of the first cached contact of pair (a, b), or of where it would
  /// be, searched from `cursor`, which it moves.
  std::size_t cached_pair(std::size_t& cursor, BodyId a, BodyId b) const;
  /// Pair k's first cached contact: where its kept manifold came from, else
  /// cached_pair's answer; `cursor` as cached_pair's.
  std::size_t first_cached(std::size_t k, std::size_t& cursor) const;
  /// The contact of pair (a, b) with `feature` among its cached contacts from contacts_[first] on.
  const WorldContact* find_cached(std::size_t first, BodyId a, BodyId b, std::uint32_t feature) const;
  /// The frame's points become contacts_ (the next frame's warm-start cache),
  /// in place of the last ones, which nothing reads after detection.
  /// After a soft frame each contact takes its point's impulses from the
  /// point's row (the point is only read), an active point's slip is
  /// carried (carry_slip) and the deepest followed gap kept for the report.
  void publish_contacts(bool soft_frame = false);
  /// contacts_ resized to n contacts, to be overwritten.
  void size_contacts(std::size_t n);
  double measure_penetration() const;

  // world_solve.cpp: the velocity stage on the contact-solver kernel.
  void load_velocities();
  void load_velocity(std::size_t i);
  void store_velocities();
  void store_velocity(std::size_t i);
  void prepare_points(const ActiveEffects& effects);
  /// prepare_points on points [begin, end) (whole pairs); without
  /// `targets` (the soft step aims each substep) no Newton target is set.
  void prepare_point_range(const ActiveEffects& effects, std::size_t begin, std::size_t end, bool targets = true);
  void warm_start();
  void solve_velocities(bool friction);
  double velocity_residual() const;

  // world_position.cpp: penetration resolution (Fx2D step 3).
  void correct_positions(const StepContext& ctx, StepReport& report);
  void correct_pass(double softness, bool hold, bool resting_only);
  Vec2 integration_move(std::size_t i, Vec2 r) const;
  void hold_static_friction(const ContactPoint& first, const ContactPoint& second);
  void hold_all_static_friction(bool friction);
  double current_depth(const ContactPoint& p) const;
  void correct_point(const ContactPoint& p, double depth, double softness);
  bool correct_pair(const ContactPoint& first, const ContactPoint& second, double depth1, double depth2,
                    double softness);
  void displace(std::size_t i, double lambda, Vec2 n, Vec2 r, double inv_mass, double inv_inertia);

  // world_exact.cpp
  /// With `targets`, row k aims at (*targets)[k] instead of its Newton target;
  /// with `add`, a second pass of the substep: normal impulses only, added to the points'.
  void solve_exact_islands(StepReport& report, const std::vector<double>* targets = nullptr, bool add = false);
  void solve_position_islands(double softness, StepReport& report);

  // world_rest.cpp: a frame at rest repeats the last one, which is replayed.
  /// Every dynamic body asleep and no kinematic body moving.
  bool at_rest() const;
  /// Adds the remembered rest frame when nothing changed since it; false otherwise.
  bool replay_rest_frame(StepReport& report);
  /// After a frame: remembers it when it started and ended at rest.
  void note_frame(bool started_at_rest, const StepReport& frame);
  /// A whole step of replayed frames: nothing to keep aside, check or
  /// measure again (the closing figures are those of the rest state).
  bool replay_rest_step(int frames, StepReport& report);
  /// After a step: its closing figures, when it ends at the remembered rest.
  void note_finish(const StepReport& report);
  /// A frame's report folded into the step's.
  static void add_frame(StepReport& total, const StepReport& frame);
  /// Any edit through the World API: a remembered rest frame no longer holds.
  void changed() { ++version_; }

  // world_sleep.cpp: islands fall asleep; world_sleeping_contacts.cpp: their
  // contacts kept aside, out of the step, until they wake.
  void update_sleep();
  /// Gives every list that waking islands or putting them to sleep moves
  /// contacts through (and their scratch) room for `contacts` contacts and
  /// those asleep, so those moves cannot run out of memory: before a publish
  /// over the step's starting contacts (update_sleep comes after it), and
  /// before an edit that wakes islands.
  void make_room_to_move_contacts(std::size_t contacts);
  void update_rest_times();
  /// Labels the bodies that fell asleep this frame by island and puts their
  /// contacts aside.
  void label_new_sleepers();
  /// Moves the contacts of bodies asleep now from contacts_ to sleeping_contacts_.
  void put_contacts_aside();
  /// Wakes every body of island `label`; its contacts go back into `into`
  /// (kept in (a, b) order), where detection or warm starting finds them.
  void wake_island(IslandLabel label, std::vector<WorldContact>& into);
  /// Sleeping switched off: every body awake, every contact back in contacts_.
  void wake_everyone();
  /// Detection: wakes the islands that a mover's contact reaches; true if any woke.
  bool wake_reached_islands();
  /// Before the step first changes the contacts kept aside: keeps them (and,
  /// with `starting_contacts`, the step's starting contacts, which the
  /// change may reach) for a rollback.
  void keep_sleeping_for_rollback(bool starting_contacts);
  /// After an edit of contacts_ and asleep_ as a whole (set_step_state):
  /// sleeping contacts aside again, islands labelled from them.
  void sort_out_sleeping();
  /// sleeping_contacts_' deepest penetration, after they changed.
  void measure_sleeping_penetration();
  /// Every contact in (a, b) order: contacts_ merged with sleeping_contacts_.
  const std::vector<WorldContact>& all_contacts() const;
};

}  // namespace detail
}  // namespace collision2d

#include "world_parallel.h"
