// Broad phase by sort and sweep (SPEC section 2 "Detection"): boxes are
// sorted by their low end along the axis where the box centres spread most,
// and each box is only compared with the boxes that start before it ends.
// For scattered scenes this is O(n log n + pairs), not O(n^2).
//
// The sorted order is kept between calls: a scene that moves a little between
// calls is nearly sorted already and an insertion sort restores it in O(n).
// When the order changed a lot (first call, axis switch, teleports) the
// insertion sort gives up after a bounded number of moves and a full sort
// takes over, so the worst case stays O(n log n).
#include "collision2d/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace collision2d
{
namespace
{
/// Element moves allowed per box before the insertion sort hands over to a
/// full sort.
constexpr std::size_t kInsertionMovesPerBox = 8;

enum class Axis
{
  X,
  Y
};

double along(Vec2 v, Axis axis)
{
  return axis == Axis::X ? v.x : v.y;
}

Vec2 centre(const Aabb& box)
{
  return 0.5 * (box.lo + box.hi);
}

/// Axis with the larger variance of box centres. Centres are taken relative to
/// the first one so that scenes far from the origin keep their precision.
Axis axis_of_largest_spread(const std::vector<Aabb>& boxes)
{
  if (boxes.empty())
  {
    return Axis::X;
  }
  const Vec2 origin = centre(boxes.front());
  Vec2 sum;
  Vec2 sum_sq;
  for (const Aabb& box : boxes)
  {
    const Vec2 c = centre(box) - origin;
    sum += c;
    sum_sq += Vec2{c.x * c.x, c.y * c.y};
  }
  const double n = static_cast<double>(boxes.size());
  const double var_x = sum_sq.x / n - (sum.x / n) * (sum.x / n);
  const double var_y = sum_sq.y / n - (sum.y / n) * (sum.y / n);
  return var_y > var_x ? Axis::Y : Axis::X;
}

/// A NaN end would break the strict weak order std::sort relies on; such a
/// box is sent to the far end, where it starts after everything and so pairs
/// with nothing.
double sortable(double v)
{
  return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
}

template <class Endpoint>
bool lower_start(const Endpoint& p, const Endpoint& q)
{
  return p.lo < q.lo;
}

/// Insertion sort that stops after `budget` element moves; returns whether it
/// finished.
template <class Endpoint>
bool insertion_sort(std::vector<Endpoint>& v, std::size_t budget)
{
  std::size_t moves = 0;
  for (std::size_t i = 1; i < v.size(); ++i)
  {
    const Endpoint item = v[i];
    std::size_t j = i;
    for (; j > 0 && lower_start(item, v[j - 1]); --j)
    {
      v[j] = v[j - 1];
      if (++moves > budget)
      {
        v[j - 1] = item;  // keep the vector a permutation before giving up
        return false;
      }
    }
    v[j] = item;
  }
  return true;
}

}  // namespace

void BroadPhase::find_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs)
{
  pairs.clear();
  const Axis axis = axis_of_largest_spread(boxes);
  // Same count: refresh the ends in the previous order (a permutation of the
  // indices), which is nearly sorted for a coherent scene.
  if (sorted_.size() != boxes.size())
  {
    sorted_.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
      sorted_[i].index = i;
    }
  }
  for (Endpoint& e : sorted_)
  {
    e.lo = sortable(along(boxes[e.index].lo, axis));
    e.hi = along(boxes[e.index].hi, axis);
  }
  if (!insertion_sort(sorted_, kInsertionMovesPerBox * sorted_.size()))
  {
    std::sort(sorted_.begin(), sorted_.end(), lower_start<Endpoint>);
  }
  for (std::size_t i = 0; i < sorted_.size(); ++i)
  {
    const Endpoint& e = sorted_[i];
    for (std::size_t j = i + 1; j < sorted_.size() && sorted_[j].lo <= e.hi; ++j)
    {
      const std::size_t other = sorted_[j].index;
      if (boxes[e.index].overlaps(boxes[other]))
      {
        pairs.emplace_back(std::min(e.index, other), std::max(e.index, other));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace collision2d
