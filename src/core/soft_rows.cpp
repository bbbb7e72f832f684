// The soft step's rows in colours (soft_rows.h): the coloured manifolds
// (soft_rows_colour.cpp) packed into batches, the passes in colour order and
// the scalar lane path (the choice of path is soft_rows_dispatch.cpp).
#include "soft_rows.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <type_traits>

#include "scratch_buffer.h"
#include "soft_rows_kernel.h"

namespace collision2d
{
namespace detail
{
namespace
{
struct ScalarOps
{
  int j = 0;
  double load(const double* f) const { return f[j]; }
  void store(double* f, double v) const { f[j] = v; }
  bool flag(const std::uint8_t* f) const { return f[j] != 0; }
  bool any(const std::uint8_t* f) const { return rows::any_lane(f); }  // the whole batch, as the wider paths
  void set_flag(std::uint8_t* f, bool where, bool value) const
  {
    if (where)
    {
      f[j] = value ? 1 : 0;
    }
  }
  void gather(const std::vector<BodyVelocity>& state, const std::uint32_t* index, rows::Side<double>& side) const
  {
    const BodyVelocity& s = state[body_of(index[j])];
    side.v = {s.v.x, s.v.y};
    side.w = s.omega;
    side.moved = {s.moved.x, s.moved.y};
    side.c = s.turned_cos;
    side.s = s.turned_sin;
  }
  void scatter(std::vector<BodyVelocity>& state, const std::uint32_t* index, const rows::Side<double>& side) const
  {
    BodyVelocity discard;
    BodyVelocity& s = written_body(state, index[j], discard);
    s.v = Vec2{side.v.x, side.v.y};
    s.omega = side.w;
  }
};

}  // namespace

template <class Batch>
void warm_start_batch_scalar(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity)
{
  for (int j = 0; j < lanes; ++j)
  {
    rows::warm_start_rows<double>(ScalarOps{j}, batch, velocity);
  }
}

template <class Batch>
void solve_batch_scalar(Batch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  for (int j = 0; j < lanes; ++j)
  {
    rows::solve_rows<double>(ScalarOps{j}, batch, velocity, pass);
  }
}

COLLISION2D_ROW_BATCH_VERBS(warm_start_batch_scalar, int, std::vector<BodyVelocity>&);
COLLISION2D_ROW_BATCH_VERBS(solve_batch_scalar, int, std::vector<BodyVelocity>&, const RowPass&);

namespace
{
/// A body the rows never move: no inverse mass (static, kinematic), as the
/// colouring counts it (soft_rows_colour.cpp) and the kernel applies it.
bool fixed(double inv_mass) { return inv_mass == 0.0; }

/// What both kinds of batch keep of a manifold, from its first point.
template <class Batch>
void fill_common(Batch& r, int j, const ContactPoint& p, bool friction, const ContactSprings& springs)
{
  const bool a_fixed = fixed(p.inv_mass_a);
  const bool b_fixed = fixed(p.inv_mass_b);
  r.a[j] = static_cast<std::uint32_t>(p.a) | (a_fixed ? kFixedBody : 0u);
  r.b[j] = static_cast<std::uint32_t>(p.b) | (b_fixed ? kFixedBody : 0u);
  const Softness& spring = springs.of(p);
  r.nx[j] = p.normal.x;
  r.ny[j] = p.normal.y;
  r.inv_mass_a[j] = p.inv_mass_a;
  r.inv_mass_b[j] = p.inv_mass_b;
  r.inv_inertia_a[j] = p.inv_inertia_a;
  r.inv_inertia_b[j] = p.inv_inertia_b;
  r.bias_rate[j] = spring.bias_rate;
  r.mass_scale[j] = spring.mass_scale;
  r.mu_s[j] = p.mu_s;
  r.mu_k[j] = p.mu_k;
  r.flags.rough[j] = friction && has_friction(p) ? 1 : 0;
}

/// Point `at` of lane j's manifold.
template <class Batch>
void fill_point(Batch& r, std::size_t at, int j, const ContactPoint& c)
{
  RowPoint& q = r.point[at];
  q.ra_x[j] = c.r_a.x;
  q.ra_y[j] = c.r_a.y;
  q.rb_x[j] = c.r_b.x;
  q.rb_y[j] = c.r_b.y;
  q.base[j] = c.base_separation;
  q.anchor[j] = c.anchor_drift;
  q.normal[j] = c.lambda_n;
  q.tangent[j] = c.lambda_t;
  r.flags.kinetic[at][j] = c.kinetic ? 1 : 0;
  r.flags.sliding[at][j] = c.sliding ? 1 : 0;
}

/// A padding lane: the spare body on both sides, nothing to push; its
/// masses 1, so no division meets a zero.
template <class Batch>
void fill_padding(Batch& r, int j, std::uint32_t spare)
{
  r.a[j] = spare | kFixedBody;
  r.b[j] = spare | kFixedBody;
  for (double* f : {r.nx, r.ny, r.inv_mass_a, r.inv_mass_b, r.inv_inertia_a, r.inv_inertia_b, r.bias_rate, r.mu_s,
                    r.mu_k})
  {
    f[j] = 0.0;
  }
  r.mass_scale[j] = 1.0;
  r.flags.rough[j] = 0;
  for (std::size_t at = 0; at < std::size(r.point); ++at)
  {
    RowPoint& q = r.point[at];
    for (double* f : {q.ra_x, q.ra_y, q.rb_x, q.rb_y, q.base, q.anchor, q.normal, q.tangent})
    {
      f[j] = 0.0;
    }
    r.flags.kinetic[at][j] = 0;
    r.flags.sliding[at][j] = 0;
  }
}

/// A lane of either kind of batch: manifold `first`'s rows, or padding
/// (SIZE_MAX) whose masses are 1, so no division meets a zero.
template <class Batch>
void fill_manifold(Batch& r, int j, const ContactPoints& points, std::size_t first, bool friction,
                   const ContactSprings& springs, std::uint32_t spare)
{
  constexpr bool pair = std::is_same_v<Batch, RowBatch>;
  const bool padding = first == SIZE_MAX;
  if (padding)
  {
    fill_padding(r, j, spare);
  }
  else
  {
    fill_common(r, j, points[first], friction, springs);
    for (std::size_t k = 0; k < std::size(r.point); ++k)
    {
      fill_point(r, k, j, points[first + k]);
    }
  }
  if constexpr (pair)
  {
    r.k11[j] = padding ? 1.0 : points[first].k_n;
    r.k12[j] = padding ? 0.0 : points[first].pair_k12;
    r.k22[j] = padding ? 1.0 : points[first + 1].k_n;
    r.pair_tangent_mass[j] = padding ? 1.0 : points[first].pair_tangent_mass;
  }
  else
  {
    r.normal_mass[j] = padding ? 1.0 : points[first].normal_mass();
    r.tangent_mass[j] = padding ? 1.0 : points[first].tangent_mass();
  }
}

/// The padding lanes of a colour's last batch of one kind.
template <class Batch>
void pad_batches(const RowRange& range, FrameSpan<Batch>& batches, std::uint32_t spare)
{
  for (std::size_t slot = range.lanes; slot < (range.end - range.begin) * kRowLanes; ++slot)
  {
    fill_manifold(batches[range.begin + slot / kRowLanes], static_cast<int>(slot % kRowLanes), {}, SIZE_MAX, false,
                  ContactSprings{}, spare);
  }
}
}  // namespace

std::size_t SoftRows::place_batches(Kind kind)
{
  std::size_t batches = 0;
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    RowRange& range = range_of(colour, kind);
    range.begin = batches;
    batches += (range.lanes + kRowLanes - 1) / kRowLanes;
    range.end = batches;
  }
  return batches;
}

void SoftRows::pack(ContactPoints& points, std::vector<BodyVelocity>& velocity, bool friction,
                    const ContactSprings& springs, WorkerPool& workers, FrameBlock& block)
{
  springs_ = springs;
  spare_ = static_cast<std::uint32_t>(velocity.size());
  velocity.push_back(body_velocity(Vec2{0.0, 0.0}, 0.0, 0.0, 0.0));
  order_manifolds(workers);                               // soft_rows_order.cpp
  if (order_.size() < kMinColouredManifolds)
  {
    order_without_colours();
    return;
  }
  colour_manifolds(velocity.size());                      // soft_rows_colour.cpp
  // Each colour's rows of each kind in whole batches, the last one padded.
  // Every lane has its own slot, so the workers can fill them in any split.
  // Both kinds in one stretch of the block (the lanes below write every slot).
  const std::size_t pair_batches = place_batches(Kind::Pair);
  const std::size_t single_batches = place_batches(Kind::Single);
  place_together(block, part(rows_, pair_batches), part(singles_, single_batches));
  lane_of_.assign(points.size(), kNoLane);
  place_rows(points, friction, workers);
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    const RowColour& c = colours_[colour];
    pad_batches(c.pairs, rows_, spare_);
    pad_batches(c.singles, singles_, spare_);
  }
}

