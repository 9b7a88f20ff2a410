// Overload: a controller that refuses frames while requests keep coming. What waited is dropped
// and counted, never the boot-up of the next reset; after the reset the node answers at once.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using TransmitFlood = ExampleNodeTest;

constexpr size_t kDepth = DefaultNodeCapacity::kTxQueueDepth;

// Requests whose answers cannot leave: the controller refuses, the queue fills, the rest drop.
void flood(InProcessBus& bus, size_t requests) {
  bus.can().setAccepting(false);
  CanFrame upload;
  upload.id = 0x601;
  upload.dlc = 8;
  upload.data[0] = 0x40;  // upload 0x1000:00
  upload.data[2] = 0x10;
  for (size_t i = 0; i < requests; ++i) {
    bus.send(upload);
  }
}

TEST_F(TransmitFlood, ResetCommunicationDiscardsWhatWaitedAndTheBootUpLeavesFirst) {
  flood(bus_, 1000);
  NodeStatistics statistics = bus_.node().statistics();
  EXPECT_EQ(statistics.txDropped, 1000U - kDepth);
  EXPECT_EQ(bus_.unread(), 0U);
  EXPECT_TRUE(bus_.node().txPending());

  EXPECT_TRANSCRIPT("rx 000 [2] 82 01");  // reset communication, the controller still busy
  bus_.can().setAccepting(true);
  EXPECT_TRANSCRIPT(R"(
    wait 1
    tx 701 [1] 00                        # the boot-up, first and alone
    rx 601 [8] 40 17 10 00 00 00 00 00
    tx 581 [8] 4B 17 10 00 00 00 00 00   # and the next answer at once
  )");
  statistics = bus_.node().statistics();
  EXPECT_EQ(statistics.txDiscarded, kDepth);  // the answers that waited: counted, not sent
  EXPECT_EQ(statistics.txDropped, 1000U - kDepth);
}

// The EMCY of an error that stops the node (0x1029:01 = 2) leaves before the stop, and a busy
// controller does not lose it: it goes when the controller takes it, the node stopped.
TEST_F(TransmitFlood, TheEmcyBeforeAnErrorStopLeavesWhenTheControllerTakesIt) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 16 10 01 64 00 05 00   # monitor node 5, 100 ms
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 601 [8] 2F 29 10 01 02 00 00 00   # on a communication error: stopped
    tx 581 [8] 60 29 10 01 00 00 00 00
    rx 705 [1] 05
  )");
  bus_.can().setAccepting(false);
  EXPECT_TRANSCRIPT("wait 100");  // the timeout: EMCY 0x8130 raised, the node stops
  EXPECT_EQ(bus_.node().state(), NmtState::kStopped);
  bus_.can().setAccepting(true);
  EXPECT_TRANSCRIPT(R"(
    wait 1
    tx 081 [8] 30 81 11 05 00 00 00 00
  )");
}

TEST_F(TransmitFlood, TheBootUpOfAResetNodeIsNotLostInAFullQueue) {
  flood(bus_, 3 * kDepth);
  EXPECT_TRANSCRIPT("rx 000 [2] 81 01");  // reset node while the queue is full
  flood(bus_, 3 * kDepth);                // the flood goes on after the reset
  bus_.can().setAccepting(true);
  bus_.advance(1);
  CanFrame first;
  ASSERT_TRUE(bus_.receive(&first, 0));
  EXPECT_EQ(first.id, 0x701U);  // the boot-up kept its place at the head of the queue
  ASSERT_EQ(first.dlc, 1U);
  EXPECT_EQ(first.data[0], 0x00U);
  EXPECT_EQ(bus_.unread(), kDepth - 1U);  // then the answers that found room
}

}  // namespace
}  // namespace costa::test
