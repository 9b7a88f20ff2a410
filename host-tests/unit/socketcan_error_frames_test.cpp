// Linux CAN error frames as controller events (controllerEventsOf), and the example node driven
// by them: the EMCY frames of the bxCAN path.
#include <gtest/gtest.h>
#include <linux/can.h>
#include <linux/can/error.h>

#include <vector>

#include "costa/port/linux/socketcan_error_frames.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using port::controllerEventsOf;
using port::SocketCanErrorState;
using Events = std::vector<CanControllerEvent>;

/// An error frame as the kernel builds it (alloc_can_err_skb: CAN_ERR_DLC bytes), with the
/// error counters (CAN_ERR_CNT) that newer drivers add in data[6] and data[7].
can_frame errorFrame(canid_t errorClass, uint8_t controller = 0, uint8_t tec = 0, uint8_t rec = 0) {
  can_frame frame{};
  frame.can_id = CAN_ERR_FLAG | errorClass | CAN_ERR_CNT;
  frame.len = CAN_ERR_DLC;
  frame.data[1] = controller;
  frame.data[6] = tec;
  frame.data[7] = rec;
  return frame;
}

class SocketCanErrorFrames : public ::testing::Test {
 protected:
  Events translate(const can_frame& frame) {
    const port::SocketCanEvents events = controllerEventsOf(frame, &state_);
    return Events(events.begin(), events.end());
  }
  SocketCanErrorState state_;
};

TEST_F(SocketCanErrorFrames, WarningIsErrorActive) {
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_WARNING, 96)), Events{});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_WARNING, 0, 96)), Events{});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE)), Events{});
  EXPECT_FALSE(state_.errorPassive);
}

TEST_F(SocketCanErrorFrames, ErrorPassiveIsReportedOncePerChange) {
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE, 128)),
            Events{CanControllerEvent::kErrorPassive});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_PASSIVE, 0, 128)), Events{});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_WARNING, 120)),  // falling back
            Events{CanControllerEvent::kErrorActive});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_PASSIVE, 0, 130)),
            Events{CanControllerEvent::kErrorPassive});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE)),
            Events{CanControllerEvent::kErrorActive});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE)), Events{});
}

TEST_F(SocketCanErrorFrames, EitherOverflowIsAnOverrunAndComesFirst) {
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW)),
            Events{CanControllerEvent::kRxOverrun});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_OVERFLOW)),
            Events{CanControllerEvent::kRxOverrun});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW | CAN_ERR_CRTL_TX_PASSIVE)),
            (Events{CanControllerEvent::kRxOverrun, CanControllerEvent::kErrorPassive}));
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW)),  // still passive
            Events{CanControllerEvent::kRxOverrun});
}

TEST_F(SocketCanErrorFrames, BusOffFromErrorActiveAndTheKernelsRestart) {
  EXPECT_EQ(translate(errorFrame(CAN_ERR_BUSOFF, 0, 255)),
            (Events{CanControllerEvent::kErrorPassive, CanControllerEvent::kBusOff}));
  EXPECT_EQ(translate(errorFrame(CAN_ERR_BUSOFF, 0, 255)), Events{});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW)),  // not a state report
            Events{CanControllerEvent::kRxOverrun});
  EXPECT_TRUE(state_.busOff);
  EXPECT_EQ(translate(errorFrame(CAN_ERR_RESTARTED)), Events{CanControllerEvent::kBusOffRecovered});
  EXPECT_FALSE(state_.busOff);
  EXPECT_FALSE(state_.errorPassive);
  EXPECT_EQ(translate(errorFrame(CAN_ERR_RESTARTED)), Events{});  // nothing more to recover
}

TEST_F(SocketCanErrorFrames, BusOffFromErrorPassiveReportsOnlyTheBusOff) {
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE, 130)),
            Events{CanControllerEvent::kErrorPassive});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_BUSOFF)), Events{CanControllerEvent::kBusOff});
}

