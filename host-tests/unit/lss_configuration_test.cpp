// LSS slave (CiA 305): configure bit timing, the bit timing switch of activate bit timing,
// store configuration, and what a host that overrides nothing answers. Driven directly with
// frames; every response is checked byte for byte.
#include <gtest/gtest.h>

#include "lss_test_bus.hpp"

namespace costa::test {
namespace {

const LssIdentity& kIdentity = kLssTestIdentity;

TEST_F(LssSlaveTest, ConfigureBitTimingAsksTheHostOnlyForDefinedTimings) {
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 13 00 03 00 00 00 00 00   # 250 kbit/s: supported
    tx 7E4 [8] 13 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(slave().pendingBitTiming(), (LssBitTiming{0, 3}));
  EXPECT_EQ(host().questions, 1);

  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 13 00 00 00 00 00 00 00   # 1000 kbit/s: the host says no
    tx 7E4 [8] 13 01 00 00 00 00 00 00
  )");
  EXPECT_EQ(host().questions, 2);
  EXPECT_EQ(host().lastQuestion, (LssBitTiming{0, 0}));

  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 13 00 05 00 00 00 00 00   # reserved index
    tx 7E4 [8] 13 01 00 00 00 00 00 00
    rx 7E5 [8] 13 00 0A 00 00 00 00 00   # beyond the table
    tx 7E4 [8] 13 01 00 00 00 00 00 00
    rx 7E5 [8] 13 01 03 00 00 00 00 00   # reserved table selector
    tx 7E4 [8] 13 01 00 00 00 00 00 00
    rx 7E5 [8] 13 7F 03 00 00 00 00 00   # reserved table selector
    tx 7E4 [8] 13 01 00 00 00 00 00 00
  )");
  EXPECT_EQ(host().questions, 2);
  EXPECT_EQ(slave().pendingBitTiming(), (LssBitTiming{0, 3}));  // refusals change nothing

  host().supportedCiaIndices = 1U << 9U;
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 13 00 09 00 00 00 00 00   # automatic bit rate detection
    tx 7E4 [8] 13 00 00 00 00 00 00 00
    rx 7E5 [8] 13 80 02 00 00 00 00 00   # manufacturer table, index the host lacks
    tx 7E4 [8] 13 01 00 00 00 00 00 00
    rx 7E5 [8] 13 80 01 00 00 00 00 00   # manufacturer table, supported
    tx 7E4 [8] 13 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(host().questions, 5);
  EXPECT_EQ(slave().pendingBitTiming(), (LssBitTiming{0x80, 1}));
}

TEST_F(LssSlaveTest, ActivateBitTimingSwitchesAfterOneDelayAndResumesAfterTheSecond) {
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 13 00 02 00 00 00 00 00
    tx 7E4 [8] 13 00 00 00 00 00 00 00
  )");
  bus_.advance(1000);
  const Microseconds start = bus_.now();
  EXPECT_TRANSCRIPT("rx 7E5 [8] 15 2C 01 00 00 00 00 00\nsilence");  // 300 ms, no response
  EXPECT_TRUE(bus_.accepted());
  EXPECT_TRUE(slave().transmissionSuspended());
  EXPECT_EQ(slave().nextDeadline(), start + 300000U);

  bus_.advance(299999);
  EXPECT_EQ(host().activations, 0);
  // While the switch runs, frames are ignored (the bus may carry either bit rate).
  EXPECT_TRANSCRIPT("rx 7E5 [8] 5E 00 00 00 00 00 00 00\nsilence");
  EXPECT_FALSE(bus_.accepted());
  bus_.advance(1);
  EXPECT_EQ(host().activations, 1);
  EXPECT_EQ(host().activated, (LssBitTiming{0, 2}));
  EXPECT_EQ(host().activatedAt, start + 300000U);
  EXPECT_TRUE(slave().transmissionSuspended());
  EXPECT_EQ(slave().nextDeadline(), start + 600000U);

  bus_.advance(299999);
  EXPECT_TRUE(slave().transmissionSuspended());
  bus_.advance(1);
  EXPECT_FALSE(slave().transmissionSuspended());
  EXPECT_EQ(slave().nextDeadline(), kNever);
  EXPECT_EQ(host().activations, 1);
  EXPECT_TRUE(slave().configurationState());  // the LSS state does not change
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 5E 00 00 00 00 00 00 00
    tx 7E4 [8] 5E 05 00 00 00 00 00 00
  )");
}

