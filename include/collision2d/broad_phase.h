// Broad phase: candidate pairs whose bounding boxes overlap, in time linear in
// the bodies plus the pairs for scattered scenes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "collision2d/aabb.h"

namespace collision2d
{
using BodyPair = std::pair<std::size_t, std::size_t>;

/// Runs a job over [0, count), cut into parts that may run at once on
/// several threads (the World's workers); returns when every part is done.
class RangeRunner
{
public:
  /// A job: processes items [begin, end) with its context.
  using Job = void (*)(void* context, std::size_t begin, std::size_t end);
  virtual ~RangeRunner() = default;
  /// How many parts a run is cut into at most.
  virtual int workers() const = 0;
  virtual void run(std::size_t count, Job job, void* context) = 0;
};

/// Uniform grid (spatial hash) sized from the boxes themselves, with the few
/// boxes much larger than a cell (a ground slab, container walls) kept out of
/// the grid and queried against it. Keeps its scratch buffers between calls,
/// so a world that calls it every substep allocates nothing once warmed up.
class BroadPhase
{
public:
  /// Replaces `pairs` with every (i, j), i < j, whose boxes overlap
  /// (Aabb::overlaps, touching counts), sorted by (i, j) and unique. A box with
  /// a non-finite coordinate or with lo > hi on an axis is empty: it pairs with
  /// nothing.
  void find_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs);
  /// As above, the grid's cells searched in parts by `runner` when there are
  /// enough of them; the pairs are the same for any runner.
  void find_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner& runner);
  /// Up to this many boxes every pair is tested: fewer tests than the grid's
  /// fixed work of placing, classifying, filling and sorting.
  static constexpr std::size_t kAllPairsBoxes = 8;

