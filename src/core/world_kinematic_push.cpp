// A kinematic body (a robot's link, which no contact slows) that moves past
// most of a body in one substep is swept like a fast dynamic body. A body
// it strikes stops at the time of impact, as a clamped body does, and is
// then pushed ahead of the face by the face's advance along the contact
// normal over the rest of the substep; a body near the face that stops
// against another body while the face closes on it is pushed from where
// the face meets it; a pushed body pushes what it strikes in turn.
// The Fx2D order finds contacts where a substep ends: the pushed pair ends
// touching, detection counts it (a stopped body's touch tolerance), and the
// velocity stage gives the body the face's normal velocity. The soft step's
// frame contact already holds a body ahead of a face (its margin grows by
// the face's reach in the frame), so there only a stopped body is pushed,
// and it is not held for the rest of the frame.
#include <algorithm>

#include "collision2d/collide.h"
#include "collision2d/time_of_impact.h"
#include "collision2d/touch_tolerance.h"
#include "world_impl.h"

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

}  // namespace

void WorldImpl::note_pusher(std::size_t i, std::size_t other)
{
  // The pair with body i's earliest impact decides whether it is pushed.
  const bool pushed = bodies_[other].type() == BodyType::Kinematic && awake_dynamic(i);
  pusher_[i] = pushed ? other : kNoPusher;
  pushed_at_[i] = toi_[i];
}

void WorldImpl::note_touching_face(std::size_t i, std::size_t j)
{
  const std::size_t face = bodies_[i].type() == BodyType::Kinematic ? i : j;
  const std::size_t body = face == i ? j : i;
  if (bodies_[face].type() == BodyType::Kinematic && swept_[face] && awake_dynamic(body))
  {
    touching_faces_.push_back(BodyPair{face, body});
  }
}

void WorldImpl::press_touching_faces(double h, bool soft_substep)
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
    const Vec2 path = held ? Vec2{0.0, 0.0} : substep_displacement(body, h) * toi_[body];
    double t = time_of_impact(bodies_[face], face_move, bodies_[body], path);
    if (t <= 0.0 && !closes_now(face, body, face_move - path))
    {
      continue;
    }
    if (t >= 1.0 || (pusher_[body] != kNoPusher && pushed_at_[body] <= t))
    {
      continue;
    }
    t = std::max(t, 0.0);
    toi_[body] = held ? 0.0 : t * toi_[body];  // where on its path the face meets it
    pusher_[body] = face;
    pushed_at_[body] = t;
  }
}

bool WorldImpl::closes_now(std::size_t face, std::size_t body, Vec2 closing)
{
  // A closing within the touch tolerance is round-off of a body that moves
  // with the face.
  const double tolerance =
      kImpactNormalToleranceScale * kRelativeTouchTolerance * (bodies_[face].radius() + bodies_[body].radius());
  Vec2 normal;
  return touch_normal(body, face, Vec2{0.0, 0.0}, Vec2{0.0, 0.0}, normal) && dot(closing, normal) > tolerance;
}

void WorldImpl::find_pushes(double h)
{
  const std::size_t n = bodies_.size();
  push_.assign(n, Vec2{0.0, 0.0});
  last_pushed_.clear();
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t face = pusher_[i];
    if (face != kNoPusher)
    {
      push_[i] = push_ahead(i, face, pushed_at_[i], substep_displacement(i, h) * toi_[i], substep_displacement(face, h));
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

void WorldImpl::apply_pushes(double h, bool stored)
{
  // Added before the substep's move (move_body, move_in_frame), which
  // adds each body's own move up to its stop.
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (pusher_[i] == kNoPusher)
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

bool WorldImpl::pass_pushes_on(double h)
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

void WorldImpl::push_on(std::size_t p, std::size_t q, double h)
{
  // A body is pushed by what reaches it first: no later than where it
  // stops (a stop at the same time, up to round-off, is this impact's).
  const Vec2 path = pushed_path(p, h);
  const double t = time_of_impact(bodies_[p], path, bodies_[q], substep_displacement(q, h));
  if (!(t <= toi_[q] + kSameImpact) || (pusher_[q] != kNoPusher && pushed_at_[q] < t))
  {
    return;
  }
  const Vec2 push = push_ahead(q, p, t, substep_displacement(q, h) * t, path);
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

Vec2 WorldImpl::push_ahead(std::size_t i, std::size_t k, double t, Vec2 body_move, Vec2 face_move)
{
  Vec2 normal;
  if (!touch_normal(i, k, body_move, face_move * t, normal))
  {
    return Vec2{0.0, 0.0};
  }
  // A face moving away from the body along the normal pushes nothing.
  return ((1.0 - t) * std::max(0.0, dot(face_move, normal))) * normal;
}

bool WorldImpl::touch_normal(std::size_t i, std::size_t k, Vec2 i_move, Vec2 k_move, Vec2& normal)
{
  // Both bodies posed for the narrow phase, then put back. Two disks on one
  // centre have no normal (collide would throw).
  Body& body = bodies_[i];
  Body& face = bodies_[k];
  const Vec2 body_at = body.position();
  const Vec2 face_at = face.position();
  body.set_position(body_at + i_move);
  face.set_position(face_at + k_move);
  const bool coincident =
      face.shape() == Shape::Disk && body.shape() == Shape::Disk && face.position() == body.position();
  const double tolerance = kImpactNormalToleranceScale * kRelativeTouchTolerance * (body.radius() + face.radius());
  Manifold m;
  const bool touching = !coincident && collide(face, body, m, tolerance);
  body.set_position(body_at);
  face.set_position(face_at);
  normal = m.normal;
  return touching;
}

Vec2 WorldImpl::pushed_path(std::size_t i, double h) const
{
  return substep_displacement(i, h) * toi_[i] + push_[i];
}

}  // namespace detail
}  // namespace collision2d
