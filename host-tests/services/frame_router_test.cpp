// FrameRouter alone: lookup by CAN-ID, shared CAN-IDs, a full table, 11-bit ids, the stale flag.
#include "costa/frame_router.hpp"

#include <gtest/gtest.h>

#include <string>

namespace costa::test {
namespace {

class FrameRouterTest : public ::testing::Test {
 protected:
  static constexpr size_t kCapacity = 6;

  /// The route `find()` gives for `id`, as "route/channel", or "none".
  std::string routeOf(uint32_t id) const {
    const RouteEntry* entry = router_.find(id);
    if (entry == nullptr) {
      return "none";
    }
    EXPECT_EQ(entry->id, id);
    return std::to_string(static_cast<int>(entry->route)) + "/" + std::to_string(entry->channel);
  }
  static std::string routeText(Route route, uint8_t channel = 0) {
    return std::to_string(static_cast<int>(route)) + "/" + std::to_string(channel);
  }

  RouteEntry slots_[kCapacity];
  FrameRouter router_{slots_, kCapacity};
};

TEST_F(FrameRouterTest, ANewTableIsStaleUntilCleared) {
  EXPECT_TRUE(router_.stale());
  router_.clear();
  EXPECT_FALSE(router_.stale());
  EXPECT_EQ(router_.size(), 0U);
  router_.invalidate();
  EXPECT_TRUE(router_.stale());
}

TEST_F(FrameRouterTest, EveryRouteIsFoundWhateverTheOrderItWasAddedIn) {
  router_.clear();
  EXPECT_TRUE(router_.add(0x605, Route::kSdo));
  EXPECT_TRUE(router_.add(0x000, Route::kNmt));
  EXPECT_TRUE(router_.add(0x7E5, Route::kLss));
  EXPECT_TRUE(router_.add(0x205, Route::kRpdo, 1));
  EXPECT_TRUE(router_.add(0x080, Route::kSync));
  EXPECT_TRUE(router_.add(0x185, Route::kTpdoRequest, 2));
  EXPECT_EQ(routeOf(0x000), routeText(Route::kNmt));
  EXPECT_EQ(routeOf(0x080), routeText(Route::kSync));
  EXPECT_EQ(routeOf(0x185), routeText(Route::kTpdoRequest, 2));
  EXPECT_EQ(routeOf(0x205), routeText(Route::kRpdo, 1));
  EXPECT_EQ(routeOf(0x605), routeText(Route::kSdo));
  EXPECT_EQ(routeOf(0x7E5), routeText(Route::kLss));
  for (uint16_t i = 1; i < kCapacity; ++i) {
    EXPECT_LT(slots_[i - 1U].id, slots_[i].id) << i;  // sorted
  }
  EXPECT_FALSE(router_.shared());
}

TEST_F(FrameRouterTest, CanIdsWithoutARouteFindNothing) {
  router_.clear();
  EXPECT_TRUE(router_.add(0x080, Route::kSync));
  EXPECT_TRUE(router_.add(0x0FF, Route::kRpdo));  // same function code as 0x080
  EXPECT_EQ(routeOf(0x081), "none");
  EXPECT_EQ(routeOf(0x100), "none");  // the next function code has none
  EXPECT_EQ(routeOf(0x000), "none");
  EXPECT_EQ(routeOf(0x7FF), "none");
  EXPECT_EQ(routeOf(0x0FF), routeText(Route::kRpdo));
}

TEST_F(FrameRouterTest, RoutesOfOneCanIdFollowEachOtherInTheOrderAdded) {
  router_.clear();
  EXPECT_TRUE(router_.add(0x200, Route::kRpdo, 0));
  EXPECT_FALSE(router_.shared());
  EXPECT_TRUE(router_.add(0x080, Route::kSync));
  EXPECT_TRUE(router_.add(0x080, Route::kRpdo, 3));  // an RPDO on the SYNC CAN-ID
  EXPECT_TRUE(router_.shared());
  const RouteEntry* first = router_.find(0x080);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->route, Route::kSync);
  const RouteEntry* second = router_.nextOfSameId(first);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(second->route, Route::kRpdo);
  EXPECT_EQ(second->channel, 3U);
  EXPECT_EQ(router_.nextOfSameId(second), nullptr);
  const RouteEntry* alone = router_.find(0x200);
  ASSERT_NE(alone, nullptr);
  EXPECT_EQ(router_.nextOfSameId(alone), nullptr);
}

TEST_F(FrameRouterTest, AFullTableRefusesAndKeepsItsRoutes) {
  router_.clear();
  for (uint16_t i = 0; i < kCapacity; ++i) {
    EXPECT_TRUE(router_.add(static_cast<uint16_t>(0x180 + i), Route::kTpdoRequest,
                            static_cast<uint8_t>(i)));
  }
  EXPECT_FALSE(router_.add(0x080, Route::kSync));
  EXPECT_EQ(router_.size(), kCapacity);
  EXPECT_EQ(routeOf(0x080), "none");
  EXPECT_EQ(routeOf(0x185), routeText(Route::kTpdoRequest, 5));
}

TEST(FrameRouterCapacityTest, MoreThan255SlotsHoldAt255Routes) {
  static RouteEntry slots[300];
  FrameRouter router(slots, 300);
  router.clear();
  for (uint16_t i = 0; i < UINT8_MAX; ++i) {
    EXPECT_TRUE(router.add(i, Route::kRpdo, static_cast<uint8_t>(i)));
  }
  EXPECT_FALSE(router.add(0x7FF, Route::kRpdo));
  EXPECT_EQ(router.size(), size_t{UINT8_MAX});
  EXPECT_EQ(router.find(0x7FF), nullptr);
  ASSERT_NE(router.find(254), nullptr);
  EXPECT_EQ(router.find(254)->channel, 254U);
}

TEST_F(FrameRouterTest, AnIdentifierBeyondElevenBitsIsRefused) {
  router_.clear();
  EXPECT_FALSE(router_.add(0x800, Route::kRpdo));
  EXPECT_EQ(router_.size(), 0U);
  EXPECT_TRUE(router_.add(FrameRouter::kLargestId, Route::kRpdo));
  EXPECT_EQ(routeOf(0x7FF), routeText(Route::kRpdo));
}

TEST_F(FrameRouterTest, ClearForgetsEveryRoute) {
  router_.clear();
  EXPECT_TRUE(router_.add(0x080, Route::kSync));
  EXPECT_TRUE(router_.add(0x080, Route::kRpdo));
  router_.clear();
  EXPECT_EQ(router_.size(), 0U);
  EXPECT_FALSE(router_.shared());
  EXPECT_EQ(routeOf(0x080), "none");
  EXPECT_TRUE(router_.add(0x605, Route::kSdo));
  EXPECT_EQ(routeOf(0x605), routeText(Route::kSdo));
}

TEST_F(FrameRouterTest, AFastCanIdHasOneRouteOfTheKindAskedForUntilTheTableChanges) {
  EXPECT_EQ(router_.fastId(), FrameRouter::kNoFastId);
  router_.clear();
  EXPECT_TRUE(router_.add(0x605, Route::kSdo));
  EXPECT_TRUE(router_.add(0x080, Route::kSync));
  EXPECT_FALSE(router_.setFastId(0x606, Route::kSdo));  // no route
  EXPECT_EQ(router_.fastId(), FrameRouter::kNoFastId);
  EXPECT_FALSE(router_.setFastId(0x080, Route::kSdo));  // another route
  EXPECT_EQ(router_.fastId(), FrameRouter::kNoFastId);
  EXPECT_FALSE(router_.setFastId(0x1605, Route::kSdo));  // beyond 11 bits
  EXPECT_TRUE(router_.setFastId(0x605, Route::kSdo));
  EXPECT_EQ(router_.fastId(), 0x605U);
  router_.invalidate();
  EXPECT_EQ(router_.fastId(), FrameRouter::kNoFastId);
  router_.clear();
  EXPECT_TRUE(router_.add(0x605, Route::kSdo));
  EXPECT_TRUE(router_.setFastId(0x605, Route::kSdo));
  router_.clear();
  EXPECT_EQ(router_.fastId(), FrameRouter::kNoFastId);
}

TEST_F(FrameRouterTest, ACanIdWithSeveralRoutesIsNeverFast) {
  router_.clear();
  EXPECT_TRUE(router_.add(0x605, Route::kSdo));
  EXPECT_TRUE(router_.add(0x605, Route::kRpdo, 1));  // an RPDO on the SDO server's CAN-ID
  EXPECT_FALSE(router_.setFastId(0x605, Route::kSdo));
  EXPECT_EQ(router_.fastId(), FrameRouter::kNoFastId);
}

}  // namespace
}  // namespace costa::test
