// Internal to the core: the soft step's contact rows in colours. Each frame
// the two-point manifolds whose normal block is solvable, and the one-point
// manifolds, are packed four to a batch (struct of arrays, a batch type for
// each) and coloured so that no two manifolds of one colour move the same
// body; a colour's batches can then be solved eight (two batches at once),
// four or two lanes at a time (chosen at run time) with exactly the bits of
// the scalar path, since lanes never share a body. Nearly dependent
// two-point manifolds, the few of a colour that a batch would mostly pad,
// and any that find no colour stay on the kernel's point verbs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "contact_kernel.h"
#include "worker_pool.h"

namespace collision2d
{
namespace detail
{
/// Lanes in one batch.
constexpr int kRowLanes = 4;

/// Set in a batch's body index when the rows never change that body's
/// velocity (a static or kinematic body, the spare body). Many lanes of one
/// colour may name such a body, and workers run a colour's batches at once:
/// the passes read it but never write it back, so no two workers write one body.
/// Indices stay below it: 2^31 bodies would take terabytes.
constexpr std::uint32_t kFixedBody = 1u << 31;
/// The body a batch's index names, without the kFixedBody bit.
inline std::uint32_t body_of(std::uint32_t index) { return index & ~kFixedBody; }
/// Where a pass writes the velocity of the body `index` names: `discard`
/// for a fixed body.
inline BodyVelocity& written_body(std::vector<BodyVelocity>& state, std::uint32_t index, BodyVelocity& discard)
{
  return (index & kFixedBody) != 0 ? discard : state[index];
}

/// One point of each lane's manifold (its flags are its batch's RowFlags).
struct alignas(32) RowPoint
{
  double ra_x[kRowLanes], ra_y[kRowLanes], rb_x[kRowLanes], rb_y[kRowLanes];  ///< lever arms (m)
  double base[kRowLanes];     ///< gap at prepare less the anchors' offset (m)
  double anchor[kRowLanes];   ///< slip since sticking, at prepare (m)
  double normal[kRowLanes];   ///< accumulated normal impulse (N s)
  double tangent[kRowLanes];  ///< accumulated tangential impulse (N s)
};

/// A batch's flags, one byte (0 or 1) per lane, beside its body indices.
/// Every pass streams the batches through memory: as doubles the flags took
/// a seventh of a two-point batch's bytes.
template <int Points>
struct RowFlags
{
  std::uint8_t rough[kRowLanes];            ///< friction acts
  std::uint8_t kinetic[Points][kRowLanes];  ///< slid before: the kinetic cone applies
  std::uint8_t sliding[Points][kRowLanes];  ///< friction at its bound
};

/// Four two-point manifolds, one per lane.
struct alignas(32) RowBatch
{
  std::uint32_t a[kRowLanes];  ///< body indices (kFixedBody marks those never written); padding names the spare body
  std::uint32_t b[kRowLanes];
  RowFlags<2> flags;
  alignas(32) double nx[kRowLanes];  ///< the normal (the lanes' loads need 32-byte alignment after the flags)
  double ny[kRowLanes];              ///< the tangent is perp(normal), as prepared
  double k11[kRowLanes], k12[kRowLanes], k22[kRowLanes];  ///< normal block (1/kg)
  double pair_tangent_mass[kRowLanes];                ///< kg
  double inv_mass_a[kRowLanes], inv_mass_b[kRowLanes], inv_inertia_a[kRowLanes], inv_inertia_b[kRowLanes];
  double bias_rate[kRowLanes], mass_scale[kRowLanes];  ///< the pair's softness
  double mu_s[kRowLanes], mu_k[kRowLanes];
  RowPoint point[2];
};

/// Four one-point manifolds, one per lane (a disk's contacts): the point
/// verbs' normal and friction rows.
struct alignas(32) RowSingle
{
  std::uint32_t a[kRowLanes];  ///< body indices (kFixedBody marks those never written); padding names the spare body
  std::uint32_t b[kRowLanes];
  RowFlags<1> flags;
  alignas(32) double nx[kRowLanes];  ///< as RowBatch's
  double ny[kRowLanes];
  double normal_mass[kRowLanes], tangent_mass[kRowLanes];  ///< kg
  double inv_mass_a[kRowLanes], inv_mass_b[kRowLanes], inv_inertia_a[kRowLanes], inv_inertia_b[kRowLanes];
  double bias_rate[kRowLanes], mass_scale[kRowLanes];
  double mu_s[kRowLanes], mu_k[kRowLanes];
  RowPoint point[1];
};
// Every pass streams the batches: their sizes are kept in sight.
static_assert(sizeof(RowBatch) == 1024 && sizeof(RowSingle) == 704, "a batch's bytes changed");

/// What every row of one pass shares.
struct RowPass
{
  double inv_h = 0.0;       ///< 1/s
  double max_push = 0.0;    ///< m/s
  bool use_bias = false;    ///< false: the relax pass
};

/// What a point's solve leaves: its accumulated impulses (N s) and whether
/// its friction ended at its bound.
struct PointOutcome
{
  double normal = 0.0;
  double tangent = 0.0;
  bool sliding = false;
};

/// A point's outcome as the point itself holds it (its manifold was solved
/// on the point verbs, or the rows are not in use).
inline PointOutcome own_outcome(const ContactPoint& p) { return {p.lambda_n, p.lambda_t, p.sliding}; }

/// A colour's batches of one kind: [begin, end) of their vector.
struct RowRange
{
  std::size_t begin = 0;
  std::size_t end = 0;
  std::size_t lanes = 0;  ///< manifolds in the batches; the last batch may be padded
};

/// One colour: its batches of two-point manifolds (in rows_) and of
/// one-point ones (in singles_), and the points it leaves to the point verbs
/// (the index of each manifold's first point).
struct RowColour
{
  RowRange pairs;
  RowRange singles;
  std::vector<std::size_t> others;
};

/// The frame's manifolds in colours. The World walks the colours in order:
/// each colour's batches (solve_rows), then its other manifolds on the point
/// verbs, and the overflow last. A frame of one or two manifolds has no
/// colours: they go to the overflow, from the top down.
class SoftRows
{
public:
  /// Before prepare: the frame has this many points, each to be noted once.
  void expect_points(std::size_t points);
  /// At prepare, for each active manifold's first point k (its second point,
  /// if any, prepared): what colouring needs, read while the points are in
  /// cache. `up` is against gravity, any length (zero keeps point order).
  /// A manifold against a static body goes after all the others. Safe
  /// from several workers for distinct k.
  void note_manifold(std::size_t k, const ContactPoint& p, const ContactPoint* second, Vec2 up);
  /// ... and for every other point.
  void note_no_manifold(std::size_t k);
  /// After note_manifold(k): that manifold stays on the point verbs (its
  /// points change within the frame in ways a packed row would not see).
  void keep_on_point_verbs(std::size_t k);
  /// Colours and packs this frame's noted manifolds (prepared, soft terms
  /// set; their springs from `springs`), the highest first; the lanes are
  /// filled by the workers. Below kMinColouredManifolds they are only
  /// ordered, the highest first.
  /// `velocity` gains one spare body at its end for the padding lanes.
  /// The rows take `block` (FrameBlock: nothing else in it is alive from
  /// here until the contacts are published).
  void pack(ContactPoints& points, std::vector<BodyVelocity>& velocity, bool friction,
            const ContactSprings& springs, WorkerPool& workers, FrameBlock& block);
  /// Colours in use: the greedy colouring takes the lowest free one, so
  /// they are 0 .. colour_count() - 1.
  std::size_t colour_count() const { return used_colours_; }
  const std::vector<std::size_t>& others(std::size_t colour) const { return colours_[colour].others; }
  const std::vector<std::size_t>& overflow() const { return overflow_; }
  /// Manifolds in colours (rows and others), not counting the overflow.
  std::size_t coloured() const { return coloured_; }
  /// A colour's batches of both kinds, or part `part` of `parts` of them
  /// (the parts share no body); nothing for a colour without batches.
  void warm_start_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, std::size_t part = 0,
                       std::size_t parts = 1);
  void solve_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, const RowPass& pass, std::size_t part = 0,
                  std::size_t parts = 1);
  /// Where point k's accumulated impulses live while the rows are packed:
  /// its lane of a row, or both nullptr when its manifold is solved on the
  /// point verbs (the point's own fields are then current).
  ImpulseSlots impulses_of(std::size_t k);
  /// After the passes: the spare body that pack added leaves `velocity`.
  /// The rows stay packed until point_outcome has read each point's.
  void drop_spare_body(std::vector<BodyVelocity>& velocity) const;
  /// Point k's impulses and friction state: from its row if it has one,
  /// else `p`'s own (its manifold was solved on the point verbs).
  PointOutcome point_outcome(std::size_t k, const ContactPoint& p) const
  {
    const RowSlot slot = row_slot(k);
    if (slot.point == nullptr)
    {
      return own_outcome(p);
    }
    return {slot.point->normal[slot.lane], slot.point->tangent[slot.lane], slot.sliding[slot.lane] != 0};
  }

private:
  /// Fewer manifolds than this are solved in height order without colours:
  /// for one or two it is the order the colours give, so the bits are the
  /// same without the colouring's fixed cost (docs/performance.md).
  static constexpr std::size_t kMinColouredManifolds = 3;
  /// Notes (contact points) below which packing stays on the calling
  /// thread: a manifold costs tens of nanoseconds, waking the workers microseconds.
  static constexpr std::size_t kMinSharedNotes = 2048;
  /// How many parts the packing of this frame's notes takes (1: not shared).
  std::size_t parts_for(const WorkerPool& workers) const
  {
    return notes_.size() >= kMinSharedNotes ? static_cast<std::size_t>(workers.workers()) : 1;
  }
  /// Colours tried before a manifold goes to the overflow: a box in a stack
  /// touches at most six others, so greedy colouring needs far fewer.
  static constexpr std::size_t kMaxColours = 24;
  /// A manifold's body that cannot move, for take_colour.
  static constexpr std::uint32_t kFixed = UINT32_MAX;
  /// How a manifold is solved.
  enum class Kind : std::uint8_t
  {
    Other,  ///< on the point verbs
    Pair,   ///< in a batch of two-point manifolds
    Single  ///< in a batch of one-point manifolds
  };
  /// Per point, from prepare: what colouring reads of the manifold that
  /// starts there, and the colour it took.
  struct Note
  {
    std::uint32_t key = 0;     ///< the static ones last, then descending in height
    std::uint32_t a = kFixed;  ///< the bodies the manifold moves
    std::uint32_t b = kFixed;
    std::uint8_t colour = 0;   ///< below kMaxColours
    bool first = false;        ///< an active manifold starts at this point
    bool against_static = false;  ///< one of its bodies is static
    Kind kind = Kind::Other;   ///< how it is solved (once coloured)
  };

