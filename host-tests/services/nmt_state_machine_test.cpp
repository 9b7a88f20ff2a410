// NmtStateMachine without Node: NMT commands, entry and exit actions, resets, node-ids; NmtSlave.
#include "costa/nmt_state_machine.hpp"

#include <gtest/gtest.h>

#include "costa/nmt_slave.hpp"
#include "node_services.hpp"

namespace costa::test {
namespace {

using NmtStateMachineTest = NodeServicesTest;

const CanFrame kBootUp = frame(0x705, {0x00});

TEST_F(NmtStateMachineTest, PowerOnResetsTheApplicationThenCommunicationAndBootsUp) {
  NodeServices& node = build();
  EXPECT_EQ(node.nmt.state(), NmtState::kInitialising);
  node.nmt.powerOn();
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
  EXPECT_EQ(node.nmt.nodeId(), kNodeId);
  EXPECT_EQ(sent(), frames({kBootUp}));
  EXPECT_EQ(node.listener.take(), (Events{"reset application", "reset communication",
                                          "state initialising -> pre-operational"}));
}

TEST_F(NmtStateMachineTest, CommandsForThisNodeOrAllNodesChangeTheState) {
  NodeServices& node = powerOn();
  EXPECT_TRUE(node.nmt.onCommand(nmtCommand(NmtCommand::kStart, kNodeId)));
  EXPECT_TRUE(node.nmt.onCommand(nmtCommand(NmtCommand::kStop, 0)));
  EXPECT_TRUE(node.nmt.onCommand(nmtCommand(NmtCommand::kEnterPreOperational, kNodeId)));
  EXPECT_TRUE(node.nmt.onCommand(nmtCommand(NmtCommand::kEnterPreOperational, kNodeId)));
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
  EXPECT_EQ(node.listener.take(),
            (Events{"state pre-operational -> operational", "state operational -> stopped",
                    "state stopped -> pre-operational"}));
  EXPECT_TRUE(sent().empty());  // state changes send nothing by themselves
}

TEST_F(NmtStateMachineTest, CommandsForOtherNodesAndMalformedCommandsChangeNothing) {
  NodeServices& node = powerOn();
  (void)node.nmt.onCommand(nmtCommand(NmtCommand::kStart, kNodeId + 1U));
  (void)node.nmt.onCommand(frame(0x000, {0x01, kNodeId, 0x00}));  // DLC 3
  (void)node.nmt.onCommand(frame(0x000, {0x01}));                 // DLC 1
  (void)node.nmt.onCommand(frame(0x000, {0x03, kNodeId}));        // no such command
  (void)node.nmt.onCommand(remote(0x000, 2));
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
  EXPECT_TRUE(node.listener.take().empty());
  EXPECT_TRUE(sent().empty());
}

TEST_F(NmtStateMachineTest, EnteringStoppedDropsTheSdoTransfer) {
  NodeServices& node = powerOn();
  EXPECT_TRUE(node.sdo.onRequest(frame8(0x605, {0x40, 0x03, 0x20, 0x00}), kStart));
  EXPECT_TRUE(node.sdo.busy());
  node.nmt.enter(NmtState::kStopped);
  EXPECT_FALSE(node.sdo.busy());
  EXPECT_EQ(sent().size(), 1U);  // the initiate response only: no abort
}

TEST_F(NmtStateMachineTest, OnlyOperationalRunsThePdos) {
  NodeServices& node = powerOn();
  const CanFrame rpdo = frame(0x205, {0x07, 0x00, 0x00});
  EXPECT_FALSE(node.pdos.receive(0, rpdo, kStart));
  node.nmt.enter(NmtState::kOperational);
  EXPECT_TRUE(node.pdos.receive(0, rpdo, kStart));
  node.nmt.enter(NmtState::kStopped);
  EXPECT_FALSE(node.pdos.receive(0, rpdo, kStart));
  EXPECT_EQ(value(0x2000, 1), 0x07U);
}

TEST_F(NmtStateMachineTest, EnteringOperationalSendsInitialTpdosWhenTheProfileSaysSo) {
  NodeSettings settings = withNodeId(kNodeId);
  settings.profile.pdo.tpdoOnEnteringOperational = true;
  NodeServices& node = powerOn(settings);
  node.nmt.enter(NmtState::kOperational);
  EXPECT_EQ(clock_.next, kStart);  // what the new state allows is due at once
  node.pdos.process(kStart);
  EXPECT_EQ(sent(), frames({frame(0x185, {0x34, 0x12, 0xEF, 0xCD, 0xAB, 0x89})}));
}

TEST_F(NmtStateMachineTest, ResetCommunicationRestoresOnlyTheCommunicationArea) {
  NodeServices& node = powerOn();
  node.nmt.enter(NmtState::kOperational);
  store(0x1017, 0, 500);
  store(0x2000, 1, 0x42);
  (void)node.listener.take();
  EXPECT_TRUE(node.nmt.onCommand(nmtCommand(NmtCommand::kResetCommunication, kNodeId)));
  EXPECT_EQ(value(0x1017, 0), 0U);
  EXPECT_EQ(value(0x2000, 1), 0x42U);
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
  EXPECT_EQ(sent(), frames({kBootUp}));
  EXPECT_EQ(node.listener.take(),
            (Events{"state operational -> initialising", "reset communication",
                    "state initialising -> pre-operational"}));
}

TEST_F(NmtStateMachineTest, ResetNodeRestoresTheWholeDictionary) {
  NodeServices& node = powerOn();
  store(0x1017, 0, 500);
  store(0x2000, 1, 0x42);
  EXPECT_TRUE(node.nmt.onCommand(nmtCommand(NmtCommand::kResetNode, 0)));
  EXPECT_EQ(value(0x1017, 0), 0U);
  EXPECT_EQ(value(0x2000, 1), 0U);
  EXPECT_EQ(sent(), frames({kBootUp}));
  EXPECT_EQ(node.listener.take(),
            (Events{"state pre-operational -> initialising", "reset application",
                    "reset communication", "state initialising -> pre-operational"}));
}

TEST_F(NmtStateMachineTest, AResetDiscardsQueuedFramesSoTheBootUpLeavesFirst) {
  NodeServices& node = powerOn();
  can_.setAccepting(false);
  tx_.send(frame(0x185, {0x01}));
  tx_.send(frame(0x185, {0x02}));
  node.nmt.resetCommunication();
  EXPECT_EQ(tx_.discarded(), 2U);
  can_.setAccepting(true);
  tx_.flush(kStart);
  EXPECT_EQ(sent(), frames({kBootUp}));
}

TEST_F(NmtStateMachineTest, TheHeartbeatStartsAfterTheBootUpFromTheCommunicationArea) {
  NodeServices& node = powerOn();
  EXPECT_EQ(node.heartbeat.nextDeadline(), kNever);  // 0x1017 is 0 by default
  EXPECT_EQ(write(node.heartbeat, 0x1017, 0, 100, 2), AbortCode::kNone);
  EXPECT_EQ(node.heartbeat.nextDeadline(), afterMs(100));
  node.nmt.resetCommunication();  // the default again: no heartbeat
  EXPECT_EQ(node.heartbeat.nextDeadline(), kNever);
}

TEST_F(NmtStateMachineTest, APendingNodeIdAppliesAtTheNextResetCommunication) {
  NodeServices& node = powerOn();
  node.nmt.setPendingNodeId(0x22);
  EXPECT_EQ(node.nmt.nodeId(), kNodeId);
  node.nmt.resetCommunication();
  EXPECT_EQ(node.nmt.nodeId(), 0x22U);
  EXPECT_EQ(value(0x1014, 0), 0xA2U);  // $NODEID defaults follow
  EXPECT_EQ(value(0x1400, 1), 0x222U);
  EXPECT_EQ(sent(), frames({frame(0x722, {0x00})}));
  EXPECT_TRUE(node.nmt.onCommand(nmtCommand(NmtCommand::kStart, 0x22)));
  EXPECT_EQ(node.nmt.state(), NmtState::kOperational);
}

TEST_F(NmtStateMachineTest, WithoutANodeIdTheNodeStaysSilentAndInitialising) {
  NodeServices& node = build(withNodeId(0xFF));
  node.nmt.powerOn();
  EXPECT_EQ(node.nmt.nodeId(), 0xFFU);
  EXPECT_EQ(node.nmt.state(), NmtState::kInitialising);
  (void)node.nmt.onCommand(nmtCommand(NmtCommand::kStart, 0));
  EXPECT_EQ(node.nmt.state(), NmtState::kInitialising);
  EXPECT_TRUE(sent().empty());
}

TEST_F(NmtStateMachineTest, AutomaticStartEntersOperationalAtTheNextProcess) {
  NodeSettings settings = withNodeId(kNodeId);
  settings.automaticStart = true;
  NodeServices& node = build(settings);
  node.nmt.powerOn();
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
  EXPECT_EQ(node.nmt.nextDeadline(), kStart);
  node.nmt.process();
  EXPECT_EQ(node.nmt.state(), NmtState::kOperational);
  EXPECT_EQ(node.nmt.nextDeadline(), kNever);
  node.nmt.setAutomaticStart(false);
  node.nmt.resetCommunication();
  node.nmt.process();
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
}

TEST_F(NmtStateMachineTest, NoLocalTransitionLeadsIntoOrOutOfInitialising) {
  NodeServices& node = build();
  node.nmt.enter(NmtState::kOperational);  // before power-on
  EXPECT_EQ(node.nmt.state(), NmtState::kInitialising);
  node.nmt.powerOn();
  node.nmt.enter(NmtState::kInitialising);
  EXPECT_EQ(node.nmt.state(), NmtState::kPreOperational);
}

TEST(NmtSlave, DecidesWhatAFrameAsksOfTheNode) {
  using Action = NmtSlave::Action;
  const auto decide = [](std::initializer_list<uint8_t> bytes, NmtState current) {
    return NmtSlave::decide(frame(0x000, bytes), kNodeId, current);
  };
  EXPECT_EQ(decide({0x01, kNodeId}, NmtState::kPreOperational).action, Action::kEnterState);
  EXPECT_EQ(decide({0x01, kNodeId}, NmtState::kPreOperational).state, NmtState::kOperational);
  EXPECT_EQ(decide({0x02, 0}, NmtState::kOperational).state, NmtState::kStopped);
  EXPECT_EQ(decide({0x80, 0}, NmtState::kStopped).state, NmtState::kPreOperational);
  EXPECT_EQ(decide({0x81, 0}, NmtState::kStopped).action, Action::kResetNode);
  EXPECT_EQ(decide({0x82, kNodeId}, NmtState::kStopped).action, Action::kResetCommunication);
  EXPECT_EQ(decide({0x01, kNodeId}, NmtState::kOperational).action, Action::kNone);  // already
  EXPECT_EQ(decide({0x01, kNodeId}, NmtState::kInitialising).action, Action::kNone);
  EXPECT_EQ(decide({0x01, kNodeId + 1U}, NmtState::kStopped).action, Action::kNone);
  EXPECT_EQ(decide({0x01, kNodeId, 0}, NmtState::kStopped).action, Action::kNone);
  EXPECT_EQ(decide({0x7F, kNodeId}, NmtState::kStopped).action, Action::kNone);
  EXPECT_EQ(NmtSlave::decide(remote(0x000, 2), kNodeId, NmtState::kStopped).action, Action::kNone);
}

}  // namespace
}  // namespace costa::test