void SoftRows::place_rows(const ContactPoints& points, bool friction, WorkerPool& workers)
{
  const std::size_t parts = parts_for(workers);
  part_others_.resize(parts);
  if (parts == 1)
  {
    place_rows_part(0, 1, points, friction);
  }
  else
  {
    // Each part counts its rows of each colour and kind; its first place of
    // each then follows the parts' before it.
    resize_to_overwrite(part_counts_, parts * kPartCounts);
    workers.run_stages(2, [&](std::size_t stage, std::size_t part, std::size_t n) {
      stage == 0 ? count_rows_part(part, n) : place_rows_part(part, n, points, friction);
    });
  }
  // The rows past a colour's batches, after the manifolds colouring left to
  // the point verbs, in point order as the parts found them.
  for (const auto& others : part_others_)
  {
    for (const auto& [colour, first] : others)
    {
      colours_[colour].others.push_back(first);
    }
  }
}

void SoftRows::count_rows_part(std::size_t part, std::size_t parts)
{
  std::uint32_t* own = &part_counts_[part * kPartCounts];
  std::fill(own, own + 2 * kMaxColours, 0U);
  for (std::size_t k = notes_.size() * part / parts; k < notes_.size() * (part + 1) / parts; ++k)
  {
    if (is_row(notes_[k]))
    {
      ++own[row_index(notes_[k])];
    }
  }
}

