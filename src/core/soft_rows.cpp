// The soft step's rows in colours (soft_rows.h): greedy colouring, packing
// into batches, the passes in colour order and the scalar lane path (the
// choice of path is soft_rows_dispatch.cpp).
#include "soft_rows.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <utility>

#include "soft_rows_kernel.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Colours tried before a manifold goes to the overflow: a box in a stack
/// touches at most six others, so greedy colouring needs far fewer.
constexpr std::size_t kMaxColours = 24;
/// Fewer manifolds than this are ordered by a comparison sort (sort_by_height).
constexpr std::size_t kRadixSortFrom = 256;
/// A bit per colour, for the colours a body is in.
constexpr std::uint32_t kAllColours = (std::uint32_t{1} << kMaxColours) - 1;
/// Row manifolds (lanes) below which filling or emptying the batches stays on
/// the calling thread: a lane is a few dozen copies.
constexpr std::size_t kMinSharedLanes = 512;

struct ScalarOps
{
  int j = 0;
  double load(const double* f) const { return f[j]; }
  void store(double* f, double v) const { f[j] = v; }
  void gather(const std::vector<BodyVelocity>& state, const std::uint32_t* index, rows::Side<double>& side) const
  {
    const BodyVelocity& s = state[index[j]];
    side.v = {s.v.x, s.v.y};
    side.w = s.omega;
    side.moved = {s.moved.x, s.moved.y};
    side.c = s.turned_cos;
    side.s = s.turned_sin;
  }
  void scatter(std::vector<BodyVelocity>& state, const std::uint32_t* index, const rows::Side<double>& side) const
  {
    BodyVelocity& s = state[index[j]];
    s.v = Vec2{side.v.x, side.v.y};
    s.omega = side.w;
  }
};

bool row_manifold(const ContactPoint& p) { return p.count == 2 && p.pair_block; }

/// A key whose unsigned order is the descending order of h. A float is fine
/// enough to order contacts by height; equal heights keep point order.
std::uint32_t descending_key(float h)
{
  std::uint32_t bits = 0;
  h = h == 0.0F ? 0.0F : h;  // -0 sorts with +0
  std::memcpy(&bits, &h, sizeof bits);
  const std::uint32_t ascending = (bits & 0x80000000U) != 0 ? ~bits : bits | 0x80000000U;
  return ~ascending;
}

/// Sorts keys by their high half, keeping the order of equal ones: a least
/// significant digit radix sort, linear where a comparison sort cost more
/// than the colouring it orders. One pass counts every digit. The low halves
/// are distinct and ascending, so a comparison sort of the whole keys gives
/// the same order: below kRadixSortFrom keys it is cheaper than clearing and
/// summing the digit counts.
void sort_by_height(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& scratch)
{
  if (keys.size() < kRadixSortFrom)
  {
    std::sort(keys.begin(), keys.end());
    return;
  }
  constexpr int kDigitBits = 8;
  constexpr int kKeyDigits = 4;  // the high 32 bits
  constexpr std::size_t kDigits = std::size_t{1} << kDigitBits;
  const auto digit = [](std::uint64_t key, int d) {
    return static_cast<std::size_t>(key >> (32 + kDigitBits * d)) & (kDigits - 1);
  };
  std::array<std::array<std::size_t, kDigits>, kKeyDigits> start{};
  for (const std::uint64_t key : keys)
  {
    for (int d = 0; d < kKeyDigits; ++d)
    {
      ++start[d][digit(key, d)];
    }
  }
  scratch.reserve(keys.capacity());
  scratch.resize(keys.size());
  for (int d = 0; d < kKeyDigits; ++d)
  {
    if (keys.empty() || start[d][digit(keys.front(), d)] == keys.size())
    {
      continue;  // one value of this digit for all: nothing moves
    }
    std::size_t sum = 0;
    for (std::size_t& s : start[d])
    {
      sum += std::exchange(s, sum);
    }
    for (const std::uint64_t key : keys)
    {
      scratch[start[d][digit(key, d)]++] = key;
    }
    keys.swap(scratch);
  }
}

}  // namespace

