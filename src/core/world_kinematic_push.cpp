// A kinematic body (a robot's link, which no contact slows) that moves past
// most of a body in one substep is swept like a fast dynamic body. A body
// it strikes stops at the time of impact, as a clamped body does, and is
// then pushed ahead of the face by the face's advance along the contact
// normal over the rest of the substep; a body near the face that stops
// against another body while the face closes on it is pushed from where
// the face meets it; a pushed body pushes what it strikes in turn.
// A turning face (a kinematic polygon that spins) is swept with its turn;
// a body it strikes is carried round with it, and a body touching it moves
// on and is lifted back onto the face where the substep ends, since a
// straight move falls behind a turning face however slowly it turns.
// The Fx2D order finds contacts where a substep ends: the pushed pair ends
// touching, detection counts it (a stopped body's touch tolerance), and the
// velocity stage gives the body the face's normal velocity. The soft step's
// frame contact already holds a body ahead of a face (its margin grows by
// the face's reach in the frame), so there only a stopped body is pushed,
// and it is not held for the rest of the frame.
#include <algorithm>
#include <limits>

#include "collision2d/collide.h"
#include "collision2d/time_of_impact.h"
#include "collision2d/touch_tolerance.h"
#include "turn.h"
#include "world_motion.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// The normal at the time of impact is read from a manifold with this many
/// times the detection's touch tolerance: the swept pair touches there only
/// up to round-off.
constexpr double kImpactNormalToleranceScale = 4.0;
/// Rounds of a chain of pushes (a pushed body pushing the next) in a
/// substep: a row longer than this overlaps past its last pushed body, and
/// each round is one more broad phase.
constexpr int kMaxPushRounds = 16;
/// Two times of impact closer than this (fraction of a substep) are one:
/// the sweep found a stop along the body's own move that a push retraces.
constexpr double kSameImpact = 1e-9;

/// The signed gap of a manifold's deepest point (m): negative when overlapping.
double deepest_separation(const Manifold& m)
{
  double deepest = m.points[0].separation;
  for (int p = 1; p < m.count; ++p)
  {
    deepest = std::min(deepest, m.points[p].separation);
  }
  return deepest;
}

}  // namespace

void WorldMotion::note_pusher(std::size_t i, std::size_t other)
{
  // The pair with body i's earliest impact decides whether it is pushed.
  const bool pushed = bodies_[other].type() == BodyType::Kinematic && awake_dynamic(i);
  pusher_[i] = pushed ? other : kNoBody;
  pushed_at_[i] = toi_[i];
}

void WorldMotion::note_touching_face(std::size_t i, std::size_t j)
{
  const std::size_t face = bodies_[i].type() == BodyType::Kinematic ? i : j;
  const std::size_t body = face == i ? j : i;
  if (bodies_[face].type() == BodyType::Kinematic && swept_[face] && awake_dynamic(body))
  {
    touching_faces_.push_back(BodyPair{face, body});
  }
}

void WorldMotion::press_touching_faces(double h, bool soft_substep)
{
  // A body near a fast face moves with it once the velocity stage has run
  // (the soft step's contact holds the gap). One that an impact has slowed
  // since, or that stops at its time of impact with another body, would let
  // the face run into it: it is pushed from where the face meets its path.
  // In the soft step only a stopped body: its contact with the face holds
  // any other.
  for (const auto& [face, body] : touching_faces_)
  {
    const bool held = soft_substep && stopped_[body];
    if (soft_substep && !held && !(toi_[body] < 1.0))
    {
      continue;
    }
    const Vec2 face_move = substep_displacement(face, h);
    const double turn = face_turn(face, h);
    const Vec2 path = held ? Vec2{0.0, 0.0} : substep_displacement(body, h) * toi_[body];
    double t = time_of_impact(bodies_[face], face_move, turn, bodies_[body], path, 0.0);
    // A turning face is checked where the substep ends (push_ahead).
    if (t <= 0.0 && turn == 0.0 && !closes_now(face, body, face_move, path))
    {
      continue;
    }
    if (t >= 1.0 || (pusher_[body] != kNoBody && pushed_at_[body] <= t))
    {
      continue;
    }
    t = std::max(t, 0.0);
    // A free body on a turning face keeps its own move: the face's turn
    // lifts it where the substep ends (push_ahead).
    const bool moves_on = t == 0.0 && !held && toi_[body] >= 1.0 && turn != 0.0;
    toi_[body] = held ? 0.0 : moves_on ? 1.0 : t * toi_[body];  // where on its path the face meets it
    pusher_[body] = face;
    pushed_at_[body] = t;
  }
}

