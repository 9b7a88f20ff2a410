// LSS slave (CiA 305): switch state global, configure node-id and the inquire services, the
// autonomous reset communication, which services each LSS state offers, and malformed frames.
// Driven directly with frames; every response is checked byte for byte.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "lss_test_bus.hpp"

namespace costa::test {
namespace {

const LssIdentity& kIdentity = kLssTestIdentity;

TEST_F(LssSlaveTest, StartsInWaitingStateWithTheGivenNodeIds) {
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_EQ(slave().activeNodeId(), 5U);
  EXPECT_EQ(slave().pendingNodeId(), 5U);
  EXPECT_FALSE(slave().nonConfigured());
  EXPECT_FALSE(slave().transmissionSuspended());
  EXPECT_EQ(slave().nextDeadline(), kNever);
}

TEST(LssSlaveConstruction, BeforeResetItIsANonConfiguredSlaveInWaitingState) {
  RecordingLssHost host;
  port::RecordingCan can;
  QueuedFrame slots[2];
  TransmitPath tx(can, slots, 2);
  const LssSlave slave(tx, host);
  EXPECT_EQ(slave.state(), LssState::kWaiting);
  EXPECT_EQ(slave.activeNodeId(), 0xFFU);
  EXPECT_EQ(slave.pendingNodeId(), 0xFFU);
  EXPECT_TRUE(slave.nonConfigured());
  EXPECT_EQ(slave.identity().serialNumber, 0U);
}

TEST_F(LssSlaveTest, SwitchStateGlobalChangesStateWithoutAnswer) {
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 01 00 00 00 00 00 00\nsilence");
  EXPECT_TRUE(bus_.accepted());
  EXPECT_EQ(slave().state(), LssState::kConfiguration);
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 01 00 00 00 00 00 00\nsilence");  // configuration again
  EXPECT_TRUE(slave().configurationState());
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 00 00 00 00 00 00 00\nsilence");
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 00 00 00 00 00 00 00\nsilence");  // waiting again
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_EQ(host().resetRequests, 0);
}

TEST_F(LssSlaveTest, SwitchStateGlobalWithAnUnknownModeIsIgnored) {
  for (const char* frame :
       {"rx 7E5 [8] 04 02 00 00 00 00 00 00", "rx 7E5 [8] 04 FF 00 00 00 00 00 00"}) {
    EXPECT_EQ(play(frame), "") << frame;
    EXPECT_FALSE(bus_.accepted()) << frame;
    EXPECT_EQ(slave().state(), LssState::kWaiting) << frame;
  }
  enterConfiguration();
  EXPECT_EQ(play("rx 7E5 [8] 04 02 00 00 00 00 00 00\nsilence"), "");
  EXPECT_FALSE(bus_.accepted());
  EXPECT_TRUE(slave().configurationState());
}

TEST_F(LssSlaveTest, InquireServicesAnswerTheIdentityAndTheActiveNodeId) {
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 5A 00 00 00 00 00 00 00
    tx 7E4 [8] 5A 78 56 34 12 00 00 00   # vendor-id, little-endian
    rx 7E5 [8] 5B 00 00 00 00 00 00 00
    tx 7E4 [8] 5B F0 DE BC 9A 00 00 00   # product code
    rx 7E5 [8] 5C 00 00 00 00 00 00 00
    tx 7E4 [8] 5C 01 00 02 00 00 00 00   # revision number
    rx 7E5 [8] 5D 00 00 00 00 00 00 00
    tx 7E4 [8] 5D 0D F0 FE CA 00 00 00   # serial number
    rx 7E5 [8] 5E 00 00 00 00 00 00 00
    tx 7E4 [8] 5E 05 00 00 00 00 00 00   # node-id
  )");
}

TEST_F(LssSlaveTest, ConfigureNodeIdSetsThePendingNodeIdInquireStillReportsTheActiveOne) {
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 11 0A 00 00 00 00 00 00
    tx 7E4 [8] 11 00 00 00 00 00 00 00
    rx 7E5 [8] 5E 00 00 00 00 00 00 00
    tx 7E4 [8] 5E 05 00 00 00 00 00 00   # active until reset communication
  )");
  EXPECT_EQ(slave().pendingNodeId(), 0x0AU);
  EXPECT_EQ(slave().activeNodeId(), 5U);

