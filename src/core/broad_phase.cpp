// Broad phase on a uniform grid. Each box is
// entered in the cells it covers and only boxes sharing a cell are compared,
// so a scattered scene costs O(n + pairs) instead of the O(n^1.5) a sweep
// along one axis costs when the bodies fill a square.
//
// The cell is a high percentile of the box sizes, so most boxes cover at most
// 2 x 2 cells whatever the scene's scale. The few boxes spanning many cells (a
// ground slab, container walls) would each fill a whole row of cells: they are
// kept out of the grid, swept against each other and looked up in the grid
// cells they cover instead (broad_phase_grid.cpp).
#include "collision2d/broad_phase.h"
#include "broad_phase_parts.h"
#include "scratch_buffer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace collision2d
{
namespace
{
/// Share of boxes no larger than one cell: high enough that a scene of two
/// body sizes gets cells of the larger (many small boxes per cell are swept
/// within it) rather than sending the larger half out of the grid.
constexpr double kCellPercentile = 0.75;
/// Cell side over that percentile size. Cells twice a box's size are
/// covered 1.5 x 1.5 times on average, against 2 x 2 for cells of one size:
/// fewer grid entries to write and scatter, for a few more boxes per cell.
constexpr double kCellsPerSize = 2.0;
/// Boxes covering more cells than this along an axis are not stored in the
/// grid: with the percentile above they are at most a quarter of the boxes,
/// and in practice the few static slabs and walls.
constexpr std::int32_t kMaxCellsPerSide = 4;
/// Cell indices are clamped to this magnitude so that ranges and areas stay
/// integer-exact; clamping is monotone, so the grid only gets coarser far out.
constexpr double kCellIndexLimit = 536870912.0;  // 2^29 cells
/// Cell size when the boxes are points spread over nothing (all identical).
constexpr double kFallbackCell = 1.0;  // m
/// Calls between two choices of the cell size. The cell only sets the cost
/// of a call, never its pairs, and box sizes barely change between substeps,
/// so the percentile (a selection over every box) is not redone each call;
/// a change in the number of boxes redoes it at once.
constexpr std::size_t kCellRefreshCalls = 16;

std::int32_t cell_index(double v, double origin, double inv_cell)
{
  // The origin is the lowest corner, so v - origin >= 0 and truncation is
  // the floor (std::floor is a library call on baseline x86-64). It may
  // overflow to +inf for huge finite coordinates: the clamp takes it back
  // into range. Multiplying by the inverse cell is as monotone in v as
  // dividing, which is all that keeps overlapping boxes in a shared cell.
  const double c = (v - origin) * inv_cell;
  return static_cast<std::int32_t>(std::clamp(c, 0.0, kCellIndexLimit));
}

bool positive_finite(double v)
{
  return std::isfinite(v) && v > 0.0;
}

}  // namespace

void BroadPhase::find_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs)
{
  find_pairs_with(boxes, pairs, nullptr);
}

void BroadPhase::find_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner& runner)
{
  find_pairs_with(boxes, pairs, &runner);
}

void BroadPhase::find_pairs_with(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner* runner)
{
  // The pairs end sorted, so the order the parts found them in does not show.
  if (boxes.size() <= kAllPairsBoxes)
  {
    pairs.clear();
    all_pairs(boxes, pairs);
    return;
  }
  place_grid(boxes, runner);
  classify(boxes, runner);
  fill_grid(runner);
  pairs_in_grid(boxes, pairs, runner);  // broad_phase_grid.cpp
}

void BroadPhase::all_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs)
{
  // Each box checked once, an unusable one kept as an empty box (lo above
  // hi) that overlaps nothing; then one branch per pair, not one per
  // comparison: in a frame's few boxes the outcomes change as bodies meet and part.
  // The pairs come out in (i, j) order, sorted as the grid's pairs end.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::size_t n = boxes.size();
#if defined(__SSE2__)
  // A corner's x and y side by side: two-lane compares test both axes at once
  // (lo_i <= hi_j and lo_j <= hi_i), the same comparisons as Aabb::overlaps.
  __m128d lo[kAllPairsBoxes];
  __m128d hi[kAllPairsBoxes];
  for (std::size_t i = 0; i < n; ++i)
  {
    const __m128d l = _mm_loadu_pd(&boxes[i].lo.x);
    const __m128d h = _mm_loadu_pd(&boxes[i].hi.x);
    const bool usable = detail::is_usable(l, h);
    lo[i] = usable ? l : _mm_set1_pd(kInf);
    hi[i] = usable ? h : _mm_set1_pd(-kInf);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t j = i + 1; j < n; ++j)
    {
      const __m128d overlap = _mm_and_pd(_mm_cmple_pd(lo[i], hi[j]), _mm_cmple_pd(lo[j], hi[i]));
      if (_mm_movemask_pd(overlap) == detail::kBothAxes)
      {
        pairs.emplace_back(i, j);
      }
    }
  }
