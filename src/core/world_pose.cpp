// The polygons' outlines at their poses, laid out once per detection so that
// each pair a body is in, and its broad-phase box, reuse the turned vertices.
#include <algorithm>

#include "posed_polygon.h"
#include "world_impl.h"

namespace collision2d
{
namespace detail
{
void WorldImpl::pose_bodies()
{
  const std::size_t n = bodies_.size();
  if (!body_pass_full_ && posed_offset_.size() == n)
  {
    // A resting body's outline is where the frame that made it rest put it.
    for_each_body([this](std::size_t i) { pose_range(i, i + 1, false); });
    return;
  }
  // Only an edit changes a body's vertex count, and the bodies' records are
  // cold here: the offsets are laid out again after one. Only an edit moves
  // a static body too: without one since the last layout, whose pass posed
  // every body, a static outline stands (a ground posed once, not every frame).
  const bool edited = posed_offset_.size() != n || posed_version_ != version_;
  if (edited)
  {
    posed_offset_.resize(n);
    std::size_t total = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      posed_offset_[i] = total;
      total += 2 * bodies_[i].vertex_count();
    }
    posed_vertices_.resize(total);
    posed_version_ = version_;
  }
  workers_.parallel_for(n, kMinSharedBodies, [this, edited](std::size_t begin, std::size_t end) {
    pose_range(begin, end, !edited);
  });
}

/// Poses bodies [begin, end), all but the static ones with `skip_static`.
void WorldImpl::pose_range(std::size_t begin, std::size_t end, bool skip_static)
{
  for (std::size_t i = begin; i < end; ++i)
  {
    const Body& b = bodies_[i];
    if (skip_static && b.type() == BodyType::Static)
    {
      continue;
    }
    Vec2* vertices = posed_vertices_.data() + posed_offset_[i];
    pose_polygon(b, vertices, vertices + b.vertex_count());
  }
}

PosedPolygon WorldImpl::posed(std::size_t i) const
{
  const Body& b = bodies_[i];
  if (b.shape() == Shape::Disk)
  {
    return {&b, nullptr, nullptr};
  }
  const Vec2* vertices = posed_vertices_.data() + posed_offset_[i];
  return {&b, vertices, vertices + b.vertex_count()};
}

Aabb WorldImpl::posed_box(std::size_t i) const
{
  // Body::aabb() turns the polygon's vertices again, from a block of their
  // own; the outline just laid out holds the same sums (world_vertex_of).
  const PosedPolygon p = posed(i);
  if (p.vertices == nullptr)
  {
    return bodies_[i].aabb();
  }
  Aabb box{p.vertices[0], p.vertices[0]};
  for (const Vec2* v = p.vertices + 1; v != p.normals; ++v)
  {
    box.lo = {std::min(box.lo.x, v->x), std::min(box.lo.y, v->y)};
    box.hi = {std::max(box.hi.x, v->x), std::max(box.hi.y, v->y)};
  }
  return box;
}

}  // namespace detail
}  // namespace collision2d
