// A sleeping island's contacts are kept aside, out of the step: nothing moves
// in the island, so they stay what they were when it fell asleep, and no
// stage of a frame reads them until a mover reaches the island or an edit
// wakes it. Then the whole island wakes and its contacts (impulses, friction
// state) go back where detection finds them. The World still reports them
// (all_contacts()).
#include <algorithm>
#include <iterator>

#include "world_impl.h"

namespace collision2d
{
namespace detail
{
namespace
{
bool pair_order(const WorldContact& x, const WorldContact& y)
{
  return x.a < y.a || (x.a == y.a && x.b < y.b);
}

/// Merges sorted `extra` into sorted `into`, through `scratch` (both keep capacity).
void merge_into(std::vector<WorldContact>& into, const std::vector<WorldContact>& extra,
                std::vector<WorldContact>& scratch)
{
  scratch.clear();
  scratch.reserve(into.size() + extra.size());
  std::merge(into.begin(), into.end(), extra.begin(), extra.end(), std::back_inserter(scratch), pair_order);
  into.swap(scratch);
}

}  // namespace

void WorldImpl::label_new_sleepers()
{
  root_label_.assign(bodies_.size(), 0);
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (!asleep_[i] || island_label_[i] != 0)
    {
      continue;
    }
    // update_sleep's union-find still holds this frame's islands.
    std::size_t root = i;
    while (island_[root] != root)
    {
      root = island_[root];
    }
    if (root_label_[root] == 0)
    {
      root_label_[root] = ++next_island_label_;
    }
    island_label_[i] = root_label_[root];
  }
}

void WorldImpl::put_contacts_aside()
{
  keep_sleeping_for_rollback(false);  // only this frame's contacts change
  // A contact kept aside keeps its impulses and friction state; its slip is
  // not followed while nothing moves.
  moved_contacts_.clear();
  auto kept = contacts_.begin();
  for (WorldContact& c : contacts_)
  {
    if (asleep_[c.contact.a] || asleep_[c.contact.b])
    {
      c.anchor_drift = 0.0;
      moved_contacts_.push_back(c);
    }
    else
    {
      *kept++ = c;
    }
  }
  contacts_.erase(kept, contacts_.end());
  if (sleeping_contacts_.empty())
  {
    sleeping_contacts_.swap(moved_contacts_);  // nothing to merge with: no third buffer
  }
  else
  {
    merge_into(sleeping_contacts_, moved_contacts_, merge_scratch_);
  }
  measure_sleeping_penetration();
}

void WorldImpl::wake_island(IslandLabel label, std::vector<WorldContact>& into)
{
  keep_sleeping_for_rollback(true);
  ++sleep_stamp_;
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    if (island_label_[i] == label)
    {
      island_label_[i] = 0;
      asleep_[i] = false;
    }
  }
  // The island's contacts are those kept aside with one of its bodies: the
  // other body is in the island too, or is static or still kinematic.
  moved_contacts_.clear();
  auto kept = sleeping_contacts_.begin();
  for (const WorldContact& c : sleeping_contacts_)
  {
    if (asleep_[c.contact.a] || asleep_[c.contact.b])
    {
      *kept++ = c;
    }
    else
    {
      moved_contacts_.push_back(c);
    }
  }
  sleeping_contacts_.erase(kept, sleeping_contacts_.end());
  merge_into(into, moved_contacts_, merge_scratch_);
  measure_sleeping_penetration();
  cache_cursor_ = contacts_.size() + 1;  // the cache may have changed: the next lookup searches
}

std::size_t WorldImpl::asleep_bodies()
{
  if (asleep_counted_stamp_ != sleep_stamp_ || asleep_counted_version_ != version_)
  {
    asleep_counted_stamp_ = sleep_stamp_;
    asleep_counted_version_ = version_;
    asleep_count_ = static_cast<std::size_t>(std::count(asleep_.begin(), asleep_.end(), true));
  }
  return asleep_count_;
}