TEST_F(SocketCanErrorFrames, AStateReportEndsABusOffTheControllerLeftByItself) {
  EXPECT_EQ(translate(errorFrame(CAN_ERR_BUSOFF)),
            (Events{CanControllerEvent::kErrorPassive, CanControllerEvent::kBusOff}));
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE)),
            Events{CanControllerEvent::kBusOffRecovered});
  EXPECT_EQ(translate(errorFrame(CAN_ERR_BUSOFF)),
            (Events{CanControllerEvent::kErrorPassive, CanControllerEvent::kBusOff}));
  // Back, but still error passive: the node cleared error passive with the bus-off, so again.
  EXPECT_EQ(translate(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE, 200)),
            (Events{CanControllerEvent::kBusOffRecovered, CanControllerEvent::kErrorPassive}));
}

TEST_F(SocketCanErrorFrames, OtherClassesAndDataFramesReportNothing) {
  EXPECT_EQ(translate(errorFrame(CAN_ERR_PROT | CAN_ERR_ACK | CAN_ERR_TX_TIMEOUT)), Events{});
  can_frame data = errorFrame(CAN_ERR_BUSOFF);
  data.can_id &= ~CAN_ERR_FLAG;  // a data frame with id 0x240: not an error frame
  EXPECT_EQ(translate(data), Events{});
  can_frame protocol = errorFrame(CAN_ERR_PROT);
  protocol.data[1] = CAN_ERR_CRTL_TX_PASSIVE;  // data[1] means something only with CAN_ERR_CRTL
  EXPECT_EQ(translate(protocol), Events{});
  EXPECT_FALSE(state_.errorPassive);
  EXPECT_FALSE(state_.busOff);
}

// --- the example node driven by error frames ---------------------------------------------

class NodeOverSocketCanErrors : public ExampleNodeTest {
 protected:
  void deliver(const can_frame& frame) {
    const port::SocketCanEvents events = controllerEventsOf(frame, &state_);
    withNode([&events](Node& node) {
      for (const CanControllerEvent event : events) {
        node.onControllerEvent(event, node.now());
      }
    });
  }
  SocketCanErrorState state_;
};

TEST_F(NodeOverSocketCanErrors, OverrunErrorPassiveAndBackBecomeEmcy) {
  deliver(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW));
  EXPECT_TRANSCRIPT("tx 081 [8] 10 81 11 00 00 00 00 00");
  deliver(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_WARNING, 96));
  EXPECT_TRANSCRIPT("silence");
  deliver(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE, 128));
  EXPECT_TRANSCRIPT("tx 081 [8] 20 81 11 00 00 00 00 00");
  EXPECT_EQ(value(0x1001, 0), 0x11U);
  deliver(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_WARNING, 120));
  EXPECT_TRANSCRIPT("tx 081 [8] 00 00 00 00 00 00 00 00");
  EXPECT_EQ(value(0x1001, 0), 0U);
  EXPECT_EQ(bus_.node().statistics().rxOverruns, 1U);
}

TEST_F(NodeOverSocketCanErrors, BusOffStopsTransmittingAndTheRestartRecovers) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 64 00 00 00   # heartbeat 100 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
  )");
  deliver(errorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE, 128));
  EXPECT_TRANSCRIPT("tx 081 [8] 20 81 11 00 00 00 00 00");
  deliver(errorFrame(CAN_ERR_BUSOFF));
  EXPECT_TRUE(bus_.node().busOff());
  EXPECT_EQ(bus_.node().statistics().busOffs, 1U);
  EXPECT_TRANSCRIPT("wait 250\nsilence");
  deliver(errorFrame(CAN_ERR_RESTARTED));
  EXPECT_FALSE(bus_.node().busOff());
  EXPECT_TRANSCRIPT(R"(
    tx 701 [1] 7F                        # what waited in the queue goes out first
    tx 701 [1] 7F
    tx 081 [8] 00 00 00 00 00 00 00 00   # error passive is over
    tx 081 [8] 40 81 11 00 00 00 00 00   # recovered from bus-off
    wait 100
    tx 701 [1] 7F
  )");
  EXPECT_EQ(value(0x1001, 0), 0U);
}

}  // namespace
}  // namespace costa::test
