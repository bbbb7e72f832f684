// The soft step's manifolds in colours (soft_rows.h): each noted at prepare,
// ordered from the top of the scene down (soft_rows_order.cpp), then
// coloured greedily.
#include "soft_rows.h"

#include <algorithm>
#include <cstring>

#include "scratch_buffer.h"

namespace collision2d
{
namespace detail
{
namespace
{
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

/// The key's top bit: set for a manifold against a static body.
constexpr std::uint32_t kStaticKeyBit = 0x80000000U;

/// A key whose unsigned order puts the manifolds against a static body
/// after the others, each in the descending order of h. A float less its
/// last bit is fine enough to order contacts by height; equal heights keep
/// point order. A body pressed between a moving one and the ground is then
/// solved against the ground last: solved in height order, without gravity
/// (all heights equal) the pusher could have the last word and carry it
/// through the ground.
std::uint32_t order_key(float h, bool against_static)
{
  std::uint32_t bits = 0;
  h = h == 0.0F ? 0.0F : h;  // -0 sorts with +0
  std::memcpy(&bits, &h, sizeof bits);
  const std::uint32_t ascending = (bits & 0x80000000U) != 0 ? ~bits : bits | 0x80000000U;
  return (~ascending >> 1) | (against_static ? kStaticKeyBit : 0U);
}

/// The manifold's first point, the low half of its order_ key.
std::size_t first_point(std::uint64_t key) { return static_cast<std::size_t>(key & 0xffffffffU); }

}  // namespace

std::size_t SoftRows::take_colour(std::uint32_t a, std::uint32_t b, bool against_static)
{
  // a and b are the bodies the manifold moves (kFixed for one that cannot
  // move); the lowest colour neither is in yet.
  const auto colours_of = [&](std::uint32_t i) { return i == kFixed ? 0U : colours_of_[i]; };
  // A bit per colour, for the colours a body is in.
  constexpr std::uint32_t kAllColours = (std::uint32_t{1} << kMaxColours) - 1;
  const std::uint32_t taken = colours_of(a) | colours_of(b);
  const std::uint32_t free = ~taken & kAllColours;
  if (free == 0)
  {
    return kMaxColours;
  }
  // Static manifolds are coloured after all the others (order_key), so the
  // colour after the body's last is solved after every other manifold of it.
  const std::size_t after_last = taken == 0 ? 0 : static_cast<std::size_t>(32 - __builtin_clz(taken));
  const std::size_t colour = against_static && after_last < kMaxColours
                                 ? after_last
                                 : static_cast<std::size_t>(__builtin_ctz(free));
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

void SoftRows::keep_on_point_verbs(std::size_t k) { notes_[k].kind = Kind::Other; }

void SoftRows::note_manifold(std::size_t k, const ContactPoint& p, const ContactPoint* second, Vec2 up)
{
  const Vec2 at = second != nullptr ? 0.5 * (p.point + second->point) : p.point;
  const Kind kind = second == nullptr ? Kind::Single : p.pair_block ? Kind::Pair : Kind::Other;
  notes_[k] = Note{order_key(static_cast<float>(dot(at, up)), p.against_static), p.inv_mass_a != 0.0 ? p.a : kFixed,
                   p.inv_mass_b != 0.0 ? p.b : kFixed, 0, true, p.against_static, kind};
}

void SoftRows::note_no_manifold(std::size_t k) { notes_[k].first = false; }

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
    const std::size_t colour = take_colour(m.a, m.b, m.against_static);
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
  // The rows a batch would mostly pad go to the point verbs (place_rows):
  // the same bits, without the padding lanes.
  for (std::size_t colour = 0; colour < used_colours_; ++colour)
  {
    for (RowRange* range : {&colours_[colour].pairs, &colours_[colour].singles})
    {
      range->lanes = batched_lanes(range->lanes);
    }
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
