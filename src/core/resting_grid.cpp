// The resting bodies' grid (resting_grid.h). Cells are keyed by (column,
// row) in one sorted list; a pair is reported from the cell holding the low
// corner of the two boxes' intersection, so once.
#include "resting_grid.h"

#include "broad_phase_parts.h"

#include <algorithm>
#include <cmath>

namespace collision2d
{
namespace detail
{
namespace
{
/// The cell edge is the median box size times this: most boxes cover one to four cells.
constexpr double kCellsPerSize = 1.0;
/// Boxes spanning more cells than this per side are kept out of the grid and
/// tested against every query (a ground slab).
constexpr std::int64_t kMaxCellsPerSide = 4;
/// Boxes reaching beyond this many cells from the origin are kept out too.
constexpr double kCellLimit = 536870912.0;  // 2^29
/// With this few resting boxes (a ground and walls) every one counts as large.
constexpr std::size_t kFewMembers = 32;
/// A query covering more cells than this tests every member instead.
constexpr std::int64_t kMaxQueryCells = 1024;

}  // namespace

std::uint64_t RestingGrid::key_of(std::int64_t cx, std::int64_t cy) const
{
  return (static_cast<std::uint64_t>(cx) << 32) | static_cast<std::uint64_t>(cy);
}

std::int64_t RestingGrid::cell_x(double x) const
{
  return static_cast<std::int64_t>(std::floor(std::clamp((x - origin_x_) * inv_cell_, -1.0, kCellLimit)));
}

std::int64_t RestingGrid::cell_y(double y) const
{
  return static_cast<std::int64_t>(std::floor(std::clamp((y - origin_y_) * inv_cell_, -1.0, kCellLimit)));
}

void RestingGrid::build(const std::vector<Aabb>& boxes, const std::vector<std::size_t>& members)
{
  members_.clear();
  entries_.clear();
  extents_.clear();
  origin_x_ = 0.0;
  origin_y_ = 0.0;
  bool any = false;
  for (std::size_t i : members)
  {
    const Aabb& b = boxes[i];
    if (!is_usable(b))
    {
      continue;
    }
    extents_.push_back(std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y));
    origin_x_ = any ? std::min(origin_x_, b.lo.x) : b.lo.x;
    origin_y_ = any ? std::min(origin_y_, b.lo.y) : b.lo.y;
    any = true;
  }
  if (!extents_.empty())
  {
    auto middle = extents_.begin() + static_cast<std::ptrdiff_t>(extents_.size() / 2);
    std::nth_element(extents_.begin(), middle, extents_.end());
    cell_ = *middle > 0.0 && std::isfinite(*middle) ? kCellsPerSize * *middle : 1.0;
  }
  inv_cell_ = 1.0 / cell_;
  x1_ = -1;
  y1_ = -1;
  // Grid members first, large ones after.
  large_.clear();
  const bool few = extents_.size() <= kFewMembers;
  for (std::size_t i : members)
  {
    const Aabb& b = boxes[i];
    if (!is_usable(b))
    {
      continue;
    }
    Member m{b, i, cell_x(b.lo.x), cell_y(b.lo.y)};
    const std::int64_t x1 = cell_x(b.hi.x);
    const std::int64_t y1 = cell_y(b.hi.y);
    const bool far = (b.hi.x - origin_x_) * inv_cell_ >= kCellLimit || (b.hi.y - origin_y_) * inv_cell_ >= kCellLimit;
    if (few || far || x1 - m.x0 >= kMaxCellsPerSide || y1 - m.y0 >= kMaxCellsPerSide)
    {
      large_.push_back(m);
      continue;
    }
    x1_ = std::max(x1_, x1);
    y1_ = std::max(y1_, y1);
    for (std::int64_t cx = m.x0; cx <= x1; ++cx)
    {
      for (std::int64_t cy = m.y0; cy <= y1; ++cy)
      {
        entries_.push_back(Entry{key_of(cx, cy), static_cast<std::uint32_t>(members_.size())});
      }
    }
    members_.push_back(m);
  }
  large_begin_ = members_.size();
  members_.insert(members_.end(), large_.begin(), large_.end());
  large_bodies_.clear();
  for (const Member& m : large_)
  {
    large_bodies_.push_back(m.body);
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& p, const Entry& q) {
    return p.key < q.key || (p.key == q.key && p.member < q.member);
  });
}

void RestingGrid::visit(const Member& m, const Aabb& box, std::size_t mover, std::vector<BodyPair>& pairs) const
{
  if (m.body != mover && box.overlaps(m.box))
  {
    pairs.emplace_back(std::min(mover, m.body), std::max(mover, m.body));
  }
}

void RestingGrid::query(const Aabb& box, std::size_t mover, std::vector<BodyPair>& pairs) const
{
  if (!is_usable(box))
  {
    return;
  }
  if (entries_.empty())
  {
    return;
  }
  // The query's cells, clipped to the occupied ones (a lower bound clipped
  // to 0 leaves the low-corner test unchanged: every member's is >= 0).
  const std::int64_t x0 = std::max<std::int64_t>(0, cell_x(box.lo.x));
  const std::int64_t y0 = std::max<std::int64_t>(0, cell_y(box.lo.y));
  const std::int64_t x1 = std::min(x1_, cell_x(box.hi.x));
  const std::int64_t y1 = std::min(y1_, cell_y(box.hi.y));
  if (x0 > x1 || y0 > y1)
  {
    return;
  }
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxQueryCells)
  {
    for (std::size_t k = 0; k < large_begin_; ++k)
    {
      visit(members_[k], box, mover, pairs);
    }
    return;
  }
  for (std::int64_t cx = x0; cx <= x1; ++cx)
  {
    for (std::int64_t cy = y0; cy <= y1; ++cy)
    {
      const std::uint64_t key = key_of(cx, cy);
      auto it = std::lower_bound(entries_.begin(), entries_.end(), key,
                                 [](const Entry& e, std::uint64_t k) { return e.key < k; });
      for (; it != entries_.end() && it->key == key; ++it)
      {
        const Member& m = members_[it->member];
        if (std::max(m.x0, x0) == cx && std::max(m.y0, y0) == cy)
        {
          visit(m, box, mover, pairs);
        }
      }
    }
  }
}

}  // namespace detail
}  // namespace collision2d
