// The frame buffers' sizing (src/core/scratch_buffer.h): mapping pages ahead
// of their first write must leave what memory already holds as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "scratch_buffer.h"

namespace collision2d
{
namespace detail
{
namespace
{
/// Enough elements to span many 4 kB pages.
constexpr std::size_t kElements = 1 << 16;

std::uint64_t pattern(std::size_t k) { return 0x9e3779b97f4a7c15ULL * (k + 1); }

TEST(ScratchBuffer, PrefaultingKeepsWhatThePagesHold)
{
  std::vector<std::uint64_t> held(kElements);
  for (std::size_t k = 0; k < held.size(); ++k)
  {
    held[k] = pattern(k);
  }
  // A range that starts and ends inside pages, as a buffer's new tail does.
  prefault_pages(held.data() + 3, held.data() + held.size() - 5);
  for (std::size_t k = 0; k < held.size(); ++k)
  {
    ASSERT_EQ(held[k], pattern(k)) << "element " << k;
  }
}

TEST(ScratchBuffer, GrowingWithinCapacityKeepsTheWrittenElements)
{
  FrameBuffer<std::uint64_t> buffer;
  resize_to_overwrite(buffer, kElements / 4);
  const std::size_t capacity = buffer.capacity();
  ASSERT_GE(capacity, kElements / 2);  // room for twice the count
  for (std::size_t k = 0; k < buffer.size(); ++k)
  {
    buffer[k] = pattern(k);
  }
  // The new tail's pages are mapped before the caller writes them; the
  // elements before it are left alone, and the block is not replaced.
  resize_to_overwrite(buffer, kElements / 2);
  EXPECT_EQ(buffer.capacity(), capacity);
  for (std::size_t k = 0; k < kElements / 4; ++k)
  {
    ASSERT_EQ(buffer[k], pattern(k)) << "element " << k;
  }
}

TEST(ScratchBuffer, GrowingPastCapacityTakesRoomForTwiceTheCount)
{
  FrameBuffer<std::uint64_t> buffer;
  resize_to_overwrite(buffer, 10);
  resize_to_overwrite(buffer, kElements);
  EXPECT_EQ(buffer.size(), kElements);
  EXPECT_GE(buffer.capacity(), 2 * kElements);
  for (std::size_t k = 0; k < buffer.size(); ++k)
  {
    buffer[k] = pattern(k);  // every new page writable
  }
  EXPECT_EQ(buffer[kElements - 1], pattern(kElements - 1));
}

TEST(ScratchBuffer, BuffersTakingABlockInTurnShareItsMemory)
{
  FrameBlock block;
  FrameSpan<std::uint64_t> first;
  place_together(block, part(first, kElements / 2));
  for (std::size_t k = 0; k < first.size(); ++k)
  {
    first[k] = pattern(k);
  }
  const std::size_t capacity = block.capacity();
  ASSERT_GE(capacity, kElements * sizeof(std::uint64_t));  // room for twice the bytes
  // A second buffer within the capacity takes the same bytes, as they are:
  // the block holds the larger of the two, not their sum.
  FrameSpan<std::uint32_t> second;
  place_together(block, part(second, kElements));
  EXPECT_EQ(static_cast<void*>(second.data()), static_cast<void*>(first.data()));
  EXPECT_EQ(block.capacity(), capacity);
  for (std::size_t k = 0; k < kElements / 2; ++k)
  {
    ASSERT_EQ(first[k], pattern(k)) << "element " << k;
  }
}

TEST(ScratchBuffer, AGrowingBlockTakesRoomForTwiceAndMapsWhatItHands)
{
  FrameBlock block;
  block.take(64);
  unsigned char* bytes = block.take(kElements);
  EXPECT_GE(block.capacity(), 2 * kElements);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(bytes) % 64, 0U) << "aligned for any frame buffer";
  for (std::size_t k = 0; k < kElements; ++k)
  {
    bytes[k] = static_cast<unsigned char>(k);  // every byte handed out is writable
  }
  EXPECT_EQ(bytes[kElements - 1], static_cast<unsigned char>(kElements - 1));
}

TEST(ScratchBuffer, ACopiedBlockAndItsSpansStartEmpty)
{
  FrameBlock block;
  FrameSpan<double> span;
  place_together(block, part(span, 100));
  span[99] = 1.5;
  const FrameBlock block_copy = block;  // NOLINT(performance-unnecessary-copy-initialization): the copy is the test
  FrameSpan<double> span_copy = span;
  EXPECT_EQ(block_copy.capacity(), 0U);
  EXPECT_TRUE(span_copy.empty());
  EXPECT_EQ(span_copy.data(), nullptr);
  span_copy = span;
  EXPECT_TRUE(span_copy.empty()) << "assigning leaves it empty too";
  EXPECT_EQ(span[99], 1.5) << "the original keeps its block";
  FrameBlock moved = std::move(block);
  EXPECT_GE(moved.capacity(), 100 * sizeof(double));
  EXPECT_EQ(block.capacity(), 0U);  // NOLINT(bugprone-use-after-move): a moved-from block is empty
  EXPECT_EQ(span[99], 1.5) << "the bytes moved with the block";
}

TEST(ScratchBuffer, ABufferGrownPastALargeBlockHoldsWhatIsWrittenAfter)
{
  // Growing frees the old block with its pages given back (they read as
  // zeros if the heap hands them out again); the new one holds every write.
  FrameBuffer<std::uint64_t> buffer;
  const std::size_t n = 2 * kGiveBackFrom / sizeof(std::uint64_t);
  resize_to_overwrite(buffer, n);
  std::fill(buffer.begin(), buffer.end(), pattern(0));
  resize_to_overwrite(buffer, 3 * n);
  for (std::size_t k = 0; k < buffer.size(); ++k)
  {
    buffer[k] = pattern(k + 7);
  }
  for (std::size_t k = 0; k < buffer.size(); ++k)
  {
    ASSERT_EQ(buffer[k], pattern(k + 7)) << "element " << k;
  }
  FrameBlock block;
  block.take(kGiveBackFrom);
  unsigned char* bytes = block.take(4 * kGiveBackFrom);  // grows: the old block's pages go back
  bytes[4 * kGiveBackFrom - 1] = 1;
  EXPECT_EQ(bytes[4 * kGiveBackFrom - 1], 1);
}

TEST(ScratchBuffer, ReservingToOverwriteKeepsABlockWithRoomAndTakesExactlyWhatItAsks)
{
  FrameBuffer<std::uint64_t> keys;
  reserve_to_overwrite(keys, kElements);
  EXPECT_EQ(keys.capacity(), kElements) << "exactly the room asked for";
  const std::uint64_t* block = keys.data();
  keys.push_back(pattern(1));
  reserve_to_overwrite(keys, kElements / 2);
  EXPECT_EQ(keys.data(), block) << "room enough: the block stays";
  EXPECT_EQ(keys.front(), pattern(1)) << "and so does what it holds";
  reserve_to_overwrite(keys, 2 * kElements);
  EXPECT_GE(keys.capacity(), 2 * kElements);
  EXPECT_TRUE(keys.empty()) << "an outgrown block's contents are dead";
}

#if defined(__linux__)
constexpr std::size_t kPageBytes = 4096;

/// How many of the whole pages inside [begin, begin + bytes) are resident.
std::size_t resident_pages(const void* begin, std::size_t bytes)
{
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + kPageBytes - 1) & ~(kPageBytes - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(begin) + bytes) & ~(kPageBytes - 1);
  std::vector<unsigned char> in_core((last - first) / kPageBytes);
  if (in_core.empty() || mincore(reinterpret_cast<void*>(first), last - first, in_core.data()) != 0)
  {
    return 0;
  }
  std::size_t resident = 0;
  for (const unsigned char page : in_core)
  {
    resident += page & 1U;
  }
  return resident;
}

TEST(ScratchBuffer, AnOutgrownHeapBlockGivesItsPagesBack)
{
  // A public vector (the published contacts) lives in the heap; its pages
  // go back to the system once it has been outgrown.
  std::vector<std::uint64_t> held(4 * kGiveBackFrom / sizeof(std::uint64_t));
  for (std::size_t k = 0; k < held.size(); ++k)
  {
    held[k] = pattern(k);
  }
  const std::size_t bytes = held.size() * sizeof(std::uint64_t);
  const std::size_t whole_pages = bytes / kPageBytes - 1;
  ASSERT_GE(resident_pages(held.data(), bytes), whole_pages);
  give_back_pages(held.data(), bytes);
  EXPECT_EQ(resident_pages(held.data(), bytes), 0U);
  // Below the threshold a block is left to the heap: it still holds its words.
  std::vector<std::uint64_t> smaller(kGiveBackFrom / 2 / sizeof(std::uint64_t), 3);
  give_back_pages(smaller.data(), smaller.size() * sizeof(std::uint64_t));
  EXPECT_EQ(std::count(smaller.begin(), smaller.end(), 3U), static_cast<std::ptrdiff_t>(smaller.size()));
  free_outgrown(held);
  EXPECT_EQ(held.capacity(), 0U);
}
#endif

}  // namespace
}  // namespace detail
}  // namespace collision2d