private:
  /// Inclusive range of grid cells a box covers.
  struct CellRange
  {
    std::int32_t x0;
    std::int32_t y0;
    std::int32_t x1;
    std::int32_t y1;
  };
  /// One (cell, box) incidence; entries_ holds them grouped by hash bucket.
  struct Entry
  {
    std::int32_t cx;
    std::int32_t cy;
    std::size_t box;
  };

  /// The lowest corner of some boxes (none yet: any is false).
  struct LowCorner
  {
    bool any = false;
    double x = 0.0;
    double y = 0.0;
    void lower(double lo_x, double lo_y)
    {
      x = any ? std::min(x, lo_x) : lo_x;
      y = any ? std::min(y, lo_y) : lo_y;
      any = true;
    }
  };
  /// Where a box goes: nowhere, the grid, or the large boxes.
  enum class BoxClass : unsigned char
  {
    Unusable,
    Grid,
    Large
  };
  /// Origin of the cell indices every call, cell size every few calls.
  void place_grid(const std::vector<Aabb>& boxes, RangeRunner* runner);
  void choose_cell_size(const std::vector<Aabb>& boxes);
  CellRange cells_of(const Aabb& box) const;
  /// Each box's cells and class, then the grid boxes and the large ones
  /// listed in box order, with each grid box's first entry and the cells the
  /// grid covers (in parts with a runner, the lists as one pass makes them).
  void classify(const std::vector<Aabb>& boxes, RangeRunner* runner);
  /// What classify counts of some boxes; for a part, then where its lists start.
  struct GridLayout
  {
    std::size_t grid = 0;   ///< boxes in the grid
    std::size_t large = 0;  ///< boxes too large for it
    std::size_t entries = 0;
    CellRange occupied{0, 0, -1, -1};  ///< the grid boxes' cells (none: empty)
    /// Counts a grid box covering `cells`.
    void add_grid_box(const CellRange& cells);
    /// Adds another part's count.
    void add(const GridLayout& other);
  };
  /// classify on the calling thread alone (no runner, or too few boxes to share).
  void list_in_one_pass(const std::vector<Aabb>& boxes);
  /// Classes boxes [begin, end) and counts them.
  GridLayout count_classes(const std::vector<Aabb>& boxes, std::size_t begin, std::size_t end);
  /// Lists the classed boxes [begin, end) from `at` on.
  void list_classes(std::size_t begin, std::size_t end, GridLayout at);
  /// Box i's class, its cells stored in ranges_ when usable.
  BoxClass classify_box(const std::vector<Aabb>& boxes, std::size_t i);
  void find_pairs_with(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner* runner);
  /// At most kAllPairsBoxes boxes: every pair tested, no grid.
  static void all_pairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs);
  /// The grid's entries by counting sort; with a runner, in parts of the
  /// boxes, each part's entries placed where one pass would put them.
  void fill_grid(RangeRunner* runner);
  void fill_grid_in_parts(RangeRunner& runner, std::size_t parts, std::size_t bucket_count);
  /// Part `part` of `parts` of the grid boxes: hashes their entries, counting them per bucket.
  void count_entries(std::size_t part, std::size_t parts, std::size_t bucket_count);
  /// ... and writes them at their part's bucket cursors.
  void scatter_entries(std::size_t part, std::size_t parts, std::size_t bucket_count);
  /// Dense or hashed bucket layout for this call; returns the bucket count.
  std::size_t choose_layout(std::size_t entry_count);
  std::size_t bucket_of(std::int32_t cx, std::int32_t cy) const;
  bool owns(std::int32_t cx, std::int32_t cy, std::size_t a, std::size_t b) const;

  /// The grid's pairs and the large boxes', sorted, replace `pairs`.
  void pairs_in_grid(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner* runner);
  /// Part `part` of `parts`: its share of the buckets searched, each pair
  /// listed under the part that owns its first box.
  void search_part(const std::vector<Aabb>& boxes, std::size_t part, std::size_t parts);
  /// The pairs found in buckets [begin, end), each passed to add(i, j).
  template <class Add>
  void pairs_in_buckets(const std::vector<Aabb>& boxes, std::size_t begin, std::size_t end, Add& add);
  template <class Add>
  void pairs_in_bucket(const std::vector<Aabb>& boxes, std::size_t begin, std::size_t end, Add& add);
  void pairs_of_large(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs);
  void large_against_grid(const std::vector<Aabb>& boxes, std::size_t large, std::vector<BodyPair>& pairs) const;
  /// Each owner's share of the boxes: about an equal share of the boxes
  /// and the last call's pairs (a scene's pairs crowd where it is densest).
  void choose_owners(std::size_t box_count, std::size_t parts);
  /// The owner whose share holds `box` (the owners are few: a walk).
  std::size_t owner_of(std::size_t box) const
  {
    std::size_t owner = 0;
    while (box >= owner_box_[owner + 1])
    {
      ++owner;
    }
    return owner;
  }
  /// Each owner sorts the pairs it owns, with the large boxes' among them,
  /// into its own stretch of `pairs`: a counting sort on the first box, then
  /// each box's few partners sorted.
  void sort_by_owner(std::size_t box_count, std::size_t parts, RangeRunner* runner, std::vector<BodyPair>& pairs);
  void sort_owned(std::size_t owner, std::size_t parts, std::vector<BodyPair>& sorted);

  // Grid geometry of the current call.
  double cell_ = 1.0;
  double inv_cell_ = 1.0;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  CellRange occupied_{0, 0, -1, -1};  // bounding range of the grid boxes' cells
  std::size_t bucket_mask_ = 0;        // hashed layout
  std::int64_t dense_width_ = 0;       // dense layout: cells per row of the occupied range (0: hashed)

  // When the cell size was chosen.
  std::size_t calls_since_cell_ = 0;  // calls left before it is chosen again
  std::size_t cell_box_count_ = 0;    // number of boxes it was chosen for

  // Scratch kept between calls.
  std::vector<double> extents_;          // box sizes, for the percentile
  std::vector<CellRange> ranges_;        // per box
  std::vector<std::size_t> grid_boxes_;  // boxes stored in the grid
  std::vector<std::size_t> large_;       // boxes too large for the grid
  std::vector<std::size_t> bucket_start_;
  std::vector<Entry> entries_;
  std::vector<std::size_t> entry_bucket_;  // when shared: bucket of each entry, in fill order
  /// An entry and its bucket, in fill order before scattering (not shared).
  /// 32-bit indices: 2^32 boxes would take 128 GiB of boxes alone.
  struct StagedEntry
  {
    std::int32_t cx;
    std::int32_t cy;
    std::uint32_t box;
    std::uint32_t bucket;
  };
  std::vector<StagedEntry> staged_;
  std::vector<std::size_t> pair_start_;
  /// A list of pairs that one part fills: on a cache line of its own, so
  /// that two parts adding pairs do not write the same line.
  struct alignas(64) PartPairs
  {
    std::vector<BodyPair> pairs;
  };
  std::vector<PartPairs> part_pairs_;      // the grid's pairs by searching part, then owner part
  std::vector<BodyPair> large_pairs_;     // the large boxes' pairs
  std::vector<std::size_t> owner_box_;    // each owner's first box, and the box count
  std::vector<std::size_t> owner_start_;  // where each owner's stretch of the result starts
  std::vector<std::size_t> first_entry_;  // each grid box's first entry
  std::vector<std::size_t> part_count_;   // when shared: per part and bucket, a count, then a cursor
  std::vector<LowCorner> corners_;        // each part's lowest corner
  std::vector<BoxClass> box_class_;       // when shared: each box's class
  std::vector<GridLayout> part_layouts_;  // when shared: classify's count of each part
  std::size_t entry_count_ = 0;           // the grid boxes' entries (classify)
};

}  // namespace collision2d
