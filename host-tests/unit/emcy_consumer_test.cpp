// The EMCY consumer (CiA 301 7.2.7, 0x1028) through wire frames. The example consumes the EMCY
// of nodes 2 and 3 (0x1028:01 = 0x082, :02 = 0x083; :03 and :04 not valid) and shows the last
// one in 0x2013 (01 producer, 02 error code, 03 error register, 04 how many).
#include <algorithm>
#include <vector>

#include "example_fixture.hpp"

namespace costa::test {
namespace {

/// Keeps what it hears in a fixed array (the node calls it where nothing may allocate).
class EmcyLog : public NodeEvents {
 public:
  void onEmcyReceived(const EmcyMessage& emcy) noexcept override {
    if (count_ < kCapacity) {
      heard_[count_++] = emcy;
    }
  }
  std::vector<EmcyMessage> heard() const { return {heard_, heard_ + count_}; }

 private:
  static constexpr size_t kCapacity = 8;
  EmcyMessage heard_[kCapacity] = {};
  size_t count_ = 0;
};

class EmcyConsumerTest : public ExampleNodeTest {
 protected:
  void SetUp() override {
    ExampleNodeTest::SetUp();
    ASSERT_TRUE(bus_.node().addListener(log_));
  }
  uint32_t ignored() { return bus_.node().statistics().emcyFramesIgnored; }

  EmcyLog log_;
};

TEST_F(EmcyConsumerTest, AnEmergencyOfAWatchedNodeReachesTheListenersWithItsProducer) {
  EXPECT_TRANSCRIPT(R"(
    rx 082 [8] 10 81 11 AA BB CC DD EE   # node 2: CAN overrun, manufacturer bytes
    rx 601 [8] 40 13 20 01 00 00 00 00
    tx 581 [8] 4F 13 20 01 02 00 00 00
    rx 601 [8] 40 13 20 02 00 00 00 00
    tx 581 [8] 4B 13 20 02 10 81 00 00
    rx 601 [8] 40 13 20 03 00 00 00 00
    tx 581 [8] 4F 13 20 03 11 00 00 00
    rx 083 [8] 00 00 00 00 00 00 00 00   # node 3: error reset
    rx 601 [8] 40 13 20 04 00 00 00 00
    tx 581 [8] 43 13 20 04 02 00 00 00
  )");
  const std::vector<EmcyMessage> heard = log_.heard();
  ASSERT_EQ(heard.size(), 2U);
  const EmcyMessage& first = heard[0];
  EXPECT_EQ(first.canId, 0x082U);
  EXPECT_EQ(first.producer, 2U);
  EXPECT_EQ(first.entry, 1U);
  EXPECT_EQ(first.errorCode, 0x8110U);
  EXPECT_EQ(first.errorRegister, 0x11U);
  const uint8_t manufacturer[5] = {0xAA, 0xBB, 0xCC, 0xDD, 0xEE};
  EXPECT_TRUE(std::equal(manufacturer, manufacturer + 5, first.manufacturer));
  EXPECT_EQ(heard[1].producer, 3U);
  EXPECT_EQ(heard[1].entry, 2U);
  EXPECT_EQ(ignored(), 0U);
}

TEST_F(EmcyConsumerTest, UnwatchedAndMalformedEmergenciesAreIgnored) {
  const uint32_t framesIgnored = bus_.node().statistics().framesIgnored;
  EXPECT_TRANSCRIPT(R"(
    rx 084 [8] 10 81 11 00 00 00 00 00   # node 4: 0x1028:03 is not valid
    rx 082 [7] 10 81 11 00 00 00 00      # seven bytes
    rx 082 [0] RTR
    silence
  )");
  EXPECT_TRUE(log_.heard().empty());
  EXPECT_EQ(ignored(), 2U);
  EXPECT_EQ(bus_.node().statistics().framesIgnored, framesIgnored + 3U);
}

TEST_F(EmcyConsumerTest, AStoppedNodeHearsNoEmergency) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 02 01
    rx 082 [8] 10 81 11 00 00 00 00 00
    rx 000 [2] 01 01
    rx 082 [8] 30 81 11 00 00 00 00 00   # operational: heard
  )");
  const std::vector<EmcyMessage> heard = log_.heard();
  ASSERT_EQ(heard.size(), 1U);
  EXPECT_EQ(heard[0].errorCode, 0x8130U);
}

TEST_F(EmcyConsumerTest, EntriesAreConfiguredBySdoWithTheCanIdRules) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 28 10 03 84 00 00 00   # node 4 too
    tx 581 [8] 60 28 10 03 00 00 00 00
    rx 084 [8] 20 81 11 00 00 00 00 00
    rx 601 [8] 23 28 10 04 A0 01 00 00   # any CAN-ID a configurable object may use
    tx 581 [8] 60 28 10 04 00 00 00 00
    rx 1A0 [8] 00 50 01 00 00 00 00 00
    rx 601 [8] 23 28 10 01 01 06 00 00   # 0x601 (SDO) in a valid entry: restricted
    tx 581 [8] 80 28 10 01 30 00 09 06
    rx 601 [8] 23 28 10 01 01 06 00 80   # ... but fine in an entry that is not valid
    tx 581 [8] 60 28 10 01 00 00 00 00
    rx 082 [8] 10 81 11 00 00 00 00 00   # node 2 no longer watched
    rx 601 [8] 23 28 10 02 83 00 00 20   # 29-bit
    tx 581 [8] 80 28 10 02 30 00 09 06
    rx 601 [8] 23 28 10 02 83 08 00 00   # bit 11: not an 11-bit CAN-ID
    tx 581 [8] 80 28 10 02 30 00 09 06
    rx 601 [8] 2F 28 10 00 02 00 00 00   # the number of entries is constant
    tx 581 [8] 80 28 10 00 02 00 01 06
  )");
  const std::vector<EmcyMessage> heard = log_.heard();
  ASSERT_EQ(heard.size(), 2U);
  EXPECT_EQ(heard[0].producer, 4U);
  EXPECT_EQ(heard[0].entry, 3U);
  EXPECT_EQ(heard[1].canId, 0x1A0U);
  EXPECT_EQ(heard[1].producer, 0U);  // not a pre-defined EMCY CAN-ID
  EXPECT_EQ(heard[1].entry, 4U);
  EXPECT_EQ(heard[1].errorCode, 0x5000U);
}

TEST_F(EmcyConsumerTest, ResetCommunicationRestoresTheWatchedCanIds) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 28 10 01 82 00 00 80   # stop watching node 2
    tx 581 [8] 60 28 10 01 00 00 00 00
    rx 082 [8] 10 81 11 00 00 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    rx 082 [8] 10 81 11 00 00 00 00 00   # watched again (0x1028's defaults)
  )");
  ASSERT_EQ(log_.heard().size(), 1U);
}

}  // namespace
}  // namespace costa::test