/// Whether the face, touching the body now, closes on it as it moves
/// `face_move` (m) while the body moves `path` (m).
bool WorldMotion::closes_now(std::size_t face, std::size_t body, Vec2 face_move, Vec2 path)
{
  // A closing within the touch tolerance is round-off of a body that moves
  // with the face.
  const double tolerance = impact_tolerance(face, body);
  Manifold m;
  return touch_manifold(body, face, Vec2{0.0, 0.0}, Vec2{0.0, 0.0}, 0.0, m) &&
         dot(face_move - path, m.normal) > tolerance;
}

void WorldMotion::find_pushes(double h)
{
  const std::size_t n = bodies_.size();
  push_.assign(n, Vec2{0.0, 0.0});
  last_pushed_.clear();
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t face = pusher_[i];
    if (face != kNoBody)
    {
      push_[i] = push_ahead(i, face, pushed_at_[i], substep_displacement(i, h) * toi_[i],
                            FaceMove{substep_displacement(face, h), face_turn(face, h)});
      last_pushed_.push_back(i);
    }
  }
  in_last_round_.assign(n, 0);
  int rounds = 0;
  while (rounds < kMaxPushRounds && pass_pushes_on(h))
  {
    ++rounds;
  }
}

void WorldMotion::apply_pushes(double h, bool stored)
{
  // Added before the substep's move (move_body, move_in_frame), which
  // adds each body's own move up to its stop.
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (pusher_[i] == kNoBody)
    {
      continue;
    }
    if (stored)
    {
      bodies_[i].set_position(bodies_[i].position() + push_[i]);
      continue;
    }
    // The soft step holds a stopped body for the rest of the frame; a
    // pushed one moves on. Its stop goes into the push and its move is the
    // whole substep's, so it is neither stopped nor held.
    frame_position_[i] = frame_position_[i] + (push_[i] - substep_displacement(i, h) * (1.0 - toi_[i]));
    toi_[i] = 1.0;
    stopped_[i] = false;
  }
}

/// One round of that chain: the bodies last_pushed_ strike; false if none.
bool WorldMotion::pass_pushes_on(double h)
{
  if (last_pushed_.empty())
  {
    return false;
  }
  // The pushed bodies' boxes grow by their pushes; the others keep the sweep's.
  for (std::size_t p : last_pushed_)
  {
    in_last_round_[p] = 1;
    boxes_[p] = bodies_[p].aabb().swept(pushed_path(p, h));
  }
  sweep_phase_.find_pairs(boxes_, pairs_);
  next_pushed_.clear();
  for (const BodyPair& pair : pairs_)
  {
    for (const auto& [p, q] : {std::pair{pair.first, pair.second}, std::pair{pair.second, pair.first}})
    {
      if (in_last_round_[p] && awake_dynamic(q) && pusher_[q] != p)
      {
        push_on(p, q, h);
      }
    }
  }
  for (std::size_t p : last_pushed_)
  {
    in_last_round_[p] = 0;
  }
  last_pushed_.swap(next_pushed_);
  return !last_pushed_.empty();
}

/// Pushed body p meets body q on its way: q is pushed if p reaches it first.
void WorldMotion::push_on(std::size_t p, std::size_t q, double h)
{
  // A body is pushed by what reaches it first: no later than where it
  // stops (a stop at the same time, up to round-off, is this impact's).
  const Vec2 path = pushed_path(p, h);
  const double t = time_of_impact(bodies_[p], path, bodies_[q], substep_displacement(q, h));
  if (!(t <= toi_[q] + kSameImpact) || (pusher_[q] != kNoBody && pushed_at_[q] < t))
  {
    return;
  }
  const Vec2 push = push_ahead(q, p, t, substep_displacement(q, h) * t, FaceMove{path, 0.0});
  if (t <= 0.0 && push.x == 0.0 && push.y == 0.0)
  {
    return;  // touching already, and not closing: the velocity stage's
  }
  toi_[q] = t;
  pushed_at_[q] = t;
  pusher_[q] = p;
  push_[q] = push;
  next_pushed_.push_back(q);
}

Vec2 WorldMotion::push_ahead(std::size_t i, std::size_t k, double t, Vec2 body_move, FaceMove face)
{
  // A free body touching a turning face moves on (press_touching_faces):
  // it meets the face at the substep's start.
  const bool moves_on = face.turn != 0.0 && t <= 0.0 && toi_[i] >= 1.0;
  Manifold m;
  if (!touch_manifold(i, k, moves_on ? Vec2{0.0, 0.0} : body_move, face.move * t, face.turn * t, m))
  {
    return Vec2{0.0, 0.0};
  }
  // A face moving away from the body along the normal pushes nothing.
  const double advance = face_advance(k, m, face.move * t, face.move, face.turn);
  if (face.turn == 0.0)
  {
    return ((1.0 - t) * std::max(0.0, advance)) * m.normal;
  }
  if (moves_on)
  {
    return lift_on_turning_face(i, k, body_move, face, m);
  }
  return !(advance > 0.0) ? Vec2{0.0, 0.0} : carry_on_turning_face(i, k, t, body_move, face, m.normal);
}

