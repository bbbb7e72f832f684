// Soft step: a pair's manifold kept across frames. While the pair's relative
// pose stays close to the one its manifold was detected at, the frame keeps
// that manifold's normal, lever arms and features and follows each point's
// gap from the bodies' pose changes, as the substeps do within a frame. A
// resting stack then keeps the contact geometry it settled with: detecting
// again each frame re-aims each normal along its lower box's tilt and moves
// its points with the tilt, which lets a tall column buckle under its load
// (docs/performance.md, the nudged column).
#include <algorithm>
#include <cmath>

#include "turn.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// A kept manifold's bodies may each turn this much at most (the cosine of
/// about 1 degree; a resting stack's boxes turn far less). Its normal does not turn
/// with them, so a pair turning together (a box on a tilting platform) has
/// its normal off by up to this angle until it is detected again.
constexpr double kMinKeptCos = 0.99985;
// Every turn a manifold is kept for is summed by turn_of's series, not the
// library: cos(x) <= 1 - x^2/2 + x^4/24, so cos(kSeriesTurn) lies below the bound.
static_assert(1.0 - kSeriesTurn * kSeriesTurn / 2.0 + kSeriesTurn * kSeriesTurn * kSeriesTurn * kSeriesTurn / 24.0 <
                  kMinKeptCos,
              "a kept manifold's turns fit turn_of's series");

bool same_pair(const WorldContact& c, BodyId a, BodyId b) { return c.a == a && c.b == b; }

}  // namespace

bool WorldImpl::keep_manifold(std::size_t k, std::size_t i, std::size_t j, std::size_t& cursor)
{
  const Body& a = bodies_[i];
  const Body& b = bodies_[j];
  // A disk's contact point moves around it as it rolls: detect again.
  if (reuse_distance_ <= 0.0 || a.shape() == Shape::Disk || b.shape() == Shape::Disk)
  {
    return false;
  }
  const BodyId id_a = ids_[i];
  const BodyId id_b = ids_[j];
  const std::size_t at = cached_pair(cursor, id_a, id_b);
  if (at >= contacts_.size() || !same_pair(contacts_[at], id_a, id_b) || !contacts_[at].origin.known)
  {
    return false;
  }
  const auto first = contacts_.begin() + static_cast<std::ptrdiff_t>(at);
  const ContactOrigin& o = first->origin;
  const double turn_a = a.theta() - o.theta_a;
  const double turn_b = b.theta() - o.theta_b;
  double cos_a = 1.0;
  double sin_a = 0.0;
  double cos_b = 1.0;
  double sin_b = 0.0;
  turn_of(turn_a, cos_a, sin_a);
  turn_of(turn_b, cos_b, sin_b);
  if (cos_a <= kMinKeptCos || cos_b <= kMinKeptCos)
  {
    return false;
  }
  // How far the pair has moved relative to each other since (in a's frame):
  // the centres' offset, and any point turning about b's centre. The offset
  // now, turned back by a's turn since then, lines up with the offset then
  // as it was in the world: a's angle then needs no library call.
  const Vec2 offset_then = o.r_a - o.r_b;
  const Vec2 offset_now = rotate_inv(b.position() - a.position(), cos_a, sin_a);
  const double extent = std::max(a.type() == BodyType::Static ? 0.0 : a.radius(),
                                 b.type() == BodyType::Static ? 0.0 : b.radius());
  const double moved = length(offset_now - offset_then) + extent * std::abs(sin_b * cos_a - cos_b * sin_a);
  if (!(moved < reuse_distance_))
  {
    return false;
  }
  Manifold& m = manifolds_[k];
  kept_from_[k] = at;
  m.normal = first->contact.normal;
  m.count = first + 1 != contacts_.end() && same_pair(first[1], id_a, id_b) ? 2 : 1;
  for (int c = 0; c < m.count; ++c)
  {
    const WorldContact& cached = first[c];
    const Vec2 r_a = rotate(cached.origin.r_a, cos_a, sin_a);
    const Vec2 r_b = rotate(cached.origin.r_b, cos_b, sin_b);
    const double s = cached.origin.separation + dot(b.position() - a.position() + r_b - r_a, m.normal);
    m.points[c] = ManifoldPoint{a.position() + r_a, std::max(0.0, -s), s, cached.contact.feature};
  }
  return true;
}

void WorldImpl::set_new_origin(std::size_t k, ContactPoint& row) const
{
  const Body& a = bodies_[pairs_[k].first];
  const Body& b = bodies_[pairs_[k].second];
  row.r_a = row.point - a.position();
  row.r_b = row.point - b.position();
  row.origin_separation = row.separation;
  row.origin_theta_a = a.theta();
  row.origin_theta_b = b.theta();
  row.origin_known = true;
}

}  // namespace detail
}  // namespace collision2d