void WorldImpl::wake_everyone()
{
  if (sleeping_contacts_.empty() && asleep_bodies() == 0)
  {
    return;
  }
  keep_sleeping_for_rollback(true);
  ++sleep_stamp_;
  merge_into(contacts_, sleeping_contacts_, merge_scratch_);
  sleeping_contacts_.clear();
  sleeping_penetration_ = 0.0;
  asleep_.assign(bodies_.size(), false);
  island_label_.assign(bodies_.size(), 0);
}

bool WorldImpl::wake_reached_islands()
{
  if (asleep_bodies() == 0)
  {
    return false;
  }
  bool woke = false;
  for (std::size_t k = 0; k < pairs_.size(); ++k)
  {
    if (collided_[k] != Collided::Hit)
    {
      continue;
    }
    for (std::size_t i : {pairs_[k].first, pairs_[k].second})
    {
      if (asleep_[i])
      {
        keep_sleeping_for_rollback(true);
        rest_time_[i] = 0.0;  // being reached is not resting
        wake_island(island_label_[i], contacts_);
        woke = true;
      }
    }
  }
  return woke;
}

void WorldImpl::keep_sleeping_for_rollback(bool starting_contacts)
{
  // Woken contacts join the cache, which may hold the step's starting
  // contacts: those are kept too.
  // Once published over, they are gone; nothing can refuse the step after
  // its one publish (require_finite_state comes first).
  if (rollback_.active && starting_contacts && rollback_.contacts_in_place && !rollback_.contacts_published)
  {
    rollback_.contacts = contacts_;
    rollback_.contacts_in_place = false;
  }
  if (!rollback_.active || rollback_.sleeping_kept)
  {
    return;
  }
  // The copies come first: one that runs out of memory leaves the flag
  // down, so the rollback puts back the state it kept before, not a copy
  // cut short.
  rollback_.sleeping_contacts = sleeping_contacts_;
  rollback_.island_label = island_label_;
  rollback_.sleeping_penetration = sleeping_penetration_;
  rollback_.next_island_label = next_island_label_;
  rollback_.sleeping_kept = true;
  // The resting bodies are about to change too: they are still as the step
  // found them (the step after they came to rest kept every body, so their
  // entries are normally fresh already; this does not rely on it).
  if (rollback_.movers_only)
  {
    rollback_.movers_only = false;
    for (std::size_t i : resting_)
    {
      keep_body(i);
    }
  }
}

void WorldImpl::sort_out_sleeping()
{
  std::stable_sort(contacts_.begin(), contacts_.end(), pair_order);
  sleeping_contacts_.clear();
  island_label_.assign(bodies_.size(), 0);
  // Aside go the contacts with a sleeping body, as put_contacts_aside sends
  // them. The rest stay in the step's list even when neither body moves (two
  // bodies made static): the next frame drops those, as in the world saved.
  const auto awake = [this](const WorldContact& c) { return !asleep_[c.contact.a] && !asleep_[c.contact.b]; };
  const auto aside = std::stable_partition(contacts_.begin(), contacts_.end(), awake);
  sleeping_contacts_.assign(aside, contacts_.end());
  contacts_.erase(aside, contacts_.end());
  // Islands: the sleeping bodies linked by the contacts kept aside.
  island_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i)
  {
    island_[i] = i;
  }
  for (const WorldContact& c : sleeping_contacts_)
  {
    if (asleep_[c.contact.a] && asleep_[c.contact.b])
    {
      island_[island_root(island_, c.contact.a)] = island_root(island_, c.contact.b);
    }
  }
  label_new_sleepers();
  measure_sleeping_penetration();
}

void WorldImpl::measure_sleeping_penetration()
{
  sleeping_penetration_ = 0.0;
  for (const WorldContact& c : sleeping_contacts_)
  {
    sleeping_penetration_ = std::max(sleeping_penetration_, c.contact.penetration);
  }
}

const std::vector<WorldContact>& WorldImpl::all_contacts() const
{
  if (sleeping_contacts_.empty())
  {
    return contacts_;
  }
  all_contacts_.clear();
  all_contacts_.reserve(contacts_.size() + sleeping_contacts_.size());
  std::merge(contacts_.begin(), contacts_.end(), sleeping_contacts_.begin(), sleeping_contacts_.end(),
             std::back_inserter(all_contacts_), pair_order);
  return all_contacts_;
}

}  // namespace detail
}  // namespace collision2d