void warm_start_batch_scalar(RowBatch& batch, int lanes, std::vector<BodyVelocity>& velocity)
{
  for (int j = 0; j < lanes; ++j)
  {
    rows::warm_start_rows<double>(ScalarOps{j}, batch, velocity);
  }
}

void solve_batch_scalar(RowBatch& batch, int lanes, std::vector<BodyVelocity>& velocity, const RowPass& pass)
{
  for (int j = 0; j < lanes; ++j)
  {
    rows::solve_rows<double>(ScalarOps{j}, batch, velocity, pass);
  }
}

std::size_t SoftRows::take_colour(std::uint32_t a, std::uint32_t b)
{
  // a and b are the bodies the manifold moves (kFixed for one that cannot
  // move); the lowest colour neither is in yet.
  const auto colours_of = [&](std::uint32_t i) { return i == kFixed ? 0U : colours_of_[i]; };
  const std::uint32_t free = ~(colours_of(a) | colours_of(b)) & kAllColours;
  if (free == 0)
  {
    return kMaxColours;
  }
  const std::size_t colour = static_cast<std::size_t>(__builtin_ctz(free));
  for (std::uint32_t i : {a, b})
  {
    if (i != kFixed)
    {
      colours_of_[i] |= std::uint32_t{1} << colour;
    }
  }
  return colour;
}

void SoftRows::expect_points(std::size_t points) { notes_.resize(points); }

void SoftRows::note_manifold(std::size_t k, const ContactPoint& p, const ContactPoint* second, Vec2 up)
{
  const Vec2 at = second != nullptr ? 0.5 * (p.point + second->point) : p.point;
  notes_[k] = Note{descending_key(static_cast<float>(dot(at, up))), p.inv_mass_a != 0.0 ? p.a : kFixed,
                   p.inv_mass_b != 0.0 ? p.b : kFixed, 0, true, row_manifold(p)};
}

void SoftRows::note_no_manifold(std::size_t k) { notes_[k].first = false; }

void SoftRows::order_manifolds()
{
  // At most one manifold per point: reserved so, the keys never grow by
  // copying, and the pages past the last manifold are never touched.
  order_.clear();
  order_.reserve(notes_.size());
  for (std::size_t k = 0; k < notes_.size(); ++k)
  {
    if (notes_[k].first)
    {
      order_.push_back(std::uint64_t{notes_[k].key} << 32 | k);
    }
  }
  sort_by_height(order_, sort_scratch_);
}

