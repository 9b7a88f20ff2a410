// ErrorControl without Node: guarding, life guarding, heartbeat timeouts, 0x1029, CAN events.
#include "costa/error_control.hpp"

#include <gtest/gtest.h>

#include "node_services.hpp"

namespace costa::test {
namespace {

class ErrorControlTest : public NodeServicesTest {
 protected:
  /// Powered on and operational, with `settings`.
  NodeServices& operational(const NodeSettings& settings = withNodeId(kNodeId)) {
    NodeServices& node = powerOn(settings);
    node.nmt.enter(NmtState::kOperational);
    (void)node.listener.take();
    return node;
  }
  /// Node 0x20 monitored with 100 ms, its first heartbeat at kStart.
  void monitorNode20(NodeServices& node) {
    store(0x1016, 1, 0x00200064U);
    node.errorControl.reset(kNodeId);
    EXPECT_TRUE(node.errorControl.onFrame(frame(0x720, {0x05}), kNodeId));
  }
  /// Node 0x20 times out (EMCY 0x8130), then 0x1016:01 is written to monitor node 0x21.
  void timeOutThenMoveTo21(NodeServices& node) {
    monitorNode20(node);
    clock_.advance(afterMs(100));
    node.errorControl.process(afterMs(100));
    EXPECT_EQ(sent(), frames({emcy(0x8130, 0x11, 0x20)}));
    (void)node.listener.take();
    const uint8_t node21[4] = {0x64, 0x00, 0x21, 0x00};
    ASSERT_EQ(node.errorControl.consumerObjects().write(dictionary_, dictionary_.find(0x1016, 1),
                                                        node21, sizeof(node21)),
              AbortCode::kNone);
  }
  static CanFrame emcy(uint16_t code, uint8_t errorRegister, uint8_t byte3 = 0) {
    return frame8(
        0x85, {static_cast<uint8_t>(code), static_cast<uint8_t>(code >> 8U), errorRegister, byte3});
  }
};

TEST_F(ErrorControlTest, AGuardingRequestIsAnsweredWithTheStateAndToggleBit) {
  NodeServices& node = operational();
  EXPECT_TRUE(node.errorControl.onFrame(remote(0x705), kNodeId));
  EXPECT_TRUE(node.errorControl.onFrame(remote(0x705), kNodeId));
  EXPECT_TRUE(node.errorControl.onFrame(remote(0x706), kNodeId));  // another node's: no answer
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05}), frame(0x705, {0x85})}));
}

TEST_F(ErrorControlTest, ADeviceWithoutNodeGuardingIgnoresRequests) {
  NodeSettings settings = withNodeId(kNodeId);
  settings.profile.errorControl.nodeGuarding = false;
  NodeServices& node = operational(settings);
  EXPECT_FALSE(node.errorControl.onFrame(remote(0x705), kNodeId));
  EXPECT_TRUE(sent().empty());
}

TEST_F(ErrorControlTest, LifeGuardingExpiryRaisesEmcy8130ThenTheErrorBehaviourApplies) {
  NodeServices& node = operational();
  store(0x100C, 0, 100);
  store(0x100D, 0, 2);
  EXPECT_TRUE(node.errorControl.onFrame(remote(0x705), kNodeId));
  EXPECT_EQ(node.errorControl.nextDeadline(), afterMs(200));
  clock_.advance(afterMs(200));
  node.errorControl.process(afterMs(200));
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05}), emcy(0x8130, 0x11)}));  // EMCY first
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
  EXPECT_EQ(node.listener.take(),
            (Events{"life guarding expired", "state operational -> pre-operational"}));
  EXPECT_TRUE(node.errorControl.onFrame(remote(0x705), kNodeId));
  EXPECT_EQ(node.listener.take(), (Events{"life guarding resumed"}));
  EXPECT_EQ(emcySent(), frames({frame(0x705, {0xFF}), emcy(0x0000, 0x00)}));
}

TEST_F(ErrorControlTest, TheErrorBehaviourMayStopTheNodeOrLeaveItsState) {
  NodeServices& node = operational();
  store(0x1029, 1, ErrorControl::kNoStateChange);
  node.errorControl.onCommunicationError();
  EXPECT_EQ(node.nmt.state(), NmtState::kOperational);
  store(0x1029, 1, ErrorControl::kEnterStopped);
  node.errorControl.onCommunicationError();
  EXPECT_EQ(node.nmt.state(), NmtState::kStopped);
  node.errorControl.applyErrorBehaviour(ErrorControl::kEnterPreOperational);
  EXPECT_EQ(node.nmt.state(), NmtState::kStopped);  // only operational goes to pre-operational
  node.nmt.enter(NmtState::kPreOperational);
  node.errorControl.onCommunicationError();  // stopped from any state but initialising
  EXPECT_EQ(node.nmt.state(), NmtState::kStopped);
}

TEST_F(ErrorControlTest, AHeartbeatTimeoutRaisesEmcy8130NamingTheProducer) {
  NodeServices& node = operational();
  monitorNode20(node);
  EXPECT_EQ(node.errorControl.nextDeadline(), afterMs(100));
  clock_.advance(afterMs(100));
  node.errorControl.process(afterMs(100));
  EXPECT_EQ(sent(), frames({emcy(0x8130, 0x11, 0x20)}));
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
  EXPECT_EQ(node.listener.take(),
            (Events{"heartbeat timeout 20", "state operational -> pre-operational"}));
  EXPECT_TRUE(node.errorControl.onFrame(frame(0x720, {0x05}), kNodeId));
  EXPECT_EQ(node.listener.take(), (Events{"heartbeat resumed 20"}));
  EXPECT_EQ(emcySent(), frames({emcy(0x0000, 0x00)}));
}