  // Reset communication: the node applies the pending node-id.
  bus_.reset(kIdentity, slave().pendingNodeId(), slave().pendingNodeId());
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 5E 00 00 00 00 00 00 00
    tx 7E4 [8] 5E 0A 00 00 00 00 00 00
  )");
}

TEST_F(LssSlaveTest, ConfigureNodeIdAccepts1To127And0xFFAndRefusesTheRest) {
  enterConfiguration();
  struct Case {
    uint8_t nodeId;
    uint8_t errorCode;
  };
  const Case cases[] = {{0x01, 0}, {0x7F, 0}, {0xFF, 0}, {0x40, 0},
                        {0x00, 1}, {0x80, 1}, {0xFE, 1}, {0x9C, 1}};
  for (const Case& c : cases) {
    const uint8_t before = slave().pendingNodeId();
    char text[160];
    snprintf(text, sizeof(text),
             "rx 7E5 [8] 11 %02X 00 00 00 00 00 00\ntx 7E4 [8] 11 %02X 00 00 00 00 00 00", c.nodeId,
             c.errorCode);
    EXPECT_EQ(play(text), "") << text;
    EXPECT_EQ(slave().pendingNodeId(), c.errorCode == 0U ? c.nodeId : before) << text;
    EXPECT_EQ(slave().activeNodeId(), 5U) << text;
  }
}

TEST_F(LssSlaveTest, ConfigurationAndInquireServicesAreIgnoredInWaitingState) {
  const char* requests[] = {
      "rx 7E5 [8] 11 0A 00 00 00 00 00 00", "rx 7E5 [8] 13 00 02 00 00 00 00 00",
      "rx 7E5 [8] 15 0A 00 00 00 00 00 00", "rx 7E5 [8] 17 00 00 00 00 00 00 00",
      "rx 7E5 [8] 5A 00 00 00 00 00 00 00", "rx 7E5 [8] 5B 00 00 00 00 00 00 00",
      "rx 7E5 [8] 5C 00 00 00 00 00 00 00", "rx 7E5 [8] 5D 00 00 00 00 00 00 00",
      "rx 7E5 [8] 5E 00 00 00 00 00 00 00",
  };
  for (const char* request : requests) {
    EXPECT_EQ(play(std::string(request) + "\nsilence"), "") << request;
    EXPECT_FALSE(bus_.accepted()) << request;
  }
  EXPECT_EQ(slave().pendingNodeId(), 5U);
  EXPECT_FALSE(slave().transmissionSuspended());
  EXPECT_EQ(host().questions + host().stores, 0);
}

TEST_F(LssSlaveTest, LeavingConfigurationWithAFirstNodeIdRequestsResetCommunication) {
  bus_.reset(kIdentity, 0xFF, 0xFF);
  host().slave = &slave();  // like a node: reset communication calls reset()
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 11 0C 00 00 00 00 00 00
    tx 7E4 [8] 11 00 00 00 00 00 00 00
    rx 7E5 [8] 04 00 00 00 00 00 00 00
    silence
  )");
  EXPECT_TRUE(bus_.accepted());
  EXPECT_EQ(host().resetRequests, 1);
  EXPECT_EQ(slave().activeNodeId(), 0x0CU);
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 5E 00 00 00 00 00 00 00
    tx 7E4 [8] 5E 0C 00 00 00 00 00 00
  )");
}

TEST_F(LssSlaveTest, NoResetRequestUnlessAnUnconfiguredDeviceGetsAValidNodeId) {
  // Active node-id valid: the new one waits for the next reset communication.
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 11 0C 00 00 00 00 00 00
    tx 7E4 [8] 11 00 00 00 00 00 00 00
    rx 7E5 [8] 04 00 00 00 00 00 00 00
  )");
  // Unconfigured, and still no valid pending node-id.
  bus_.reset(kIdentity, 0xFF, 0xFF);
  enterConfiguration();
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 00 00 00 00 00 00 00");
  // Unconfigured with a valid pending node-id, but already in waiting state.
  bus_.reset(kIdentity, 0xFF, 0x0C);
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 00 00 00 00 00 00 00\nsilence");
  EXPECT_EQ(host().resetRequests, 0);
}