  /// The noted manifolds' keys in order_, from the highest down
  /// (soft_rows_order.cpp), in parts on the workers for a large frame.
  void order_manifolds(WorkerPool& workers);
  /// Part `part` of `parts` of order_manifolds' stage `stage`: 0 counts its
  /// notes' manifolds, 1 writes their keys after the earlier parts' and sorts
  /// them, 2 merges its share of every part's keys into sort_scratch_.
  void order_part(std::size_t stage, std::size_t part, std::size_t parts);
  /// No colours and no rows: every ordered manifold to the overflow.
  void order_without_colours();
  /// Empties the colours (the last frame's only) and the overflow.
  void clear_colours();
  /// Colours every ordered manifold from the highest down (soft_rows_colour.cpp)
  /// and counts each colour's rows; `bodies` counts the spare one.
  void colour_manifolds(std::size_t bodies);
  /// Gives each row manifold its place in its colour's batches, in point
  /// order, and fills its lane; in parts on the workers for a large frame.
  void place_rows(const ContactPoints& points, bool friction, WorkerPool& workers);
  /// Part `part` of `parts` of place_rows: its share of the points' rows
  /// counted by colour and kind into part_counts_ ...
  void count_rows_part(std::size_t part, std::size_t parts);
  /// ... and placed (with one part, part_counts_ is not read).
  void place_rows_part(std::size_t part, std::size_t parts, const ContactPoints& points, bool friction);
  /// Whether a note is a row manifold's first point, and its counts' index.
  static bool is_row(const Note& m) { return m.first && m.kind != Kind::Other; }
  static std::size_t row_index(const Note& m) { return 2 * std::size_t{m.colour} + (m.kind == Kind::Single ? 1 : 0); }
  /// A row manifold's lane: `slot` among its colour's rows of its kind.
  void fill_lane(const ContactPoints& points, std::size_t first, const Note& m, std::size_t slot,
                 bool friction);
  /// The first colour free of bodies a and b (kFixed: one that cannot
  /// move), now taken by them; kMaxColours when none is free. Against a
  /// static body, the colour after the moving body's last, if there is one:
  /// the ground then has the last word on a body pressed into it.
  std::size_t take_colour(std::uint32_t a, std::uint32_t b, bool against_static);
  /// A colour's batches of a kind (Pair or Single).
  RowRange& range_of(std::size_t colour, Kind kind);
  /// Whether a colour has batches (a small frame's colours often have none).
  bool batched(std::size_t colour) const
  {
    return colours_[colour].pairs.lanes + colours_[colour].singles.lanes > 0;
  }
  /// Each colour's batches of `kind` in whole batches, the last one padded;
  /// returns the batch count.
  std::size_t place_batches(Kind kind);
  /// Where a point's row is: its batch's point and sliding flags, and its lane.
  struct RowSlot
  {
    const RowPoint* point = nullptr;  ///< nullptr when its manifold has no row
    const std::uint8_t* sliding = nullptr;
    int lane = 0;
  };
  RowSlot row_slot(std::size_t k) const
  {
    const std::uint32_t at = k < lane_of_.size() ? lane_of_[k] : kNoLane;
    if (at == kNoLane)
    {
      return {};
    }
    if ((at & kSingleLane) != 0)
    {
      const std::uint32_t single = at & ~kSingleLane;
      const RowSingle& batch = singles_[single / kRowLanes];
      return {&batch.point[0], batch.flags.sliding[0], static_cast<int>(single % kRowLanes)};
    }
    const RowBatch& batch = rows_[at / (2 * kRowLanes)];
    return {&batch.point[at % 2], batch.flags.sliding[at % 2], static_cast<int>(at / 2 % kRowLanes)};
  }