#else
  constexpr Aabb kEmpty{{kInf, kInf}, {-kInf, -kInf}};
  std::array<Aabb, kAllPairsBoxes> box;
  for (std::size_t i = 0; i < n; ++i)
  {
    box[i] = detail::is_usable(boxes[i]) ? boxes[i] : kEmpty;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t j = i + 1; j < n; ++j)
    {
      if (box[i].overlaps(box[j]))
      {
        pairs.emplace_back(i, j);
      }
    }
  }
#endif
}

void BroadPhase::place_grid(const std::vector<Aabb>& boxes, RangeRunner* runner)
{
  // Cell indices are taken from the lowest corner so that scenes far from the
  // world origin keep their precision. Each part's lowest corner, then the
  // parts' in order: std::min keeps the first of equal values either way.
  const std::size_t parts = detail::runner_parts(runner, boxes.size());
  corners_.assign(parts, LowCorner{});
  const auto lowest = [&](std::size_t part) {
    LowCorner c;  // a local: the parts' corners share a cache line
    for (std::size_t i = detail::part_begin(boxes.size(), part, parts);
         i < detail::part_begin(boxes.size(), part + 1, parts); ++i)
    {
      if (detail::is_usable(boxes[i]))
      {
        c.lower(boxes[i].lo.x, boxes[i].lo.y);
      }
    }
    corners_[part] = c;
  };
  detail::for_each_part(runner, parts, lowest);
  LowCorner low;
  for (const LowCorner& c : corners_)
  {
    if (c.any)
    {
      low.lower(c.x, c.y);
    }
  }
  origin_x_ = low.x;
  origin_y_ = low.y;
  if (calls_since_cell_ == 0 || boxes.size() != cell_box_count_)
  {
    choose_cell_size(boxes);
    cell_box_count_ = boxes.size();
    calls_since_cell_ = kCellRefreshCalls;
  }
  --calls_since_cell_;
  inv_cell_ = 1.0 / cell_;
}

void BroadPhase::choose_cell_size(const std::vector<Aabb>& boxes)
{
  extents_.clear();
  double top_lo_x = 0.0;  // highest low corner: with the origin, the spread of boxes
  double top_lo_y = 0.0;
  for (const Aabb& box : boxes)
  {
    if (!detail::is_usable(box))
    {
      continue;
    }
    const bool first = extents_.empty();
    top_lo_x = first ? box.lo.x : std::max(top_lo_x, box.lo.x);
    top_lo_y = first ? box.lo.y : std::max(top_lo_y, box.lo.y);
    extents_.push_back(std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y));
  }
  if (extents_.empty())
  {
    cell_ = kFallbackCell;
    return;
  }
  const auto rank = static_cast<std::size_t>(kCellPercentile * static_cast<double>(extents_.size() - 1));
  std::nth_element(extents_.begin(), extents_.begin() + static_cast<std::ptrdiff_t>(rank), extents_.end());
  cell_ = kCellsPerSize * extents_[rank];
  if (!positive_finite(cell_))
  {
    // Mostly points: one cell per body on average over the occupied square.
    const double spread = std::max(top_lo_x - origin_x_, top_lo_y - origin_y_);
    cell_ = spread / std::sqrt(static_cast<double>(extents_.size()));
  }
  if (!positive_finite(cell_))
  {
    cell_ = kFallbackCell;
  }
}

BroadPhase::CellRange BroadPhase::cells_of(const Aabb& box) const
{
  return {cell_index(box.lo.x, origin_x_, inv_cell_), cell_index(box.lo.y, origin_y_, inv_cell_),
          cell_index(box.hi.x, origin_x_, inv_cell_), cell_index(box.hi.y, origin_y_, inv_cell_)};
}

void BroadPhase::classify(const std::vector<Aabb>& boxes, RangeRunner* runner)
{
  const std::size_t n = boxes.size();
  const std::size_t parts = detail::runner_parts(runner, n);
  ranges_.resize(n);
  if (parts == 1)
  {
    list_in_one_pass(boxes);
    return;
  }
  // Counted in parts, then each part's lists written from where the parts
  // before it end: the lists one pass in box order makes.
  box_class_.resize(n);
  part_layouts_.resize(parts);
  detail::run_parts(*runner, parts, [&](std::size_t part) {
    part_layouts_[part] =
        count_classes(boxes, detail::part_begin(n, part, parts), detail::part_begin(n, part + 1, parts));
  });
  GridLayout whole;
  for (GridLayout& layout : part_layouts_)
  {
    const GridLayout counted = layout;
    layout = GridLayout{whole.grid, whole.large, whole.entries, CellRange{}};  // where the part's lists start
    whole.add(counted);
  }
  detail::resize_to_overwrite(grid_boxes_, whole.grid);
  detail::resize_to_overwrite(first_entry_, whole.grid);
  detail::resize_to_overwrite(large_, whole.large);
  detail::run_parts(*runner, parts, [&](std::size_t part) {
    list_classes(detail::part_begin(n, part, parts), detail::part_begin(n, part + 1, parts), part_layouts_[part]);
  });
  entry_count_ = whole.entries;
  occupied_ = whole.occupied;
}

