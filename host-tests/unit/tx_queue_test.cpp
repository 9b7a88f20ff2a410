// The node's transmit queue: bounded, never blocking, drops counted; frames refused by the
// controller are kept and offered again.
#include <gtest/gtest.h>

#include "costa/tx_queue.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

TEST(TxQueue, KeepsOrderAndCountsDropsWhenFull) {
  QueuedFrame slots[3];
  TxQueue queue(slots, 3);
  for (uint32_t id = 1; id <= 5; ++id) {
    CanFrame frame;
    frame.id = id;
    queue.push(frame);
  }
  EXPECT_EQ(queue.size(), 3U);
  EXPECT_EQ(queue.dropped(), 2U);
  for (uint32_t id = 1; id <= 3; ++id) {
    EXPECT_EQ(queue.front().frame.id, id);
    queue.pop();
  }
  EXPECT_TRUE(queue.empty());
  queue.pop();  // harmless
  EXPECT_TRUE(queue.empty());
}

using TxPath = ExampleNodeTest;

TEST_F(TxPath, FramesRefusedByTheControllerAreSentLaterInOrder) {
  bus_.can().setAccepting(false);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 00 20 00 00 00 00 00
    rx 601 [8] 40 10 20 00 00 00 00 00
    silence
  )");
  EXPECT_TRUE(bus_.node().txPending());
  EXPECT_GE(bus_.node().statistics().txRefused, 1U);
  bus_.can().setAccepting(true);
  bus_.node().flushTx();
  EXPECT_TRANSCRIPT(R"(
    tx 581 [8] 43 00 20 00 E8 03 00 00
    tx 581 [8] 4F 10 20 00 00 00 00 00
  )");
  EXPECT_FALSE(bus_.node().txPending());
}

TEST_F(TxPath, AFullQueueDropsAndCountsButNeverBlocks) {
  bus_.can().setAccepting(false);
  for (int i = 0; i < 40; ++i) {
    EXPECT_EQ(play("rx 601 [8] 40 00 20 00 00 00 00 00"), "");
  }
  EXPECT_EQ(bus_.node().txDropped(), 40U - DefaultNodeCapacity::kTxQueueDepth);
  bus_.can().setAccepting(true);
  bus_.node().flushTx();
  EXPECT_EQ(bus_.unread(), DefaultNodeCapacity::kTxQueueDepth);
}

}  // namespace
}  // namespace costa::test
