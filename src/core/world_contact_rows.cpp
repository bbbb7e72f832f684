// The contact rows of a detection (world_contacts.cpp finds the pairs and
// their manifolds): where each pair's rows go, found in pair order, then the
// rows filled by the workers, each with its impulses matched from the
// previous frame's contacts (the cache, keyed by body ids and feature).
#include <algorithm>
#include <limits>
#include <new>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
bool pair_less(const WorldContact& c, BodyId a, BodyId b)
{
  return c.a < a || (c.a == a && c.b < b);
}

}  // namespace

std::size_t WorldImpl::place_pair_rows(bool cached)
{
  if (workers_.workers() > 1 && pairs_.size() >= kMinSharedPairs)
  {
    place_pairs_in_parts(cached);
  }
  else
  {
    place_pairs_in_order(cached);
  }
  return pair_rows_[pairs_.size()];
}

void WorldImpl::place_pairs_in_parts(bool cached)
{
  // The cache is in (a, b) order (as contacts_ always is), so a lookup gives
  // the same answer from any cursor: the pairs are placed in parts, each
  // with its own cursor, and their rows counted up after.
  const std::size_t parts = static_cast<std::size_t>(workers_.workers());
  placements_.resize(parts);
  workers_.parallel_for(parts, 2, [&](std::size_t begin, std::size_t end) {
    for (std::size_t part = begin; part < end; ++part)
    {
      place_pairs_part(part, parts, cached);
    }
  });
  std::size_t rows = 0;
  for (std::size_t k = 0; k < pairs_.size(); ++k)
  {
    const std::size_t count = pair_rows_[k];
    pair_rows_[k] = rows;
    rows += count;
  }
  pair_rows_[pairs_.size()] = rows;
  // The cursor ends where one pass leaves it: at the last lookup.
  for (auto placed = placements_.rbegin(); placed != placements_.rend(); ++placed)
  {
    if (placed->looked_up)
    {
      cache_cursor_ = placed->last_lookup;
      break;
    }
  }
}

void WorldImpl::place_pairs_part(std::size_t part, std::size_t parts, bool cached)
{
  // A local, stored at the end: the parts' placements share a cache line,
  // which each lookup below would otherwise write.
  PairPlacement placed;
  const std::size_t c = contacts_.size();
  std::size_t cursor = c + 1;  // the first lookup searches
  const std::size_t n = pairs_.size();
  for (std::size_t k = n * part / parts; k < n * (part + 1) / parts; ++k)
  {
    const int count = collided_[k] == Collided::Hit ? manifolds_[k].count : 0;
    pair_rows_[k] = static_cast<std::size_t>(count);
    pair_cache_[k] = c;
    if (cached && count > 0)
    {
      pair_cache_[k] = first_cached(k, cursor);
      placed.looked_up = true;
      placed.last_lookup = pair_cache_[k];
    }
  }
  placements_[part] = placed;
}

void WorldImpl::place_pairs_in_order(bool cached)
{
  // Pairs without a mover were not collided (collide_range): a sleeping
  // island's contacts are kept aside (world_sleeping_contacts.cpp).
  std::size_t rows = 0;
  for (std::size_t k = 0; k < pairs_.size(); ++k)
  {
    pair_rows_[k] = rows;
    if (collided_[k] != Collided::Hit)
    {
      continue;
    }
    const int count = manifolds_[k].count;
    pair_cache_[k] = contacts_.size();
    if (cached && count > 0)
    {
      pair_cache_[k] = first_cached(k, cache_cursor_);
    }
    rows += static_cast<std::size_t>(count);
  }
  pair_rows_[pairs_.size()] = rows;
}

double WorldImpl::add_manifold(std::size_t k, double warm_scale, bool friction)
{
  double deepest = -std::numeric_limits<double>::infinity();
  const std::size_t i = pairs_[k].first;
  const std::size_t j = pairs_[k].second;
  const Manifold& m = manifolds_[k];
  // A kept manifold's points are its cached contacts, in order.
  const WorldContact* kept_first = kept(k) ? &contacts_[kept_from_[k]] : nullptr;
  for (int c = 0; c < m.count; ++c)
  {
    ContactPoint& row = points_[pair_rows_[k] + static_cast<std::size_t>(c)];
    const WorldContact* kept_point = kept_first != nullptr ? kept_first + c : nullptr;
    // Default-initialised in place: each member takes its initialiser by
    // plain stores. `row = ContactPoint{}` first clears all of it with
    // `rep stos`, whose start-up costs more than the stores (docs/performance.md).
    new (&row) ContactPoint;
    row.a = i;
    row.b = j;
    row.normal = m.normal;
    row.point = m.points[c].point;
    row.separation = m.points[c].separation;
    row.feature = m.points[c].feature;
    row.count = static_cast<std::uint8_t>(m.count);
    if (reuse_distance_ > 0.0)
    {
      // The lever arms are fixed for the frame from here.
      row.kept = kept_point != nullptr;
      if (row.kept)
      {
        set_kept_origin(kept_point->origin, row);
      }
      else
      {
        set_new_origin(k, row);  // world_contact_reuse.cpp
      }
    }
    deepest = std::max(deepest, m.points[c].penetration);
    const WorldContact* cached = nullptr;
    if (warm_scale > 0.0 || friction)
    {
      cached = row.kept ? kept_point : find_cached(pair_cache_[k], ids_[i], ids_[j], row.feature);
    }
    if (cached != nullptr)
    {
      row.lambda_n = warm_scale * cached->impulse.normal;
      row.lambda_t = warm_scale * cached->impulse.tangent;
      row.kinetic = friction && cached->sliding;
      row.anchor_drift = cached->anchor_drift;
    }
  }
  return deepest;
}

/// Pair k's first cached contact: where its kept manifold came from, else
/// cached_pair's answer; `cursor` as cached_pair's.
std::size_t WorldImpl::first_cached(std::size_t k, std::size_t& cursor) const
{
  // A kept manifold knows where its cached contacts start.
  return kept(k) ? (cursor = kept_from_[k]) : cached_pair(cursor, ids_[pairs_[k].first], ids_[pairs_[k].second]);
}

std::size_t WorldImpl::cached_pair(std::size_t& cursor, BodyId a, BodyId b) const
{
  // The cache is in (a, b) order because contacts are published in broad-phase
  // pair order and dense indices follow ids; detection asks in that order too,
  // so the cursor only moves forward (a search covers any other order).
  if (cursor > contacts_.size() || (cursor > 0 && !pair_less(contacts_[cursor - 1], a, b)))
  {
    const auto found = std::lower_bound(contacts_.begin(), contacts_.end(), std::make_pair(a, b),
                                        [](const WorldContact& c, const std::pair<BodyId, BodyId>& key) {
                                          return pair_less(c, key.first, key.second);
                                        });
    cursor = static_cast<std::size_t>(found - contacts_.begin());
    return cursor;
  }
  while (cursor < contacts_.size() && pair_less(contacts_[cursor], a, b))
  {
    ++cursor;
  }
  return cursor;
}

/// The contact of pair (a, b) with `feature` among its cached contacts from contacts_[first] on.
const WorldContact* WorldImpl::find_cached(std::size_t first, BodyId a, BodyId b, std::uint32_t feature) const
{
  for (auto it = contacts_.begin() + first; it != contacts_.end() && it->a == a && it->b == b; ++it)
  {
    if (it->contact.feature == feature)
    {
      return &*it;
    }
  }
  return nullptr;
}

}  // namespace detail
}  // namespace collision2d