Vec2 WorldMotion::lift_on_turning_face(std::size_t i, std::size_t k, Vec2 body_move, FaceMove face, const Manifold& m)
{
  // In the face's frame the body's own straight move falls behind the
  // turning face; it is lifted back to touching, where detection finds it.
  const Body& f = bodies_[k];
  const Vec2 start = bodies_[i].position() - f.position();
  const Vec2 end = bodies_[i].position() + body_move - (f.position() + face.move);
  double c = 1.0;
  double s = 0.0;
  turn_of(face.turn, c, s);
  const Vec2 turned_normal = rotate(m.normal, c, s);
  const double touching_height = dot(start, m.normal) - deepest_separation(m);
  return std::max(0.0, touching_height - dot(end, turned_normal)) * turned_normal;
}

Vec2 WorldMotion::carry_on_turning_face(std::size_t i, std::size_t k, double t, Vec2 body_move, FaceMove face,
                                      Vec2 normal)
{
  // A struck body is carried round with the face (a push along the first
  // normal would fall behind a face that turns far) and pushed by the
  // centroid's advance along the normal; where the substep ends it is put
  // touching the face, which the carry leaves only to first order.
  const Vec2 arm = bodies_[i].position() + body_move - (bodies_[k].position() + face.move * t);
  double c = 1.0;
  double s = 0.0;
  turn_of((1.0 - t) * face.turn, c, s);
  const Vec2 push = (rotate(arm, c, s) - arm) + ((1.0 - t) * std::max(0.0, dot(face.move, normal))) * normal;
  Manifold end;
  if (!touch_manifold(i, k, body_move + push, face.move, face.turn, end))
  {
    return push;
  }
  return push - deepest_separation(end) * end.normal;
}

/// How far the material points of face k at manifold m's points move
/// along its normal (m) as the face, offset by `k_offset`, moves `move`
/// and turns `turn` (rad): the fastest of them.
double WorldMotion::face_advance(std::size_t k, const Manifold& m, Vec2 k_offset, Vec2 move, double turn) const
{
  if (turn == 0.0)
  {
    return dot(move, m.normal);
  }
  // A turning face's point at the contact moves by the turn about the
  // centroid as well; the fastest of the manifold's points sets the push.
  const Vec2 centroid = bodies_[k].position() + k_offset;
  double advance = -std::numeric_limits<double>::infinity();
  for (int p = 0; p < m.count; ++p)
  {
    advance = std::max(advance, dot(move + cross(turn, m.points[p].point - centroid), m.normal));
  }
  return advance;
}

/// How near (m) bodies i and k count as touching at a time of impact:
/// the touch tolerance, widened for the round-off of posing them there.
double WorldMotion::impact_tolerance(std::size_t i, std::size_t k) const
{
  return kImpactNormalToleranceScale * kRelativeTouchTolerance * (bodies_[i].radius() + bodies_[k].radius());
}

/// The manifold from body k into body i with i moved by `i_move`, k by
/// `k_move` and turned by `k_turn`, if they touch there within
/// impact_tolerance (false otherwise).
bool WorldMotion::touch_manifold(std::size_t i, std::size_t k, Vec2 i_move, Vec2 k_move, double k_turn, Manifold& m)
{
  // Both bodies posed for the narrow phase, then put back. Two disks on one
  // centre have no normal (collide would throw).
  Body& body = bodies_[i];
  Body& face = bodies_[k];
  const Vec2 body_at = body.position();
  const Vec2 face_at = face.position();
  const double face_theta = face.theta();
  body.set_position(body_at + i_move);
  face.set_position(face_at + k_move);
  if (k_turn != 0.0)
  {
    face.set_theta(face_theta + k_turn);
  }
  const bool coincident =
      face.shape() == Shape::Disk && body.shape() == Shape::Disk && face.position() == body.position();
  const bool touching = !coincident && collide(face, body, m, impact_tolerance(i, k));
  body.set_position(body_at);
  face.set_position(face_at);
  if (k_turn != 0.0)
  {
    face.set_theta(face_theta);
  }
  return touching;
}

Vec2 WorldMotion::pushed_path(std::size_t i, double h) const
{
  return substep_displacement(i, h) * toi_[i] + push_[i];
}

}  // namespace detail
}  // namespace collision2d