  FrameSpan<RowBatch> rows_;  ///< in the World's frame block, then singles_ after them
  FrameSpan<RowSingle> singles_;
  std::vector<RowColour> colours_;
  std::size_t used_colours_ = 0;
  std::vector<std::size_t> overflow_;    ///< manifolds no colour could take, solved last in order
  std::vector<std::uint32_t> colours_of_;  ///< per body, a bit per colour that moves it
  /// Per point: where its row keeps it, (batch * kRowLanes + lane) * 2 + its
  /// place in the manifold, or kSingleLane | (batch * kRowLanes + lane) for a
  /// one-point manifold; kNoLane for a point without a row.
  std::vector<std::uint32_t> lane_of_;
  static constexpr std::uint32_t kNoLane = UINT32_MAX;
  static constexpr std::uint32_t kSingleLane = 0x80000000U;
  FrameBuffer<Note> notes_;  ///< per point, written at prepare
  /// Scratch: per manifold, its height key (high half) and its first point
  /// (low half), sorted.
  FrameBuffer<std::uint64_t> order_;
  FrameBuffer<std::uint64_t> sort_scratch_;
  /// Scratch of the work in parts: each part's count of whatever it counts
  /// in its first stage (its manifolds, or its rows by colour and kind),
  /// kPartCounts entries a part (apart, so no two parts write one cache line).
  std::vector<std::uint32_t> part_counts_;
  static constexpr std::size_t kPartCounts = 256;
  /// place_rows: the manifolds each part leaves to the point verbs, as
  /// (colour, first point), in point order.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> part_others_;
  std::size_t coloured_ = 0;
  std::uint32_t spare_ = 0;              ///< index of the padding lanes' body
  ContactSprings springs_;               ///< the frame's contact springs, which the lanes take
};