void SoftRows::place_rows_part(std::size_t part, std::size_t parts, const ContactPoints& points, bool friction)
{
  // Within a colour the rows share no body, so their places are free: in
  // point order, as the points lie in memory, after the earlier parts' rows.
  std::array<std::uint32_t, 2 * kMaxColours> next{};
  static_assert(2 * kMaxColours <= kPartCounts, "a part's counts hold every colour and kind");
  for (std::size_t p = 0; p < part; ++p)
  {
    for (std::size_t i = 0; i < next.size(); ++i)
    {
      next[i] += part_counts_[p * kPartCounts + i];
    }
  }
  auto& others = part_others_[part];
  others.clear();
  for (std::size_t k = notes_.size() * part / parts; k < notes_.size() * (part + 1) / parts; ++k)
  {
    Note& m = notes_[k];
    if (!is_row(m))
    {
      continue;
    }
    const std::uint32_t slot = next[row_index(m)]++;
    if (slot >= range_of(m.colour, m.kind).lanes)
    {
      m.kind = Kind::Other;
      others.emplace_back(m.colour, static_cast<std::uint32_t>(k));
      continue;
    }
    fill_lane(points, k, m, slot, friction);
  }
}

void SoftRows::fill_lane(const ContactPoints& points, std::size_t first, const Note& m, std::size_t slot,
                         bool friction)
{
  const std::size_t lane = range_of(m.colour, m.kind).begin * kRowLanes + slot;  // over all batches
  if (m.kind == Kind::Single)
  {
    fill_manifold(singles_[lane / kRowLanes], static_cast<int>(lane % kRowLanes), points, first, friction, springs_,
                  spare_);
    lane_of_[first] = kSingleLane | static_cast<std::uint32_t>(lane);
    return;
  }
  fill_manifold(rows_[lane / kRowLanes], static_cast<int>(lane % kRowLanes), points, first, friction, springs_,
                spare_);
  lane_of_[first] = static_cast<std::uint32_t>(2 * lane);
  lane_of_[first + 1] = static_cast<std::uint32_t>(2 * lane + 1);
}

ImpulseSlots SoftRows::impulses_of(std::size_t k)
{
  const RowSlot slot = row_slot(k);
  // The rows are this object's own and it is not const here: writable.
  RowPoint* point = const_cast<RowPoint*>(slot.point);
  return point == nullptr ? ImpulseSlots{} : ImpulseSlots{&point->normal[slot.lane], &point->tangent[slot.lane]};
}

namespace
{
/// Calls f(batch, lanes) for part `part` of `parts` of a colour's batches of
/// one kind; with `twos`, f2(first) on each two neighbours first (the eight-lane path).
template <class Batch, class F, class F2>
void each_batch(const RowRange& c, FrameSpan<Batch>& rows, std::size_t part, std::size_t parts, bool twos, F f,
                F2 f2)
{
  const std::size_t n = c.end - c.begin;
  std::size_t r = c.begin + n * part / parts;
  const std::size_t end = c.begin + n * (part + 1) / parts;
  for (; twos && r + 1 < end; r += 2)
  {
    f2(rows[r]);
  }
  for (; r < end; ++r)
  {
    f(rows[r], static_cast<int>(std::min<std::size_t>(kRowLanes, c.lanes - (r - c.begin) * kRowLanes)));
  }
}
}  // namespace

void SoftRows::warm_start_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, std::size_t part,
                               std::size_t parts)
{
  if (!batched(colour))
  {
    return;
  }
  const RowLanes path = row_lanes();
  const bool twos = path == RowLanes::Eight;
  const auto warm = [&](auto& batch, int lanes) { warm_start_batch(path, batch, lanes, velocity); };
  const auto warm2 = [&](auto& first) { warm_start_batches_eight(first, velocity); };
  each_batch(colours_[colour].pairs, rows_, part, parts, twos, warm, warm2);
  each_batch(colours_[colour].singles, singles_, part, parts, twos, warm, warm2);
}

void SoftRows::solve_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, const RowPass& pass,
                          std::size_t part, std::size_t parts)
{
  if (!batched(colour))
  {
    return;
  }
  const RowLanes path = row_lanes();
  const bool twos = path == RowLanes::Eight;
  const auto solve = [&](auto& batch, int lanes) { solve_batch(path, batch, lanes, velocity, pass); };
  const auto solve2 = [&](auto& first) { solve_batches_eight(first, velocity, pass); };
  each_batch(colours_[colour].pairs, rows_, part, parts, twos, solve, solve2);
  each_batch(colours_[colour].singles, singles_, part, parts, twos, solve, solve2);
}

void SoftRows::drop_spare_body(std::vector<BodyVelocity>& velocity) const { velocity.pop_back(); }

}  // namespace detail
}  // namespace collision2d
