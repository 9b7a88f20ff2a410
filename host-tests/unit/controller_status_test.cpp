// CAN controller conditions reported by the port: overrun, error passive, bus-off.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using ControllerStatus = ExampleNodeTest;

TEST_F(ControllerStatus, OverrunAndErrorPassive) {
  withNode([](Node& node) { node.onControllerEvent(CanControllerEvent::kRxOverrun, node.now()); });
  EXPECT_TRANSCRIPT("tx 081 [8] 10 81 11 00 00 00 00 00");
  EXPECT_EQ(value(0x1001, 0), 0U);  // an event, not a lasting condition
  withNode(
      [](Node& node) { node.onControllerEvent(CanControllerEvent::kErrorPassive, node.now()); });
  EXPECT_TRANSCRIPT("tx 081 [8] 20 81 11 00 00 00 00 00");
  EXPECT_EQ(value(0x1001, 0), 0x11U);
  withNode(
      [](Node& node) { node.onControllerEvent(CanControllerEvent::kErrorActive, node.now()); });
  EXPECT_TRANSCRIPT("tx 081 [8] 00 00 00 00 00 00 00 00");
  EXPECT_EQ(bus_.node().statistics().rxOverruns, 1U);
}

TEST_F(ControllerStatus, BusOffStopsTransmittingAndRecovers) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 64 00 00 00   # heartbeat 100 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 000 [2] 01 01
  )");
  withNode([](Node& node) { node.onControllerEvent(CanControllerEvent::kBusOff, node.now()); });
  EXPECT_TRUE(bus_.node().busOff());
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);  // 0x1029:01 = 0
  EXPECT_TRANSCRIPT("wait 250\nsilence");
  EXPECT_EQ(bus_.node().statistics().busOffs, 1U);
  withNode(
      [](Node& node) { node.onControllerEvent(CanControllerEvent::kBusOffRecovered, node.now()); });
  EXPECT_TRANSCRIPT(R"(
    tx 701 [1] 7F                        # what waited in the queue goes out first
    tx 701 [1] 7F
    tx 081 [8] 40 81 11 00 00 00 00 00   # recovered from bus-off
    wait 100
    tx 701 [1] 7F
  )");
}

TEST_F(ControllerStatus, AFullQueueDuringBusOffDropsAndCounts) {
  withNode([](Node& node) { node.onControllerEvent(CanControllerEvent::kBusOff, node.now()); });
  for (int i = 0; i < 40; ++i) {
    EXPECT_TRANSCRIPT("rx 601 [8] 40 00 20 00 00 00 00 00");
  }
  EXPECT_EQ(bus_.node().txDropped(), 40U - DefaultNodeCapacity::kTxQueueDepth);
  EXPECT_TRANSCRIPT("silence");
}

}  // namespace
}  // namespace costa::test
