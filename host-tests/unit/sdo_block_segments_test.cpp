// blockSegments(): ceil(bytes / 7) up to the 127 segments of a block, for every size up to past
// the cap, and for the largest sizes.
#include "costa/sdo_block_segments.hpp"

#include <gtest/gtest.h>
#include <stddef.h>
#include <stdint.h>

namespace costa {
namespace {

static_assert(blockSegments(0) == 0U);
static_assert(blockSegments(882) == 126U);
static_assert(blockSegments(883) == 127U);
static_assert(blockSegments(889) == 127U);
static_assert(blockSegments(890) == 127U);

TEST(SdoBlockSegments, CountsTheSegmentsUpToABlock) {
  for (size_t bytes = 0; bytes <= 2000U; ++bytes) {
    const size_t segments = (bytes + 6U) / 7U;
    EXPECT_EQ(blockSegments(bytes), segments < 127U ? segments : 127U) << bytes;
  }
}

TEST(SdoBlockSegments, TheLargestSizesTakeAWholeBlock) {
  EXPECT_EQ(blockSegments(13109U), 127U);
  EXPECT_EQ(blockSegments(13110U), 127U);
  EXPECT_EQ(blockSegments(UINT32_MAX), 127U);
  EXPECT_EQ(blockSegments(SIZE_MAX), 127U);
}

}  // namespace
}  // namespace costa
