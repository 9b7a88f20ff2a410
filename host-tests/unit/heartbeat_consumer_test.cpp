// Heartbeat consumer (0x1016): monitoring starts at the first heartbeat, timeouts raise EMCY
// 0x8130 (manufacturer byte: the producer's node-id) and apply 0x1029, a returning producer
// resets the error.
#include <algorithm>

#include "example_fixture.hpp"

namespace costa::test {
namespace {

using HeartbeatConsumerTest = ExampleNodeTest;

/// 0x1016:01 = node 5 every 100 ms.
constexpr const char* kNode5Every100Ms = R"(
    rx 601 [8] 23 16 10 01 64 00 05 00   # node 5, 100 ms
    tx 581 [8] 60 16 10 01 00 00 00 00
)";

class RecordingHeartbeatEvents : public NodeEvents {
 public:
  void onHeartbeatTimeout(uint8_t nodeId) noexcept override { lastTimeout = nodeId; }
  void onHeartbeatResumed(uint8_t nodeId) noexcept override { lastResumed = nodeId; }
  uint8_t lastTimeout = 0;
  uint8_t lastResumed = 0;
};

TEST_F(HeartbeatConsumerTest, TimeoutAfterTheFirstHeartbeatAndReturn) {
  RecordingHeartbeatEvents events;
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_TRANSCRIPT(kNode5Every100Ms);
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    wait 1000
    silence                              # not monitored before its first heartbeat
    rx 705 [1] 05
    wait 99
    rx 705 [1] 05
    wait 99
    silence
    wait 1
    tx 081 [8] 30 81 11 05 00 00 00 00
  )");
  EXPECT_EQ(events.lastTimeout, 5U);
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
  EXPECT_TRANSCRIPT(R"(
    wait 1000
    silence
    rx 705 [1] 7F
    tx 081 [8] 00 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(events.lastResumed, 5U);
}

// Reset communication starts monitoring over (0x1016 back to its default): the error it found
// is gone with it.
TEST_F(HeartbeatConsumerTest, ResetCommunicationClearsATimeoutsError) {
  EXPECT_TRANSCRIPT(kNode5Every100Ms);
  EXPECT_TRANSCRIPT(R"(
    rx 705 [1] 05
    wait 100
    tx 081 [8] 30 81 11 05 00 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # no error left
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 00 00 00 00
  )");
}

// A new value of an entry that had timed out starts its monitoring over, as reset
// communication does: the error it had found is cleared (after the SDO answer), and a timeout
// under the new value is reported again.
TEST_F(HeartbeatConsumerTest, ANewEntryClearsTheErrorItsOldValueFound) {
  RecordingHeartbeatEvents events;
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_TRANSCRIPT(kNode5Every100Ms);
  EXPECT_TRANSCRIPT(R"(
    rx 705 [1] 05
    wait 100
    tx 081 [8] 30 81 11 05 00 00 00 00
    rx 601 [8] 23 16 10 01 00 00 00 00   # the entry off
    tx 581 [8] 60 16 10 01 00 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # no error left
    rx 601 [8] 23 16 10 01 C8 00 06 00   # node 6, 200 ms
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 706 [1] 05
    wait 200
    tx 081 [8] 30 81 11 06 00 00 00 00   # its own timeout: a new EMCY
    rx 601 [8] 23 16 10 01 C8 00 06 00   # the same value again: nothing starts over
    tx 581 [8] 60 16 10 01 00 00 00 00
    wait 1000
    silence
  )");
  EXPECT_EQ(events.lastTimeout, 6U);
  EXPECT_EQ(events.lastResumed, 0U);  // no heartbeat came back
}

// The same at the one microsecond whose clock value means "no deadline" (kNever): the
// withdrawal is still due at once (atOnce()), not left for a later deadline.
TEST_F(HeartbeatConsumerTest, ANewEntryAtTheLastMicrosecondOfTheClockClearsItsError) {
  EXPECT_TRANSCRIPT(kNode5Every100Ms);
  EXPECT_TRANSCRIPT(R"(
    rx 705 [1] 05
    wait 100
    tx 081 [8] 30 81 11 05 00 00 00 00
  )");
  while (bus_.now() != kNever) {  // in steps the node's clock follows (kLongestDelay)
    bus_.advance(std::min<Microseconds>(kNever - bus_.now(), kLongestDelay));
  }
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 16 10 01 00 00 00 00   # the entry off
    tx 581 [8] 60 16 10 01 00 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # no error left
  )");
  EXPECT_EQ(bus_.node().now(), kNever);
}

TEST_F(HeartbeatConsumerTest, EntriesWithNodeIdZeroOrTimeZeroAreDisabled) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 16 10 01 00 00 05 00   # time 0
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 601 [8] 23 16 10 02 64 00 00 00   # node 0
    tx 581 [8] 60 16 10 02 00 00 00 00
    rx 705 [1] 05
    rx 700 [1] 05
    wait 5000
    silence
  )");
}

TEST_F(HeartbeatConsumerTest, TwoEntriesForOneNodeAbort_06040043) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 16 10 01 64 00 05 00
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 601 [8] 23 16 10 02 C8 00 05 00
    tx 581 [8] 80 16 10 02 43 00 04 06
    rx 601 [8] 23 16 10 01 C8 00 05 00   # the same entry may change
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 601 [8] 23 16 10 02 C8 00 00 05   # reserved bits 31..24
    tx 581 [8] 80 16 10 02 30 00 09 06
  )");
}

TEST_F(HeartbeatConsumerTest, SeveralProducersAreMonitoredIndependently) {
  EXPECT_TRANSCRIPT(kNode5Every100Ms);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 16 10 02 C8 00 06 00   # node 6, 200 ms
    tx 581 [8] 60 16 10 02 00 00 00 00
    rx 601 [8] 2F 29 10 01 01 00 00 00   # no state change on errors
    tx 581 [8] 60 29 10 01 00 00 00 00
    rx 705 [1] 05
    rx 706 [1] 00                        # a boot-up counts as a heartbeat
    wait 100
    tx 081 [8] 30 81 11 05 00 00 00 00
    wait 100
    tx 081 [8] 30 81 11 06 00 00 00 00
    rx 706 [1] 7F
    silence                              # node 5 is still missing
    rx 705 [1] 7F
    tx 081 [8] 00 00 00 00 00 00 00 00
  )");
}

}  // namespace
}  // namespace costa::test