void SoftRows::pack(std::vector<ContactPoint>& points, std::vector<BodyVelocity>& velocity, bool friction,
                    WorkerPool& workers)
{
  spare_ = static_cast<std::uint32_t>(velocity.size());
  velocity.push_back(body_velocity(Vec2{0.0, 0.0}, 0.0, 0.0, 0.0));
  colours_of_.assign(velocity.size(), 0);
  colours_.resize(kMaxColours);
  for (RowColour& c : colours_)
  {
    c.others.clear();
    c.lanes = 0;
  }
  overflow_.clear();
  coloured_ = 0;
  used_colours_ = 0;
  // First pass: colour every manifold from the top of the scene down; rows
  // are counted, then placed. Colouring in point (body index) order made the
  // colours lopsided across a stack, and a pyramid swayed to one side as it
  // settled; from the top down, each level is coloured alike.
  order_manifolds();
  for (const std::uint64_t key : order_)
  {
    const std::size_t first = key & 0xffffffffU;
    Note& m = notes_[first];
    const std::size_t colour = take_colour(m.a, m.b);
    if (colour == kMaxColours)
    {
      overflow_.push_back(first);
      m.row = false;
      continue;
    }
    ++coloured_;
    used_colours_ = std::max(used_colours_, colour + 1);
    if (m.row)
    {
      m.colour = static_cast<std::uint8_t>(colour);
      ++colours_[colour].lanes;
    }
    else
    {
      colours_[colour].others.push_back(first);
    }
  }
  // Within a colour the rows share no body, so their places are free: in
  // point order, as the points lie in memory. A colour's only row goes to
  // the point verbs: the same bits, without a batch's padding lanes.
  row_slots_.clear();
  row_slots_.reserve(order_.size());
  std::array<std::uint32_t, kMaxColours> placed{};
  for (std::size_t k = 0; k < notes_.size(); ++k)
  {
    Note& m = notes_[k];
    if (m.first && m.row && colours_[m.colour].lanes == 1)
    {
      m.row = false;
      colours_[m.colour].others.push_back(k);
    }
    else if (m.first && m.row)
    {
      row_slots_.push_back(RowSlot{static_cast<std::uint32_t>(k), m.colour, placed[m.colour]++});
    }
  }
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    colours_[colour].lanes = placed[colour];
  }
  // Second pass: each colour's rows in whole batches, the last one padded.
  // Every lane has its own slot, so the workers can fill them in any split.
  std::size_t batches = 0;
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    RowColour& c = colours_[colour];
    c.begin = batches;
    batches += (c.lanes + kRowLanes - 1) / kRowLanes;
    c.end = batches;
  }
  rows_.resize(batches);
  workers.parallel_for(row_slots_.size(), kMinSharedLanes, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r)
    {
      const RowSlot& row = row_slots_[r];
      const std::size_t batch = colours_[row.colour].begin + row.slot / kRowLanes;
      fill_lane(rows_[batch], static_cast<int>(row.slot % kRowLanes), points, row.first, friction);
    }
  });
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    const RowColour& c = colours_[colour];
    for (std::size_t slot = c.lanes; slot < (c.end - c.begin) * kRowLanes; ++slot)
    {
      fill_lane(rows_[c.begin + slot / kRowLanes], static_cast<int>(slot % kRowLanes), points, SIZE_MAX, friction);
    }
  }
}

void SoftRows::fill_lane(RowBatch& r, int j, const std::vector<ContactPoint>& points, std::size_t first,
                         bool friction) const
{
  if (first == SIZE_MAX)
  {
    // Padding: the spare body on both sides, nothing to push.
    r.a[j] = spare_;
    r.b[j] = spare_;
    for (double* f : {r.nx, r.ny, r.k12, r.inv_mass_a, r.inv_mass_b, r.inv_inertia_a, r.inv_inertia_b,
                      r.bias_rate, r.mu_s, r.mu_k, r.rough})
    {
      f[j] = 0.0;
    }
    for (double* f : {r.k11, r.k22, r.pair_tangent_mass, r.mass_scale})
    {
      f[j] = 1.0;
    }
    for (RowPoint& q : r.point)
    {
      for (double* f : {q.ra_x, q.ra_y, q.rb_x, q.rb_y, q.base, q.kinetic, q.anchor, q.normal, q.tangent,
                        q.sliding})
      {
        f[j] = 0.0;
      }
    }
    return;
  }
  const ContactPoint& p = points[first];
  r.a[j] = static_cast<std::uint32_t>(p.a);
  r.b[j] = static_cast<std::uint32_t>(p.b);
  r.nx[j] = p.normal.x;
  r.ny[j] = p.normal.y;
  r.k11[j] = p.k_n;
  r.k12[j] = p.pair_k12;
  r.k22[j] = points[first + 1].k_n;
  r.pair_tangent_mass[j] = p.pair_tangent_mass;
  r.inv_mass_a[j] = p.inv_mass_a;
  r.inv_mass_b[j] = p.inv_mass_b;
  r.inv_inertia_a[j] = p.inv_inertia_a;
  r.inv_inertia_b[j] = p.inv_inertia_b;
  r.bias_rate[j] = p.softness.bias_rate;
  r.mass_scale[j] = p.softness.mass_scale;
  r.mu_s[j] = p.mu_s;
  r.mu_k[j] = p.mu_k;
  r.rough[j] = friction && (p.mu_s > 0.0 || p.mu_k > 0.0) ? 1.0 : 0.0;
  for (int k = 0; k < 2; ++k)
  {
    const ContactPoint& c = points[first + k];
    RowPoint& q = r.point[k];
    q.ra_x[j] = c.r_a.x;
    q.ra_y[j] = c.r_a.y;
    q.rb_x[j] = c.r_b.x;
    q.rb_y[j] = c.r_b.y;
    q.base[j] = c.base_separation;
    q.kinetic[j] = c.kinetic ? 1.0 : 0.0;
    q.anchor[j] = c.anchor_drift;
    q.normal[j] = c.lambda_n;
    q.tangent[j] = c.lambda_t;
    q.sliding[j] = c.sliding ? 1.0 : 0.0;
  }
}

