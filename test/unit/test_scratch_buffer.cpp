// The frame buffers' sizing (src/core/scratch_buffer.h): mapping pages ahead
// of their first write must leave what memory already holds as it was.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

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

}  // namespace
}  // namespace detail
}  // namespace collision2d
