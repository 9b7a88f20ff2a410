// LssSlave alone: LSS states, node-id and bit timing configuration, switch, store, identification.
#include "costa/lss_slave.hpp"

#include <gtest/gtest.h>

#include "costa/lss_protocol.hpp"
#include "service_fixture.hpp"

namespace costa::test {
namespace {

/// Supports CiA indices 2 and 3 (500 and 250 kbit/s); records every call.
class RecordingHost final : public LssSlaveHost {
 public:
  bool bitTimingSupported(LssBitTiming timing) noexcept override {
    ++questions;
    return timing.tableSelector == 0U && (timing.tableIndex == 2U || timing.tableIndex == 3U);
  }
  void activateBitTiming(LssBitTiming timing) noexcept override {
    ++activations;
    activated = timing;
  }
  LssStoreResult storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept override {
    storedNodeId = nodeId;
    storedTiming = timing;
    return storeResult;
  }
  void requestResetCommunication() noexcept override { ++resetRequests; }

  LssStoreResult storeResult = LssStoreResult::kStored;
  int questions = 0;
  int activations = 0;
  LssBitTiming activated;
  uint8_t storedNodeId = 0;
  LssBitTiming storedTiming;
  int resetRequests = 0;
};

const LssIdentity kIdentity{0x12345678, 0x9ABCDEF0, 0x00020001, 0xCAFEF00D};

class LssSlaveTest : public ServiceTest {
 protected:
  LssSlaveTest() : lss_(tx_, host_) { lss_.reset(kIdentity, kNodeId, kNodeId, LssBitTiming{0, 3}); }

  /// A request on 0x7E5 that the slave takes.
  void request(std::initializer_list<uint8_t> bytes, Microseconds now = kStart) {
    EXPECT_TRUE(lss_.onFrame(frame8(0x7E5, bytes), now));
    EXPECT_TRUE(lss_.valid());
  }
  /// A request on 0x7E5 that the slave turns away.
  void ignored(std::initializer_list<uint8_t> bytes, Microseconds now = kStart) {
    EXPECT_FALSE(lss_.onFrame(frame8(0x7E5, bytes), now));
  }
  static CanFrame answer(std::initializer_list<uint8_t> bytes) { return frame8(0x7E4, bytes); }
  void configuration() { request({lss::kSwitchStateGlobal, lss::kModeConfiguration}); }