/// The lane paths of the rows, all giving the same bits: one lane at a time,
/// two (SSE2 on x86-64, NEON on aarch64), four (AVX2) or eight (AVX-512: two
/// batches at once).
enum class RowLanes
{
  Scalar,
  Two,
  Four,
  Eight
};
/// Whether a path is compiled in and this CPU runs it (Scalar always).
bool row_lanes_available(RowLanes lanes);
/// The path the rows take: the widest available unless set_row_lanes chose one.
RowLanes row_lanes();
/// Tests and benchmarks: force a path; false (and no change) if it is not available.
bool set_row_lanes(RowLanes lanes);
/// Back to the widest available path.
void reset_row_lanes();

/// One batch of either kind (RowBatch or RowSingle) on the chosen path;
/// `lanes` counts its manifolds (the rest are padding).
template <class Batch>
void warm_start_batch(RowLanes path, Batch& batch, int lanes, std::vector<BodyVelocity>& velocity);
template <class Batch>
void solve_batch(RowLanes path, Batch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass);

/// The kernel entry points over one batch of either kind (soft_rows_kernel.h),
/// each instantiated for both. The eight-lane ones (over two batches) live in
/// soft_rows_avx512.cpp, the four-lane ones in soft_rows_avx2.cpp, the
/// two-lane ones in soft_rows_lanes2.cpp; a build without their instructions
/// makes them a narrower path, never chosen.
template <class Batch>
void warm_start_batch_scalar(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity);
template <class Batch>
void solve_batch_scalar(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass);
bool four_lanes_compiled();
template <class Batch>
void warm_start_batch_four(Batch& batch, std::vector<BodyVelocity>& velocity);
template <class Batch>
void solve_batch_four(Batch& batch, std::vector<BodyVelocity>& velocity, const RowPass& pass);
bool eight_lanes_compiled();
/// Two neighbouring batches of one colour: `first` and the one after it.
template <class Batch>
void warm_start_batches_eight(Batch& first, std::vector<BodyVelocity>& velocity);
template <class Batch>
void solve_batches_eight(Batch& first, std::vector<BodyVelocity>& velocity, const RowPass& pass);
bool two_lanes_compiled();
template <class Batch>
void warm_start_batch_two(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity);
template <class Batch>
void solve_batch_two(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass);

/// Instantiates a batch verb template for both kinds of batch.
#define COLLISION2D_ROW_BATCH_VERBS(verb, ...)                                                                  \
  template void verb<RowBatch>(RowBatch&, __VA_ARGS__);                                                          \
  template void verb<RowSingle>(RowSingle&, __VA_ARGS__)

}  // namespace detail
}  // namespace collision2d
