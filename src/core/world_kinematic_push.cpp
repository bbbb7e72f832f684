// The Fx2D order finds contacts at the poses a substep ends at, so a
// kinematic body (a robot's link, which no contact slows) that moves past
// most of a body in one substep would end inside it or beyond it. It is
// swept like a fast dynamic body: the body it strikes is stopped at the
// time of impact, as a clamped body is, and then pushed ahead of the
// kinematic face by the face's advance along the contact normal over the
// rest of the substep. The pair ends the substep touching, detection counts
// it (a stopped body's touch tolerance), and the velocity stage gives the
// body the face's normal velocity (with its restitution).
// The soft step needs none of this: its speculative margin grows by a
// kinematic body's reach in the frame (world_contacts.cpp).
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

}  // namespace

double WorldImpl::kinematic_reach_sq(std::size_t i) const
{
  if (bodies_[i].type() != BodyType::Kinematic)
  {
    return -1.0;
  }
  // As for a dynamic body (sweep_reach_sq): a relative move past the sum of
  // the two thinnest half-widths can pass through.
  const double reach = settings_.toi_displacement_fraction * (inner_radius_[i] + min_inner_radius_);
  return reach * reach;
}

void WorldImpl::note_pusher(std::size_t i, std::size_t other)
{
  // The pair with body i's earliest impact decides whether it is pushed.
  if (pushing_)
  {
    pusher_[i] = bodies_[other].type() == BodyType::Kinematic && awake_dynamic(i) ? other : kNoPusher;
  }
}

void WorldImpl::note_touching_face(std::size_t i, std::size_t j)
{
  const bool i_is_face = bodies_[i].type() == BodyType::Kinematic && swept_[i];
  const std::size_t face = i_is_face ? i : j;
  const std::size_t body = i_is_face ? j : i;
  if (bodies_[face].type() == BodyType::Kinematic && swept_[face] && awake_dynamic(body))
  {
    touching_faces_.push_back(BodyPair{face, body});
  }
}

void WorldImpl::press_touching_faces(double h)
{
  // A body touching a fast face moves with it once the velocity stage has
  // run. One that an impact has slowed since, or that stops at its time of
  // impact with another body, would let the face run through it.
  for (const auto& [face, body] : touching_faces_)
  {
    Manifold m;
    const double tolerance = kImpactNormalToleranceScale * kRelativeTouchTolerance *
                             (bodies_[face].radius() + bodies_[body].radius());
    const Vec2 closing = substep_displacement(face, h) - substep_displacement(body, h) * toi_[body];
    if (collide(bodies_[face], bodies_[body], m, tolerance) && dot(closing, m.normal) > 0.0)
    {
      toi_[body] = 0.0;
      pusher_[body] = face;
    }
  }
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
      const Vec2 face_move = substep_displacement(face, h);
      push_[i] = push_ahead(i, face, h, face_move * toi_[i], face_move);
      last_pushed_.push_back(i);
    }
  }
  in_last_round_.assign(n, 0);
  for (int round = 0; round < kMaxPushRounds && pass_pushes_on(h); ++round)
  {
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
      // A body is pushed by what reaches it first: no later than where it
      // stops (a stop at the same time is this impact's).
      if (!in_last_round_[p] || !awake_dynamic(q))
      {
        continue;
      }
      const Vec2 path = pushed_path(p, h);
      const double t = time_of_impact(bodies_[p], path, bodies_[q], substep_displacement(q, h));
      if (!(t <= toi_[q]) || pusher_[q] == p)
      {
        continue;
      }
      const double stopped_at = toi_[q];
      toi_[q] = t;
      const Vec2 push = push_ahead(q, p, h, path * t, path);
      if (t <= 0.0 && push.x == 0.0 && push.y == 0.0)
      {
        toi_[q] = stopped_at;  // touching already, and not closing: the velocity stage's
        continue;
      }
      pusher_[q] = p;
      push_[q] = push;
      next_pushed_.push_back(q);
    }
  }
  for (std::size_t p : last_pushed_)
  {
    in_last_round_[p] = 0;
  }
  last_pushed_.swap(next_pushed_);
  return !last_pushed_.empty();
}

Vec2 WorldImpl::push_ahead(std::size_t i, std::size_t k, double h, Vec2 face_before, Vec2 face_move)
{
  // Both bodies posed at the impact for the narrow phase, then put back.
  const double t = toi_[i];
  Body& body = bodies_[i];
  Body& face = bodies_[k];
  const Vec2 body_at = body.position();
  const Vec2 face_at = face.position();
  body.set_position(body_at + substep_displacement(i, h) * t);
  face.set_position(face_at + face_before);
  Manifold m;
  const double tolerance = kImpactNormalToleranceScale * kRelativeTouchTolerance * (body.radius() + face.radius());
  const bool touching = collide(face, body, m, tolerance);
  body.set_position(body_at);
  face.set_position(face_at);
  // The normal points from the face into the body; a face moving away
  // from the body along it pushes nothing.
  const double advance = touching ? (1.0 - t) * std::max(0.0, dot(face_move, m.normal)) : 0.0;
  return advance * m.normal;
}

Vec2 WorldImpl::pushed_path(std::size_t i, double h) const
{
  return substep_displacement(i, h) * toi_[i] + push_[i];
}

}  // namespace detail
}  // namespace collision2d
