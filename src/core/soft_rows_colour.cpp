// The soft step's manifolds in colours (soft_rows.h): each noted at prepare,
// ordered from the top of the scene down, then coloured greedily; a colour's
// rows get their places in point order.
#include "soft_rows.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <utility>

#include "scratch_buffer.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Fewer manifolds than this are ordered by a comparison sort (sort_by_height).
constexpr std::size_t kRadixSortFrom = 256;
/// A batch with fewer manifolds leaves them to the point verbs: a batch
/// costs four lanes' loads, stores and arithmetic whatever its padding.
constexpr std::size_t kMinBatchLanes = 3;

/// How many of a colour's manifolds of one kind go to batches: none below
/// kMinBatchLanes, and a last, partly padded batch only with that many.
std::size_t batched_lanes(std::size_t lanes)
{
  const std::size_t last = lanes % kRowLanes;
  if (lanes < kMinBatchLanes)
  {
    return 0;
  }
  return last != 0 && last < kMinBatchLanes ? lanes - last : lanes;
}

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

/// The manifold's first point, the low half of its order_ key.
std::size_t first_point(std::uint64_t key) { return static_cast<std::size_t>(key & 0xffffffffU); }

}  // namespace

std::size_t SoftRows::take_colour(std::uint32_t a, std::uint32_t b)
{
  // a and b are the bodies the manifold moves (kFixed for one that cannot
  // move); the lowest colour neither is in yet.
  const auto colours_of = [&](std::uint32_t i) { return i == kFixed ? 0U : colours_of_[i]; };
  // A bit per colour, for the colours a body is in.
  constexpr std::uint32_t kAllColours = (std::uint32_t{1} << kMaxColours) - 1;
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

void SoftRows::expect_points(std::size_t points) { resize_to_overwrite(notes_, points); }

void SoftRows::note_manifold(std::size_t k, const ContactPoint& p, const ContactPoint* second, Vec2 up)
{
  const Vec2 at = second != nullptr ? 0.5 * (p.point + second->point) : p.point;
  const Kind kind = second == nullptr ? Kind::Single : p.pair_block ? Kind::Pair : Kind::Other;
  notes_[k] = Note{descending_key(static_cast<float>(dot(at, up))), p.inv_mass_a != 0.0 ? p.a : kFixed,
                   p.inv_mass_b != 0.0 ? p.b : kFixed, 0, true, kind};
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

void SoftRows::colour_manifolds(std::size_t bodies)
{
  colours_of_.assign(bodies, 0);
  clear_colours();
  // First pass: colour every manifold from the top of the scene down; rows
  // are counted, then placed. Colouring in point (body index) order made the
  // colours lopsided across a stack, and a pyramid swayed to one side as it
  // settled; from the top down, each level is coloured alike.
  for (const std::uint64_t key : order_)
  {
    const std::size_t first = first_point(key);
    Note& m = notes_[first];
    const std::size_t colour = take_colour(m.a, m.b);
    if (colour == kMaxColours)
    {
      overflow_.push_back(first);
      m.kind = Kind::Other;
      continue;
    }
    ++coloured_;
    used_colours_ = std::max(used_colours_, colour + 1);
    if (m.kind != Kind::Other)
    {
      m.colour = static_cast<std::uint8_t>(colour);
      ++range_of(colour, m.kind).lanes;
    }
    else
    {
      colours_[colour].others.push_back(first);
    }
  }
  // Within a colour the rows share no body, so their places are free: in
  // point order, as the points lie in memory. The rows a batch would mostly
  // pad go to the point verbs: the same bits, without the padding lanes.
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    for (RowRange* range : {&colours_[colour].pairs, &colours_[colour].singles})
    {
      range->lanes = batched_lanes(range->lanes);
    }
  }
  row_slots_.clear();
  row_slots_.reserve(order_.size());
  for (std::size_t k = 0; k < notes_.size(); ++k)
  {
    Note& m = notes_[k];
    if (!m.first || m.kind == Kind::Other)
    {
      continue;
    }
    RowRange& range = range_of(m.colour, m.kind);
    if (range.placed >= range.lanes)
    {
      m.kind = Kind::Other;
      colours_[m.colour].others.push_back(k);
      continue;
    }
    row_slots_.push_back(RowSlot{static_cast<std::uint32_t>(k), m.colour, static_cast<std::uint32_t>(range.placed++),
                                 m.kind});
  }
}

void SoftRows::clear_colours()
{
  // Only the last frame's colours were filled; the rest are still clear.
  colours_.resize(kMaxColours);
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    RowColour& c = colours_[colour];
    c.others.clear();
    c.pairs = RowRange{};
    c.singles = RowRange{};
  }
  overflow_.clear();
  coloured_ = 0;
  used_colours_ = 0;
}

void SoftRows::order_without_colours()
{
  // The colouring's own order: the second manifold follows the first in a
  // colour after it when they share a body, and in any order when not.
  clear_colours();
  for (const std::uint64_t key : order_)
  {
    overflow_.push_back(first_point(key));
  }
  rows_.clear();
  singles_.clear();
  lane_of_.clear();  // no point has a row
}

RowRange& SoftRows::range_of(std::size_t colour, Kind kind)
{
  return kind == Kind::Single ? colours_[colour].singles : colours_[colour].pairs;
}

}  // namespace detail
}  // namespace collision2d