TEST_F(LssSlaveTest, MalformedFramesAreIgnoredInBothStates) {
  for (const bool configuration : {false, true}) {
    if (configuration) {
      enterConfiguration();
    }
    const char* frames[] = {
        "rx 7E5 [7] 5E 00 00 00 00 00 00",
        "rx 7E5 [0]",
        "rx 7E5 [1] 04",
        "rx 7E5 [2] 04 01",
        "rx 7E5 [0] RTR",
        "rx 7E5 [8] RTR",
        "rx 7E4 [8] 5E 00 00 00 00 00 00 00",  // the slaves' own COB-ID
        "rx 7E6 [8] 5E 00 00 00 00 00 00 00",
        "rx 000007E5 [8] 5E 00 00 00 00 00 00 00",  // 29-bit identifier
    };
    for (const char* frame : frames) {
      EXPECT_EQ(play(std::string(frame) + "\nsilence"), "") << frame;
      EXPECT_FALSE(bus_.accepted()) << frame;
      EXPECT_EQ(slave().configurationState(), configuration) << frame;
    }
  }
}

TEST_F(LssSlaveTest, ADataLengthCodeAbove8IsIgnored) {
  enterConfiguration();
  CanFrame frame;
  frame.id = 0x7E5;
  frame.data[0] = 0x5E;
  for (uint8_t dlc = 9; dlc <= 15; ++dlc) {
    frame.dlc = dlc;
    bus_.send(frame);
    EXPECT_FALSE(bus_.accepted()) << int{dlc};
  }
  frame.dlc = 255;
  bus_.send(frame);
  EXPECT_FALSE(bus_.accepted());
  EXPECT_EQ(bus_.unread(), 0U);
}

TEST_F(LssSlaveTest, RemoteFramesAreIgnoredWhateverTheirData) {
  enterConfiguration();
  const CanFrame inquire{0x7E5, {0x5E}, 8, true, false};
  bus_.send(inquire);
  EXPECT_FALSE(bus_.accepted());
  const CanFrame toWaiting{0x7E5, {0x04, 0x00}, 8, true, false};
  bus_.send(toWaiting);
  EXPECT_FALSE(bus_.accepted());
  EXPECT_TRUE(slave().configurationState());
  EXPECT_EQ(bus_.unread(), 0U);
}

TEST_F(LssSlaveTest, UnknownCommandSpecifiersAreIgnoredInBothStates) {
  const auto known = [](unsigned cs) {
    return cs == 0x04 || cs == 0x11 || cs == 0x13 || cs == 0x15 || cs == 0x17 ||
           (cs >= 0x40 && cs <= 0x43) || (cs >= 0x46 && cs <= 0x4C) || cs == 0x51 ||
           (cs >= 0x5A && cs <= 0x5E);
  };
  for (const bool configuration : {false, true}) {
    bus_.reset(kIdentity, 0xFF, 0xFF);
    if (configuration) {
      enterConfiguration();
    }
    CanFrame frame;
    frame.id = 0x7E5;
    frame.dlc = 8;
    for (unsigned cs = 0; cs <= 0xFF; ++cs) {
      if (known(cs)) {
        continue;
      }
      frame.data[0] = static_cast<uint8_t>(cs);
      frame.data[1] = 0x01;
      bus_.send(frame);
      EXPECT_FALSE(bus_.accepted()) << std::hex << cs;
    }
    EXPECT_EQ(bus_.unread(), 0U);
    EXPECT_EQ(slave().configurationState(), configuration);
    EXPECT_EQ(slave().pendingNodeId(), 0xFFU);
  }
}

TEST_F(LssSlaveTest, AFullTransmitQueueDropsTheResponseAndCountsIt) {
  enterConfiguration();
  bus_.can().setAccepting(false);  // the controller takes nothing: responses queue up
  for (size_t i = 0; i < LssBus::kQueueDepth + 2U; ++i) {
    bus_.send(CanFrame{0x7E5, {0x5E}, 8, false, false});
    EXPECT_TRUE(bus_.accepted());
  }
  EXPECT_EQ(bus_.tx().queued(), LssBus::kQueueDepth);
  EXPECT_EQ(bus_.tx().dropped(), 2U);
}

}  // namespace
}  // namespace costa::test