void BroadPhase::list_in_one_pass(const std::vector<Aabb>& boxes)
{
  // The lists, then the entries: letting the lists and first_entry_ grow in
  // turn left a large rain's heap with a higher peak (docs/performance.md).
  grid_boxes_.clear();
  large_.clear();
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    const BoxClass c = classify_box(boxes, i);
    if (c != BoxClass::Unusable)
    {
      (c == BoxClass::Large ? large_ : grid_boxes_).push_back(i);
    }
  }
  GridLayout whole;
  first_entry_.resize(grid_boxes_.size());
  for (std::size_t k = 0; k < grid_boxes_.size(); ++k)
  {
    first_entry_[k] = whole.entries;
    whole.add_grid_box(ranges_[grid_boxes_[k]]);
  }
  entry_count_ = whole.entries;
  occupied_ = whole.occupied;
}

BroadPhase::GridLayout BroadPhase::count_classes(const std::vector<Aabb>& boxes, std::size_t begin, std::size_t end)
{
  GridLayout counted;  // in locals: the parts' slots share a cache line
  for (std::size_t i = begin; i < end; ++i)
  {
    box_class_[i] = classify_box(boxes, i);
    if (box_class_[i] == BoxClass::Grid)
    {
      counted.add_grid_box(ranges_[i]);
    }
    counted.large += box_class_[i] == BoxClass::Large ? 1 : 0;
  }
  return counted;
}

void BroadPhase::list_classes(std::size_t begin, std::size_t end, GridLayout at)
{
  for (std::size_t i = begin; i < end; ++i)
  {
    if (box_class_[i] == BoxClass::Grid)
    {
      const CellRange& r = ranges_[i];
      grid_boxes_[at.grid] = i;
      first_entry_[at.grid++] = at.entries;
      at.entries += static_cast<std::size_t>(detail::cell_area(r.x0, r.y0, r.x1, r.y1));
    }
    else if (box_class_[i] == BoxClass::Large)
    {
      large_[at.large++] = i;
    }
  }
}

void BroadPhase::GridLayout::add_grid_box(const CellRange& cells)
{
  add(GridLayout{1, 0, static_cast<std::size_t>(detail::cell_area(cells.x0, cells.y0, cells.x1, cells.y1)), cells});
}

void BroadPhase::GridLayout::add(const GridLayout& other)
{
  const CellRange& o = other.occupied;
  occupied = other.grid == 0 ? occupied
             : grid == 0     ? o
                             : CellRange{std::min(occupied.x0, o.x0), std::min(occupied.y0, o.y0),
                                         std::max(occupied.x1, o.x1), std::max(occupied.y1, o.y1)};
  grid += other.grid;
  large += other.large;
  entries += other.entries;
}

BroadPhase::BoxClass BroadPhase::classify_box(const std::vector<Aabb>& boxes, std::size_t i)
{
  if (!detail::is_usable(boxes[i]))
  {
    return BoxClass::Unusable;
  }
  const CellRange r = cells_of(boxes[i]);
  ranges_[i] = r;
  const bool large = r.x1 - r.x0 >= kMaxCellsPerSide || r.y1 - r.y0 >= kMaxCellsPerSide;
  return large ? BoxClass::Large : BoxClass::Grid;
}

bool BroadPhase::owns(std::int32_t cx, std::int32_t cy, std::size_t a, std::size_t b) const
{
  // Two overlapping boxes share every cell of their intersection; the one
  // holding its low corner reports the pair, so it is reported once.
  return std::max(ranges_[a].x0, ranges_[b].x0) == cx && std::max(ranges_[a].y0, ranges_[b].y0) == cy;
}

void BroadPhase::pairs_of_large(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs)
{
  // Large boxes among themselves: a sweep along x, they are few.
  std::sort(large_.begin(), large_.end(),
            [&boxes](std::size_t a, std::size_t b) { return boxes[a].lo.x < boxes[b].lo.x; });
  for (std::size_t k = 0; k < large_.size(); ++k)
  {
    const Aabb& box = boxes[large_[k]];
    for (std::size_t m = k + 1; m < large_.size() && boxes[large_[m]].lo.x <= box.hi.x; ++m)
    {
      if (box.overlaps(boxes[large_[m]]))
      {
        pairs.emplace_back(std::min(large_[k], large_[m]), std::max(large_[k], large_[m]));
      }
    }
    large_against_grid(boxes, large_[k], pairs);
  }
}

}  // namespace collision2d
