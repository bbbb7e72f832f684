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
void BroadPhase::sort_pairs(std::size_t box_count, std::vector<BodyPair>& pairs, RangeRunner* runner)
{
  pair_start_.assign(box_count + 1, 0);
  for (const BodyPair& p : pairs)
  {
    ++pair_start_[p.first];
  }
  std::size_t end = 0;
  for (std::size_t& start : pair_start_)
  {
    end += start;
    start = end;  // one past the group's end, decremented while scattering
  }
  // Both buffers grow geometrically (they are swapped): a creeping count allocates rarely.
  detail::resize_to_overwrite(sorted_pairs_, pairs.size());  // the scatter writes every slot
  for (const BodyPair& p : pairs)
  {
    sorted_pairs_[--pair_start_[p.first]] = p;
  }
  // Each body's group is its own: the parts sort theirs apart.
  const auto sort_groups = [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
    {
      std::sort(sorted_pairs_.begin() + static_cast<std::ptrdiff_t>(pair_start_[i]),
                sorted_pairs_.begin() + static_cast<std::ptrdiff_t>(pair_start_[i + 1]));
    }
  };
  const std::size_t parts = detail::runner_parts(runner, box_count);
  if (parts == 1)
  {
    sort_groups(0, box_count);
  }
  else
  {
    detail::run_parts(*runner, parts, [&](std::size_t part) {
      sort_groups(detail::part_begin(box_count, part, parts), detail::part_begin(box_count, part + 1, parts));
    });
  }
  // Swapping hands the sorted buffer out and keeps the old one as scratch.
  pairs.swap(sorted_pairs_);
}

void BroadPhase::choose_owners(std::size_t box_count, std::size_t parts)
{
  // An owner's work is a count and a group per box and a move per pair.
  // pair_start_ holds where each box's group of the last call's pairs
  // started, with their count at its end: the boxes before box i and their
  // pairs cost i + pair_start_[i], which grows with i.
  owner_box_.resize(parts + 1);
  const bool known = pair_start_.size() == box_count + 1;
  const std::size_t total = box_count + (known ? pair_start_[box_count] : 0);
  owner_box_[0] = 0;
  for (std::size_t owner = 1; owner <= parts; ++owner)
  {
    const std::size_t share = detail::part_begin(total, owner, parts);
    std::size_t lo = owner_box_[owner - 1];
    std::size_t hi = box_count;
    while (known && lo < hi)
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
    owner_box_[owner] = known ? lo : detail::part_begin(box_count, owner, parts);
  }
}

void BroadPhase::sort_in_parts(std::size_t box_count, std::size_t parts, RangeRunner& runner,
                               std::vector<BodyPair>& pairs)
{
  // Each owner's stretch starts after the pairs of the owners before it.
  owner_start_.assign(parts + 1, 0);
  for (const BodyPair& p : large_pairs_)  // few
  {
    std::size_t owner = 0;
    while (p.first >= owner_box_[owner + 1])
    {
      ++owner;
    }
    ++owner_start_[owner + 1];
  }
  for (std::size_t k = 0; k < part_pairs_.size(); ++k)
  {
    owner_start_[k % parts + 1] += part_pairs_[k].pairs.size();
  }
  for (std::size_t owner = 0; owner < parts; ++owner)
  {
    owner_start_[owner + 1] += owner_start_[owner];
  }
  // Every count and slot is written by its owner before it is read.
  pair_start_.resize(box_count + 1);
  detail::resize_to_overwrite(sorted_pairs_, owner_start_[parts]);
  detail::run_parts(runner, parts, [&](std::size_t owner) { sort_owned(owner, parts); });
  pair_start_[box_count] = owner_start_[parts];
  pairs.swap(sorted_pairs_);
}

void BroadPhase::sort_owned(std::size_t owner, std::size_t parts)
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
  for_each_owned([this](const BodyPair& p) { sorted_pairs_[--pair_start_[p.first]] = p; });
  // The last group ends where the next owner's stretch starts (its first
  // count is that owner's to write).
  for (std::size_t i = first; i < last; ++i)
  {
    const std::size_t group_end = i + 1 < last ? pair_start_[i + 1] : owner_start_[owner + 1];
    std::sort(sorted_pairs_.begin() + static_cast<std::ptrdiff_t>(pair_start_[i]),
              sorted_pairs_.begin() + static_cast<std::ptrdiff_t>(group_end));
  }
}

}  // namespace collision2d