// A timed-out entry given a new value: its EMCY 0x8130 is cleared and the listeners hear that
// the producer it had found silent is no longer waited for.
TEST_F(ErrorControlTest, AWithdrawnEntryClearsItsErrorAndTellsTheListeners) {
  NodeServices& node = operational();
  timeOutThenMoveTo21(node);
  node.errorControl.process(afterMs(100));
  EXPECT_EQ(emcySent(), frames({emcy(0x0000, 0x00)}));
  EXPECT_EQ(node.listener.take(), (Events{"heartbeat withdrawn 20"}));
  node.errorControl.process(afterMs(100));
  EXPECT_TRUE(node.listener.take().empty()) << "once";
}

// A reset communication that comes between a new value of a timed-out entry and the next
// process() clears the entry's error as it clears those of timed-out entries; the withdrawal
// is then not reported again.
TEST_F(ErrorControlTest, AResetBeforeAWithdrawalIsReportedClearsItsError) {
  NodeServices& node = operational();
  timeOutThenMoveTo21(node);
  node.errorControl.reset(kNodeId);
  EXPECT_EQ(emcySent(), frames({emcy(0x0000, 0x00)}));
  node.errorControl.process(afterMs(100));
  EXPECT_TRUE(emcySent().empty());
  EXPECT_TRUE(node.listener.take().empty());
}

TEST_F(ErrorControlTest, WithoutEmcyForErrorsOnlyTheListenersHearOfThem) {
  NodeSettings settings = withNodeId(kNodeId);
  settings.profile.errorControl.emcyForErrors = false;
  NodeServices& node = operational(settings);
  monitorNode20(node);
  clock_.advance(afterMs(100));
  node.errorControl.process(afterMs(100));
  EXPECT_TRUE(emcySent().empty());
  EXPECT_EQ(node.listener.take(),
            (Events{"heartbeat timeout 20", "state operational -> pre-operational"}));
}

TEST_F(ErrorControlTest, OnlyOneByteFramesFromOtherNodesAreHeartbeats) {
  NodeServices& node = operational();
  store(0x1016, 1, 0x00050064U);  // even one naming this node's own id
  node.errorControl.reset(kNodeId);
  EXPECT_TRUE(node.errorControl.onFrame(frame(0x705, {0x05}), kNodeId));
  EXPECT_TRUE(node.errorControl.onFrame(frame(0x720, {0x05, 0x00}), kNodeId));
  EXPECT_EQ(node.errorControl.nextDeadline(), kNever);  // monitoring has not started
}

TEST_F(ErrorControlTest, AnOverrunSignalsEmcy8110AndErrorPassiveRaises8120UntilActive) {
  NodeServices& node = operational();
  node.errorControl.onControllerEvent(CanControllerEvent::kRxOverrun);
  node.errorControl.onControllerEvent(CanControllerEvent::kErrorPassive);
  EXPECT_TRUE(node.emcy.active(ErrorControl::kEmcyErrorPassive, 0));
  node.errorControl.onControllerEvent(CanControllerEvent::kErrorActive);
  EXPECT_FALSE(node.emcy.active(ErrorControl::kEmcyErrorPassive, 0));
  EXPECT_EQ(node.errorControl.rxOverruns(), 1U);
  EXPECT_EQ(emcySent(), frames({emcy(0x8110, 0x11), emcy(0x8120, 0x11), emcy(0x0000, 0x00)}));
}

TEST_F(ErrorControlTest, BusOffHoldsTransmissionAndRecoveryResumesItWithEmcy8140) {
  NodeServices& node = operational();
  node.errorControl.onControllerEvent(CanControllerEvent::kBusOff);
  node.errorControl.onControllerEvent(CanControllerEvent::kBusOff);  // counted once
  EXPECT_TRUE(node.errorControl.busOff());
  EXPECT_TRUE(tx_.held());
  EXPECT_EQ(node.errorControl.busOffs(), 1U);
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);  // the error behaviour
  tx_.send(frame(0x185, {0x01}));
  EXPECT_TRUE(sent().empty());
  node.errorControl.onControllerEvent(CanControllerEvent::kBusOffRecovered);
  EXPECT_FALSE(node.errorControl.busOff());
  EXPECT_FALSE(tx_.held());
  EXPECT_EQ(node.listener.take(),
            (Events{"bus-off", "state operational -> pre-operational", "bus-off recovered"}));
  tx_.flush(clock_.now);
  EXPECT_EQ(emcySent(), frames({frame(0x185, {0x01}), emcy(0x8140, 0x11)}));
}

TEST_F(ErrorControlTest, ARecoveryWithoutABusOffDoesNothing) {
  NodeServices& node = operational();
  node.errorControl.onControllerEvent(CanControllerEvent::kBusOffRecovered);
  EXPECT_TRUE(node.listener.take().empty());
  EXPECT_TRUE(emcySent().empty());
}

}  // namespace
}  // namespace costa::test
