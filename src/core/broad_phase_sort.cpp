// The broad phase's pairs sorted by (i, j): a counting sort on the first box,
// then each box's few partners sorted, O(n + pairs) where a full sort would be
// O(pairs log pairs). Shared, each part sorts the pairs whose first box is in
// its share of the boxes, so no two parts write the same count or slot.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "collision2d/broad_phase.h"
#include "broad_phase_parts.h"
#include "scratch_buffer.h"

namespace collision2d
{
void BroadPhase::choose_owners(std::size_t box_count, std::size_t parts)
{
  // An owner's work is a count and a group per box and a move per pair.
  // pair_start_ holds where each box's group of the last call's pairs
  // started, with their count at its end: the boxes before box i and their
  // pairs cost i + pair_start_[i], which grows with i.
  owner_box_.resize(parts + 1);
  owner_box_[0] = 0;
  owner_box_[parts] = box_count;  // every box has an owner, whatever the last call left
  if (pair_start_.size() != box_count + 1)
  {
    for (std::size_t owner = 1; owner < parts; ++owner)
    {
      owner_box_[owner] = detail::part_begin(box_count, owner, parts);  // no pairs known: by boxes alone
    }
    return;
  }
  const std::size_t total = box_count + pair_start_[box_count];
  for (std::size_t owner = 1; owner < parts; ++owner)
  {
    const std::size_t share = detail::part_begin(total, owner, parts);
    std::size_t lo = owner_box_[owner - 1];
    std::size_t hi = box_count;
    while (lo < hi)
    {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (mid + pair_start_[mid] < share)
      {
        lo = mid + 1;
      }
      else
      {
        hi = mid;
      }
    }
    owner_box_[owner] = lo;
  }
}

void BroadPhase::sort_by_owner(std::size_t box_count, std::size_t parts, RangeRunner* runner,
                               std::vector<BodyPair>& pairs)
{
  // Each owner's stretch starts after the pairs of the owners before it.
  owner_start_.assign(parts + 1, 0);
  for (const BodyPair& p : large_pairs_)  // few
  {
    ++owner_start_[owner_of(p.first) + 1];
  }
  for (std::size_t k = 0; k < part_pairs_.size(); ++k)
  {
    owner_start_[k % parts + 1] += part_pairs_[k].pairs.size();
  }
  for (std::size_t owner = 0; owner < parts; ++owner)
  {
    owner_start_[owner + 1] += owner_start_[owner];
  }
  // Every count and slot is written by its owner before it is read. The
  // sorted pairs go straight into `pairs`, which keeps its own block: only
  // slots past its last size are new.
  pair_start_.resize(box_count + 1);
  detail::resize_to_overwrite(pairs, owner_start_[parts]);
  detail::for_each_part(runner, parts, [&](std::size_t owner) { sort_owned(owner, parts, pairs); });
  pair_start_[box_count] = owner_start_[parts];
}

void BroadPhase::sort_owned(std::size_t owner, std::size_t parts, std::vector<BodyPair>& sorted)
{
  const std::size_t first = owner_box_[owner];
  const std::size_t last = owner_box_[owner + 1];
  // Each source in the same order for the count and the scatter.
  const auto for_each_owned = [&](auto f) {
    for (std::size_t source = 0; source < parts; ++source)
    {
      for (const BodyPair& p : part_pairs_[source * parts + owner].pairs)
      {
        f(p);
      }
    }
    for (const BodyPair& p : large_pairs_)
    {
      if (p.first >= first && p.first < last)
      {
        f(p);
      }
    }
  };
  std::fill(pair_start_.begin() + static_cast<std::ptrdiff_t>(first),
            pair_start_.begin() + static_cast<std::ptrdiff_t>(last), 0);
  for_each_owned([this](const BodyPair& p) { ++pair_start_[p.first]; });
  std::size_t end = owner_start_[owner];
  for (std::size_t i = first; i < last; ++i)
  {
    end += pair_start_[i];
    pair_start_[i] = end;  // one past the group's end, decremented while scattering
  }
  for_each_owned([&](const BodyPair& p) { sorted[--pair_start_[p.first]] = p; });
  // The last group ends where the next owner's stretch starts (its first
  // count is that owner's to write).
  for (std::size_t i = first; i < last; ++i)
  {
    const std::size_t group_end = i + 1 < last ? pair_start_[i + 1] : owner_start_[owner + 1];
    if (group_end - pair_start_[i] < 2)
    {
      continue;  // in order already (most boxes: a call each would cost more than the sorts)
    }
    std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(pair_start_[i]),
              sorted.begin() + static_cast<std::ptrdiff_t>(group_end));
  }
}

}  // namespace collision2d
