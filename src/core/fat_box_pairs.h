// Internal to the core: the broad phase's pairs kept from frame to frame.
// Pairs are found on boxes enlarged by a fraction of their size; while every
// box stays inside its enlarged one, the pairs of the boxes now are exactly
// the kept pairs whose boxes overlap now, so no grid is built. A stack at
// rest keeps its pairs for as long as it rests.
// New enlarged boxes are paired only once every box has stayed inside them
// for a frame: where bodies crowd (a rain) they overlap many more neighbours
// than the exact boxes, a cost wasted where the boxes leave them at once.
// Where boxes keep leaving, the exact boxes are paired and enlarging is tried
// again after a wait that doubles. But where boxes leave enlarged boxes that
// served for frames and paired few more boxes than the exact ones (a stack
// settling sinks out of them every few frames), new ones are made and paired
// at once, and give that frame's pairs too. A few boxes
// (BroadPhase::kAllPairsBoxes) are always paired directly.
#pragma once

#include <cstddef>
#include <vector>

#include "collision2d/broad_phase.h"

namespace collision2d
{
namespace detail
{
class FatBoxPairs
{
public:
  /// Replaces `pairs` with BroadPhase::find_pairs(boxes): the same pairs in
  /// the same order. Pairs name positions in `boxes`, so whose box is where
  /// does not matter, only that each box lies inside its enlarged one.
  void find_pairs(const std::vector<Aabb>& boxes, BroadPhase& broad_phase, std::vector<BodyPair>& pairs,
                  RangeRunner& runner);
  /// Frames whose pairs came from the kept ones (tests).
  std::size_t reused() const { return reused_; }
  /// Times the enlarged boxes were paired (tests).
  std::size_t built() const { return built_count_; }
  /// Frames whose pairs came from pairing the exact boxes (tests).
  std::size_t paired_exactly() const { return exact_count_; }
  /// Drops the enlarged boxes and their pairs: the next call pairs the boxes
  /// afresh. For a step that failed partway, which may have left them half
  /// written.
  void forget()
  {
    enlarged_ = false;
    built_ = false;
  }

private:
  /// Whether every box lies inside its enlarged one (in parts on the runner).
  bool still_inside(const std::vector<Aabb>& boxes, RangeRunner& runner);
  /// The boxes enlarged, their pairs left until a frame shows they hold.
  void enlarge(const std::vector<Aabb>& boxes);
  /// Whether to enlarge the boxes again at once where they left the last
  /// enlarged ones, and pair those now.
  bool worth_rebuilding() const;
  /// `pairs` from the exact boxes, counted (paired_exactly).
  void pair_exactly(const std::vector<Aabb>& boxes, BroadPhase& broad_phase, std::vector<BodyPair>& pairs,
                    RangeRunner& runner);
  /// fat_pairs_ from fat_.
  void build(BroadPhase& broad_phase, RangeRunner& runner);
  /// `pairs` from fat_pairs_ (keep_overlapping), counted as a frame they served.
  void serve(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner& runner);
  /// `pairs`: the kept pairs whose boxes overlap now, in order (in parts on the runner).
  void keep_overlapping(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs, RangeRunner& runner);

  std::vector<Aabb> fat_;            ///< the enlarged boxes
  std::vector<BodyPair> fat_pairs_;  ///< every pair of overlapping enlarged boxes, in (i, j) order
  bool enlarged_ = false;            ///< fat_ holds a frame's boxes enlarged
  bool built_ = false;               ///< fat_pairs_ are fat_'s pairs
  std::size_t reused_ = 0;
  std::size_t built_count_ = 0;
  std::size_t exact_count_ = 0;
  int wait_ = 1;            ///< frames the next failed reuse waits before enlarging again
  int frames_to_wait_ = 0;  ///< frames left that pair the exact boxes
  int served_ = 0;          ///< frames fat_pairs_ gave the pairs since they were built
  std::size_t exact_pairs_ = 0;  ///< pairs they gave in the last of those frames
  // Scratch of the work in parts.
  std::vector<std::vector<BodyPair>> part_pairs_;  ///< each part's kept pairs
  std::vector<unsigned char> part_inside_;  ///< each part's boxes all inside
};

}  // namespace detail
}  // namespace collision2d