RowPoint* SoftRows::row_point_of(std::size_t k, int& lane)
{
  // row_slots_ is in point order: the last manifold starting at or before k
  // holds k if it starts there or k is its second point.
  const auto after = std::upper_bound(row_slots_.begin(), row_slots_.end(), k,
                                      [](std::size_t point, const RowSlot& row) { return point < row.first; });
  if (after == row_slots_.begin())
  {
    return nullptr;
  }
  const RowSlot& row = *(after - 1);
  const std::size_t which = k - row.first;
  if (which > 1)
  {
    return nullptr;
  }
  lane = static_cast<int>(row.slot % kRowLanes);
  return &rows_[colours_[row.colour].begin + row.slot / kRowLanes].point[which];
}

double* SoftRows::normal_impulse_of(std::size_t k)
{
  int lane = 0;
  RowPoint* point = row_point_of(k, lane);
  return point == nullptr ? nullptr : &point->normal[lane];
}

namespace
{
/// Calls f(batch, lanes) for part `part` of `parts` of a colour's batches.
template <class F>
void each_batch(const RowColour& c, std::vector<RowBatch>& rows, std::size_t part, std::size_t parts, F f)
{
  const std::size_t n = c.end - c.begin;
  for (std::size_t r = c.begin + n * part / parts; r < c.begin + n * (part + 1) / parts; ++r)
  {
    f(rows[r], static_cast<int>(std::min<std::size_t>(kRowLanes, c.lanes - (r - c.begin) * kRowLanes)));
  }
}
}  // namespace

void SoftRows::warm_start_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, std::size_t part,
                               std::size_t parts)
{
  const RowLanes path = row_lanes();
  each_batch(colours_[colour], rows_, part, parts,
             [&](RowBatch& batch, int lanes) { warm_start_batch(path, batch, lanes, velocity); });
}

void SoftRows::solve_rows(std::size_t colour, std::vector<BodyVelocity>& velocity, const RowPass& pass,
                          std::size_t part, std::size_t parts)
{
  const RowLanes path = row_lanes();
  each_batch(colours_[colour], rows_, part, parts,
             [&](RowBatch& batch, int lanes) { solve_batch(path, batch, lanes, velocity, pass); });
}

void SoftRows::unpack(std::vector<ContactPoint>& points, std::vector<BodyVelocity>& velocity,
                      WorkerPool& workers) const
{
  velocity.pop_back();
  // In point order, so the points are written in turn and the lanes read
  // where they lie; each manifold's points are written by one worker.
  workers.parallel_for(row_slots_.size(), kMinSharedLanes, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r)
    {
      const RowSlot& row = row_slots_[r];
      const std::size_t batch = colours_[row.colour].begin + row.slot / kRowLanes;
      unpack_lane(rows_[batch], static_cast<int>(row.slot % kRowLanes), points, row.first);
    }
  });
}

void SoftRows::unpack_lane(const RowBatch& r, int j, std::vector<ContactPoint>& points, std::size_t first)
{
  for (int k = 0; k < 2; ++k)
  {
    ContactPoint& c = points[first + k];
    const RowPoint& q = r.point[k];
    c.lambda_n = q.normal[j];
    c.lambda_t = q.tangent[j];
    c.sliding = q.sliding[j] != 0.0;
  }
}

}  // namespace detail
}  // namespace collision2d
