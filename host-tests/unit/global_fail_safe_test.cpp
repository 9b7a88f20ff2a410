// The global fail-safe command (GFC, CiA 304) through wire frames: COB-ID 0x001, no data,
// enabled by 0x1300 = 1 (the example's default).
#include "example_fixture.hpp"

namespace costa::test {
namespace {

class FailSafeCount : public NodeEvents {
 public:
  void onGlobalFailSafe() noexcept override { ++count; }
  int count = 0;
};

class GlobalFailSafeTest : public ExampleNodeTest {
 protected:
  void SetUp() override {
    ExampleNodeTest::SetUp();
    ASSERT_TRUE(bus_.node().addListener(events_));
  }
  uint32_t ignored() { return bus_.node().statistics().framesIgnored; }

  FailSafeCount events_;
};

TEST_F(GlobalFailSafeTest, AConsumedGfcReachesTheListenersInEveryStateAfterBootUp) {
  EXPECT_TRANSCRIPT("rx 001 [0]   # pre-operational");
  EXPECT_EQ(events_.count, 1);
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 00
    rx 001 [0]                    # operational
    rx 000 [2] 02 00
    rx 001 [0]                    # stopped
  )");
  EXPECT_EQ(events_.count, 3);
  EXPECT_EQ(ignored(), 0U);
}

TEST_F(GlobalFailSafeTest, AGfcWithDataOrARemoteFrameIsIgnored) {
  EXPECT_TRANSCRIPT(R"(
    rx 001 [1] 00
    rx 001 [0] RTR
  )");
  EXPECT_EQ(events_.count, 0);
  EXPECT_EQ(ignored(), 2U);
}

TEST_F(GlobalFailSafeTest, NotValidGfcIsNeitherConsumedNorProduced) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 13 00 00 00 00 00   # 0x1300 = 0: not valid
    tx 581 [8] 60 00 13 00 00 00 00 00
    rx 001 [0]
  )");
  EXPECT_EQ(events_.count, 0);
  EXPECT_EQ(ignored(), 1U);
  withNode([](Node& node) { EXPECT_FALSE(node.sendGlobalFailSafe()); });
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 13 00 01 00 00 00   # valid again
    tx 581 [8] 60 00 13 00 00 00 00 00
    rx 001 [0]
  )");
  EXPECT_EQ(events_.count, 1);
}

TEST_F(GlobalFailSafeTest, OnlyZeroAndOneAreAccepted) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 13 00 02 00 00 00
    tx 581 [8] 80 00 13 00 30 00 09 06
    rx 601 [8] 40 00 13 00 00 00 00 00
    tx 581 [8] 4F 00 13 00 01 00 00 00
  )");
}

TEST_F(GlobalFailSafeTest, TheApplicationSendsGfcInPreOperationalAndOperationalOnly) {
  withNode([](Node& node) { EXPECT_TRUE(node.sendGlobalFailSafe()); });
  EXPECT_TRANSCRIPT("tx 001 [0]");
  EXPECT_TRANSCRIPT("rx 000 [2] 01 00");
  withNode([](Node& node) { EXPECT_TRUE(node.sendGlobalFailSafe()); });
  EXPECT_TRANSCRIPT("tx 001 [0]");
  EXPECT_TRANSCRIPT("rx 000 [2] 02 00");
  withNode([](Node& node) { EXPECT_FALSE(node.sendGlobalFailSafe()); });
  EXPECT_EQ(bus_.unread(), 0U);
  EXPECT_EQ(events_.count, 0);  // its own GFC does not reach the node
}

}  // namespace
}  // namespace costa::test