  RecordingHost host_;
  LssSlave lss_;
};

TEST_F(LssSlaveTest, ConfigurationServicesAreIgnoredWhileWaiting) {
  ignored({lss::kInquireNodeId});
  ignored({lss::kConfigureNodeId, 0x22});
  configuration();
  EXPECT_TRUE(lss_.configurationState());
  request({lss::kInquireNodeId});
  request({lss::kInquireVendor});
  request({lss::kInquireSerial});
  EXPECT_EQ(sent(), frames({answer({0x5E, kNodeId}), answer({0x5A, 0x78, 0x56, 0x34, 0x12}),
                            answer({0x5D, 0x0D, 0xF0, 0xFE, 0xCA})}));
}

TEST_F(LssSlaveTest, ConfigureNodeIdTakes1To127OrFFAsThePendingNodeId) {
  configuration();
  request({lss::kConfigureNodeId, 0x00});
  request({lss::kConfigureNodeId, 0x80});
  request({lss::kConfigureNodeId, 0x22});
  EXPECT_EQ(lss_.pendingNodeId(), 0x22U);
  request({lss::kConfigureNodeId, 0xFF});
  EXPECT_EQ(lss_.pendingNodeId(), 0xFFU);
  request({lss::kInquireNodeId});  // still the active one
  EXPECT_EQ(sent(), frames({answer({0x11, 0x01}), answer({0x11, 0x01}), answer({0x11, 0x00}),
                            answer({0x11, 0x00}), answer({0x5E, kNodeId})}));
  EXPECT_EQ(lss_.activeNodeId(), kNodeId);
}

TEST_F(LssSlaveTest, ConfigureBitTimingAsksTheHostOnlyAboutDefinedTimings) {
  configuration();
  request({lss::kConfigureBitTiming, 0, 5});   // reserved index
  request({lss::kConfigureBitTiming, 0, 10});  // beyond the table
  request({lss::kConfigureBitTiming, 1, 0});   // reserved selector
  EXPECT_EQ(host_.questions, 0);
  request({lss::kConfigureBitTiming, 0, 4});  // defined, not supported
  request({lss::kConfigureBitTiming, 0, 2});
  EXPECT_EQ(host_.questions, 2);
  EXPECT_TRUE(lss_.pendingBitTiming() == (LssBitTiming{0, 2}));
  EXPECT_EQ(sent(), frames({answer({0x13, 0x01}), answer({0x13, 0x01}), answer({0x13, 0x01}),
                            answer({0x13, 0x01}), answer({0x13, 0x00})}));
}

TEST_F(LssSlaveTest, ActivateBitTimingSwitchesAfterOneDelayAndResumesAfterTheSecond) {
  configuration();
  request({lss::kConfigureBitTiming, 0, 2});
  (void)sent();
  request({lss::kActivateBitTiming, 100, 0});  // 100 ms, no answer
  EXPECT_TRUE(lss_.transmissionSuspended());
  EXPECT_EQ(lss_.nextDeadline(), afterMs(100));
  ignored({lss::kInquireNodeId}, afterMs(50));  // frames are ignored meanwhile
  lss_.process(afterMs(100) - 1U);
  EXPECT_EQ(host_.activations, 0);
  lss_.process(afterMs(100));
  EXPECT_EQ(host_.activations, 1);
  EXPECT_TRUE(host_.activated == (LssBitTiming{0, 2}));
  EXPECT_TRUE(lss_.transmissionSuspended());
  EXPECT_EQ(lss_.nextDeadline(), afterMs(200));
  lss_.process(afterMs(200));
  EXPECT_FALSE(lss_.transmissionSuspended());
  EXPECT_EQ(lss_.nextDeadline(), kNever);
  EXPECT_TRUE(sent().empty());
  request({lss::kInquireNodeId}, afterMs(200));
  EXPECT_EQ(sent(), frames({answer({0x5E, kNodeId})}));
}

// The switch comes before the clock wraps, the resume after it (kStart is 1 s before the wrap).
TEST_F(LssSlaveTest, ActivateBitTimingAcrossTheClocksWrap) {
  configuration();
  request({lss::kConfigureBitTiming, 0, 2});
  (void)sent();
  request({lss::kActivateBitTiming, 0x58, 0x02});  // 600 ms; request() checks valid()
  EXPECT_EQ(lss_.nextDeadline(), afterMs(600));
  lss_.process(afterMs(600));
  EXPECT_EQ(host_.activations, 1);
  EXPECT_TRUE(lss_.valid());
  EXPECT_EQ(lss_.nextDeadline(), afterMs(1200));  // past the wrap
  lss_.process(afterMs(1200) - 1U);
  EXPECT_TRUE(lss_.transmissionSuspended());
  lss_.process(afterMs(1200));
  EXPECT_FALSE(lss_.transmissionSuspended());
  EXPECT_TRUE(lss_.valid());
}

TEST_F(LssSlaveTest, StoreConfigurationAnswersWithTheHostsResult) {
  configuration();
  request({lss::kConfigureNodeId, 0x22});
  request({lss::kConfigureBitTiming, 0, 2});
  (void)sent();
  request({lss::kStoreConfiguration});
  EXPECT_EQ(host_.storedNodeId, 0x22U);
  EXPECT_TRUE(host_.storedTiming == (LssBitTiming{0, 2}));
  host_.storeResult = LssStoreResult::kStorageAccessError;
  request({lss::kStoreConfiguration});
  host_.storeResult = LssStoreResult::kNotSupported;
  request({lss::kStoreConfiguration});
  EXPECT_EQ(sent(), frames({answer({0x17, 0x00}), answer({0x17, 0x02}), answer({0x17, 0x01})}));
}

TEST_F(LssSlaveTest, SwitchStateSelectiveNeedsTheWholeIdentityInOrder) {
  request({lss::kSwitchSelectiveVendor, 0x78, 0x56, 0x34, 0x12});
  request({lss::kSwitchSelectiveRevision, 0x01, 0x00, 0x02, 0x00});  // out of order: over
  request({lss::kSwitchSelectiveProduct, 0xF0, 0xDE, 0xBC, 0x9A});
  request({lss::kSwitchSelectiveRevision, 0x01, 0x00, 0x02, 0x00});
  request({lss::kSwitchSelectiveSerial, 0x0D, 0xF0, 0xFE, 0xCA});
  EXPECT_FALSE(lss_.configurationState());
  EXPECT_TRUE(sent().empty());
  request({lss::kSwitchSelectiveVendor, 0x78, 0x56, 0x34, 0x12});
  request({lss::kSwitchSelectiveProduct, 0xF0, 0xDE, 0xBC, 0x9A});
  request({lss::kSwitchSelectiveRevision, 0x01, 0x00, 0x02, 0x00});
  request({lss::kSwitchSelectiveSerial, 0x0D, 0xF0, 0xFE, 0xCA});
  EXPECT_TRUE(lss_.configurationState());
  EXPECT_EQ(sent(), frames({answer({0x44})}));
}

TEST_F(LssSlaveTest, ADeviceWithoutNodeIdAsksForAResetWhenItLeavesConfigurationWithOne) {
  lss_.reset(kIdentity, 0xFF, 0xFF, LssBitTiming{0, 3});
  EXPECT_TRUE(lss_.nonConfigured());
  request({lss::kIdentifyNonConfigured});
  EXPECT_EQ(sent(), frames({answer({0x50})}));
  configuration();
  request({lss::kSwitchStateGlobal, lss::kModeWaiting});  // no pending node-id: no reset
  EXPECT_EQ(host_.resetRequests, 0);
  configuration();
  request({lss::kConfigureNodeId, 0x22});
  EXPECT_FALSE(lss_.nonConfigured());
  request({lss::kSwitchStateGlobal, lss::kModeWaiting});
  EXPECT_EQ(host_.resetRequests, 1);
  request({lss::kIdentifyNonConfigured});  // configured now: no answer
  EXPECT_EQ(sent(), frames({answer({0x11, 0x00})}));
}

TEST_F(LssSlaveTest, FastscanFindsANonConfiguredDeviceByItsIdentity) {
  lss_.reset(kIdentity, 0xFF, 0xFF, LssBitTiming{0, 3});
  request({lss::kFastscan, 0, 0, 0, 0, lss::kFastscanConfirm, 0, 0});
  const uint32_t values[4] = {kIdentity.vendorId, kIdentity.productCode, kIdentity.revisionNumber,
                              kIdentity.serialNumber};
  for (uint8_t sub = 0; sub < 4U; ++sub) {
    const uint32_t id = values[sub];
    request({lss::kFastscan, static_cast<uint8_t>(id), static_cast<uint8_t>(id >> 8U),
             static_cast<uint8_t>(id >> 16U), static_cast<uint8_t>(id >> 24U), 0, sub,
             static_cast<uint8_t>((sub + 1U) % 4U)});
  }
  EXPECT_TRUE(lss_.configurationState());
  EXPECT_EQ(sent(), frames({answer({0x4F}), answer({0x4F}), answer({0x4F}), answer({0x4F}),
                            answer({0x4F})}));
}

TEST_F(LssSlaveTest, MalformedFramesAreTurnedAwayWithoutAnAnswer) {
  configuration();
  EXPECT_FALSE(lss_.onFrame(frame(0x7E5, {lss::kInquireNodeId}), kStart));  // DLC 1
  CanFrame remoteRequest = frame8(0x7E5, {lss::kInquireNodeId});
  remoteRequest.rtr = true;
  EXPECT_FALSE(lss_.onFrame(remoteRequest, kStart));
  CanFrame extended = frame8(0x7E5, {lss::kInquireNodeId});
  extended.extended = true;
  EXPECT_FALSE(lss_.onFrame(extended, kStart));
  EXPECT_FALSE(lss_.onFrame(frame8(0x7E4, {lss::kInquireNodeId}), kStart));
  ignored({0x99});
  ignored({lss::kSwitchStateGlobal, 2});
  EXPECT_TRUE(sent().empty());
  EXPECT_TRUE(lss_.configurationState());
}

}  // namespace
}  // namespace costa::test
