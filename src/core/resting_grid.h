// Internal to the core: the boxes of bodies that do not move (static,
// sleeping, still kinematic) in a uniform grid built when that set changes,
// so that a frame's broad phase looks only from the moving bodies' boxes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision2d/aabb.h"
#include "collision2d/broad_phase.h"

namespace collision2d
{
namespace detail
{
class RestingGrid
{
public:
  /// The grid of boxes[i] for i in `members` (ascending); unusable boxes
  /// (non-finite, lo > hi) pair with nothing, as in BroadPhase.
  void build(const std::vector<Aabb>& boxes, const std::vector<std::size_t>& members);
  /// Appends (min, max) of (mover, member) for every member whose box
  /// overlaps `box` (closed intervals), each once, in no particular order.
  /// Large members (and every member when there are only a few) are not
  /// queried: the caller pairs them with the movers (BroadPhase handles a
  /// few large boxes well). Ascending body indices.
  const std::vector<std::size_t>& large() const { return large_bodies_; }
  /// No member in the grid (every resting box, if any, is large).
  bool empty() const { return entries_.empty(); }
  void query(const Aabb& box, std::size_t mover, std::vector<BodyPair>& pairs) const;

private:
  struct Member
  {
    Aabb box;
    std::size_t body;
    std::int64_t x0;  ///< lowest cell (grid members)
    std::int64_t y0;
  };
  struct Entry
  {
    std::uint64_t key;
    std::uint32_t member;
  };
  std::uint64_t key_of(std::int64_t cx, std::int64_t cy) const;
  std::int64_t cell_x(double x) const;
  std::int64_t cell_y(double y) const;
  void visit(const Member& m, const Aabb& box, std::size_t mover, std::vector<BodyPair>& pairs) const;

  double cell_ = 1.0;
  double inv_cell_ = 1.0;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  std::int64_t x1_ = -1;  ///< highest occupied cell; the lowest is 0
  std::int64_t y1_ = -1;
  std::vector<Member> members_;     ///< grid members, then large ones from large_begin_
  std::size_t large_begin_ = 0;
  std::vector<Entry> entries_;      ///< (cell, member) sorted by cell
  std::vector<double> extents_;     ///< build's scratch
  std::vector<Member> large_;
  std::vector<std::size_t> large_bodies_;
};

}  // namespace detail
}  // namespace collision2d