TEST_F(LssSlaveTest, ActivateBitTimingWithoutConfigureActivatesTheRunningBitTiming) {
  bus_.reset(kIdentity, 5, 5, LssBitTiming{0, 4});
  enterConfiguration();
  EXPECT_TRANSCRIPT("rx 7E5 [8] 15 00 00 00 00 00 00 00\nsilence");  // zero delay
  EXPECT_TRUE(slave().transmissionSuspended());
  EXPECT_EQ(slave().nextDeadline(), bus_.now());
  bus_.advance(0);  // one process() call runs both delays
  EXPECT_EQ(host().activations, 1);
  EXPECT_EQ(host().activated, (LssBitTiming{0, 4}));
  EXPECT_FALSE(slave().transmissionSuspended());
}

TEST_F(LssSlaveTest, ALateProcessCallRunsBothStepsOfTheSwitch) {
  enterConfiguration();
  EXPECT_TRANSCRIPT("rx 7E5 [8] 15 0A 00 00 00 00 00 00");  // 10 ms
  NoAllocationScope scope;
  slave().process(bus_.now() + 50000U);
  EXPECT_EQ(host().activations, 1);
  EXPECT_FALSE(slave().transmissionSuspended());
}

TEST_F(LssSlaveTest, ResetCancelsABitTimingSwitch) {
  enterConfiguration();
  EXPECT_TRANSCRIPT("rx 7E5 [8] 15 0A 00 00 00 00 00 00");
  bus_.reset(kIdentity, 5, 5);
  EXPECT_FALSE(slave().transmissionSuspended());
  EXPECT_EQ(slave().nextDeadline(), kNever);
  bus_.advance(100000);
  EXPECT_EQ(host().activations, 0);
}

TEST_F(LssSlaveTest, StoreConfigurationStoresThePendingValuesAndSendsTheHostsResult) {
  enterConfiguration();
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 11 21 00 00 00 00 00 00
    tx 7E4 [8] 11 00 00 00 00 00 00 00
    rx 7E5 [8] 13 00 03 00 00 00 00 00
    tx 7E4 [8] 13 00 00 00 00 00 00 00
    rx 7E5 [8] 17 00 00 00 00 00 00 00
    tx 7E4 [8] 17 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(host().stores, 1);
  EXPECT_EQ(host().storedNodeId, 0x21U);
  EXPECT_EQ(host().storedTiming, (LssBitTiming{0, 3}));

  host().storeResult = LssStoreResult::kNotSupported;
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 17 00 00 00 00 00 00 00
    tx 7E4 [8] 17 01 00 00 00 00 00 00
  )");
  host().storeResult = LssStoreResult::kStorageAccessError;
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 17 00 00 00 00 00 00 00
    tx 7E4 [8] 17 02 00 00 00 00 00 00
  )");
  EXPECT_EQ(host().stores, 3);
}

// A host that overrides nothing: the inert defaults.
class InertHost : public LssSlaveHost {};

TEST(LssSlaveDefaults, TheDefaultHostSupportsNoBitTimingCannotStoreAndNeverResets) {
  InertHost host;
  port::RecordingCan can;
  QueuedFrame slots[4];
  TransmitPath tx(can, slots, 4);
  LssSlave slave(tx, host);
  NoAllocationScope scope;
  slave.reset(kIdentity, 0xFF, 0xFF, LssBitTiming{});
  const auto request = [&](uint8_t cs, uint8_t byte1, uint8_t byte2) {
    const CanFrame frame{0x7E5, {cs, byte1, byte2}, 8, false, false};
    return slave.onFrame(frame, 0);
  };
  EXPECT_TRUE(request(0x04, 0x01, 0x00));  // configuration state
  EXPECT_TRUE(request(0x11, 0x09, 0x00));
  EXPECT_TRUE(request(0x13, 0x00, 0x02));
  EXPECT_TRUE(request(0x17, 0x00, 0x00));
  const uint8_t expected[][2] = {{0x11, 0x00}, {0x13, 0x01}, {0x17, 0x01}};
  ASSERT_EQ(can.count(), 3U);
  size_t sent = 0;
  for (const auto& response : expected) {
    EXPECT_EQ(can.at(sent).id, 0x7E4U);
    EXPECT_EQ(can.at(sent).data[0], response[0]);
    EXPECT_EQ(can.at(sent).data[1], response[1]);
    ++sent;
  }
  EXPECT_TRUE(request(0x15, 0x00, 0x00));  // activate with zero delay
  slave.process(0);
  EXPECT_FALSE(slave.transmissionSuspended());
  EXPECT_TRUE(request(0x04, 0x00, 0x00));  // a first node-id, but nobody resets
  EXPECT_EQ(slave.activeNodeId(), 0xFFU);
  EXPECT_EQ(slave.pendingNodeId(), 0x09U);
  EXPECT_EQ(can.count(), sent);
}

}  // namespace
}  // namespace costa::test
