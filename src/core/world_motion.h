// Internal to the core: how the World's bodies move, the layer of its step
// below the contacts (WorldImpl, world_impl.h, builds on it). The passes
// over the bodies; a substep's move, on the bodies in the Fx2D order or on
// the soft step's frame poses; sweeps for the time of impact, stops before
// static bodies and pushes by fast kinematic bodies. It reads which pairs
// touch and the frame's contact points, and solves no contact.
#pragma once

#include <atomic>
#include <cstddef>

#include "collision2d/body.h"
#include "collision2d/collide.h"
#include "collision2d/world.h"
#include "turn.h"
#include "world_stage_types.h"
#include "world_state.h"

namespace collision2d
{
namespace detail
{
struct WorldMotion : WorldState
{
  explicit WorldMotion(const WorldSettings& settings) : WorldState(settings) {}

  // Per-body passes: the bodies a frame's per-body stages visit, shared
  // among the workers (worker_pool.h) with the same results for any number.
  /// Calls f(i) on the workers for every body the frame's per-body stages
  /// visit: all of them in a frame that changed which bodies rest, else only
  /// the movers (a resting body's state and scratch stay as that frame left them).
  template <class F>
  void for_each_body(F f)
  {
    if (body_pass_full_)
    {
      workers_.parallel_for(bodies_.size(), kMinSharedBodies, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          f(i);
        }
      });
      return;
    }
    workers_.parallel_for(movers_.size(), kMinSharedBodies, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
      {
        f(movers_[k]);
      }
    });
  }
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
  /// The bodies a per-body stage visits this frame (for_each_body's list):
  /// body k of them is visited(k).
  std::size_t visited_count() const { return body_pass_full_ ? bodies_.size() : movers_.size(); }
  std::size_t visited(std::size_t k) const { return body_pass_full_ ? k : movers_[k]; }
  /// A dynamic body that is awake: gravity and contacts move it.
  bool awake_dynamic(std::size_t i) const { return bodies_[i].type() == BodyType::Dynamic && !asleep_[i]; }
  /// Soft step: a kinematic body that moves this frame (it does work on what
  /// it touches).
  bool moving_kinematic(std::size_t i) const
  {
    return frame_motion_[i] == FrameMotion::Kinematic && (velocity_[i].v != Vec2{} || velocity_[i].omega != 0.0);
  }

  // world_motion.cpp: a body's move over a substep, and its velocity
  // between the body record and the solver's copy.
  /// How body i moves in this frame's substeps.
  FrameMotion frame_motion(std::size_t i) const
  {
    const BodyType type = bodies_[i].type();
    if (type == BodyType::Static || asleep_[i])
    {
      return FrameMotion::Still;
    }
    return type == BodyType::Kinematic ? FrameMotion::Kinematic : FrameMotion::Dynamic;
  }
  /// Whether a body that moves so, at spin omega, turns in a substep.
  static bool turns(const StepContext& ctx, FrameMotion motion, double omega)
  {
    // Kinematic bodies follow their set spin whatever the rotation toggle says.
    return (ctx.effects.rotation || motion == FrameMotion::Kinematic) && omega != 0.0;
  }
  /// Body i's move over the substep (up to its time of impact when
  /// `swept`); true when it turns, by omega turn_time, which the caller adds
  /// to the angle it keeps (advance_body: the body's own).
  bool move_body(std::size_t i, const StepContext& ctx, bool swept);
  /// How long body i turns in the substep (s): h, or up to its time of
  /// impact when its sweep turned it.
  double turn_time(std::size_t i, const StepContext& ctx, bool swept) const
  {
    // A body swept with its turn stops turning where its sweep stopped it.
    return swept && swept_[i] == kSweptTurning ? toi_[i] * ctx.h : ctx.h;
  }
  /// Body i's velocity and inverse masses into the solver's copy (velocity_).
  void load_velocity(std::size_t i);
  /// The solver's velocity back onto body i, if it is dynamic (impulses move no other).
  void store_velocity(std::size_t i);
  /// Lowers first_bad to i when body i's state is not finite.
  void note_non_finite(std::size_t i, std::atomic<std::size_t>& first_bad) const
  {
    // The lowest index, whichever worker finds it: the same body for any split.
    if (!has_finite_state(bodies_[i]))
    {
      lower_to(first_bad, i);
    }
  }
  /// Either body of the pair is dynamic (only then can their contact move a body).
  bool dynamic_pair(std::size_t i, std::size_t j) const
  {
    return bodies_[i].type() == BodyType::Dynamic || bodies_[j].type() == BodyType::Dynamic;
  }

  // world_soft_bodies.cpp: the soft step's bodies, moved on the frame's
  // own poses and velocities and placed back once a frame.
  /// The bodies' side of the preparation: poses at prepare and which bodies
  /// touch; `rotation`: whether dynamic bodies turn this frame.
  void prepare_soft_bodies(bool rotation);
  /// Pair k of this frame hit and has contact points: its bodies touch.
  bool pair_touches(std::size_t k) const { return collided_[k] == Collided::Hit && pair_rows_[k + 1] > pair_rows_[k]; }
  /// Body i's pose at prepare, no pose change yet, not stopped or touching.
  void reset_body_motion(std::size_t i);
  /// A substep's gravity kick for the dynamic bodies that take it here (all
  /// on the frame's `first` substep, then the touching ones) and a touching
  /// polygon's spin capped.
  void integrate_velocities(const StepContext& ctx, bool first);
  /// Unless `last`, another substep follows, whose gravity kick a body no
  /// contact touches takes here (integrate_velocities then skips it). On the
  /// last, returns whether some body moved far in the frame
  /// (moved_far_in_frame): only then may stop_static_crossings have work.
  bool integrate_positions(StepContext& ctx, StepReport& report, bool last);
  /// move_body on the frame's poses (frame_position_, frame_theta_).
  void move_in_frame(std::size_t i, const StepContext& ctx, bool swept);
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
  /// The poses in frame_position_ and frame_theta_ set on the bodies, with
  /// their velocities when `velocities`. Returns the first body it visited
  /// whose state is not finite (as require_finite_state), else the body count.
  std::size_t place_bodies(bool velocities);

  // world_toi.cpp
  /// What the step keeps of each body's shape: its inner radius (and the
  /// smallest of them) and whether it is a disk.
  void refresh_body_shapes();
  /// O(1) update for a body just appended: building a world stays O(n).
  void append_body_shape(const Body& body);
  Vec2 substep_displacement(std::size_t i, double h) const;
  double substep_turn(std::size_t i, double h) const;
  /// A turning kinematic polygon's turn in h seconds (rad), else 0.
  double face_turn(std::size_t i, double h) const;
  Aabb sweep_box(std::size_t i, double h) const;
  /// `rotation`: whether dynamic bodies turn this substep (the active effect).
  bool sweep(double h, StepReport& report, bool stored, bool rotation);
  bool clamped(std::size_t i) const;
  /// Fx2D: the broad-phase boxes of the bodies stopped at their time of
  /// impact, grown by their touch tolerance (world_contacts.cpp calls it).
  __attribute__((noinline, cold)) void grow_stopped_boxes();
  bool has_frame_contact(std::size_t i, std::size_t j) const;
  /// time_of_impact of a disk of `radius` at `from` standing for body i (a
  /// centroid core, or its centroid), moved by d, against `other` moved by d_other.
  double disk_time_of_impact(std::size_t i, double radius, Vec2 from, Vec2 d, const Body& other, Vec2 d_other) const;
  double core_time_of_impact(std::size_t i, std::size_t j, Vec2 di, Vec2 dj, bool stored,
                             std::size_t& on_face) const;
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
  bool mark_sweep_candidates(double h, bool rotation);
  bool mark_every_body(double h, bool stored, bool rotation);
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
  bool closes_now(std::size_t face, std::size_t body, Vec2 face_move, Vec2 path);
  /// push_ for every body a kinematic body strikes in this substep of h
  /// seconds, and for every body a pushed body strikes in turn.
  void find_pushes(double h);
  /// Those pushes added to the poses the substep moves on from, substeps of
  /// h seconds (`stored`: the bodies' own, the Fx2D order; otherwise the
  /// soft step's frame poses).
  void apply_pushes(double h, bool stored);
  bool pass_pushes_on(double h);
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
  double face_advance(std::size_t k, const Manifold& m, Vec2 k_offset, Vec2 move, double turn) const;
  bool touch_manifold(std::size_t i, std::size_t k, Vec2 i_move, Vec2 k_move, double k_turn, Manifold& m);
  double impact_tolerance(std::size_t i, std::size_t k) const;
  /// Where body i's substep takes it (m): its move up to its impact, then its push.
  Vec2 pushed_path(std::size_t i, double h) const;
};

}  // namespace detail
}  // namespace collision2d
