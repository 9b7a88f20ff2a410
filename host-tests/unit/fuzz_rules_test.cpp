// The fuzz harness's invariants (host-tests/fuzz): each one passes on a healthy example node and
// fails on the state it is there to catch, so that a fuzz run that finds nothing means
// something.
#include <gtest/gtest.h>

#include <string.h>

#include <memory>
#include <vector>

#include "checked_state.hpp"
#include "costa/od/little_endian.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "costa/stored_image.hpp"
#include "dictionary_rules.hpp"
#include "example_target.hpp"
#include "frame_rules.hpp"
#include "fuzzed_device.hpp"
#include "state_rules.hpp"
#include "storage_rules.hpp"
#include "watching_can.hpp"

namespace costa::fuzz {
namespace {

CanFrame frame(uint32_t id, std::initializer_list<uint8_t> data) {
  CanFrame f;
  f.id = id;
  f.dlc = static_cast<uint8_t>(data.size());
  size_t i = 0;
  for (uint8_t byte : data) {
    f.data[i++] = byte;
  }
  return f;
}

class FuzzRules : public ::testing::Test {
 protected:
  FuzzRules() : target_(can_, DeviceConfig{0, false, &storage_, nullptr}) { target_.start(0); }

  Node& node() { return target_.node(); }
  /// An SDO request to node 1, answered at once.
  void sdo(std::initializer_list<uint8_t> data) { target_.onFrame(frame(0x601, data), 0); }

  port::MemoryStorageOf<16384> storage_;
  port::RecordingCan can_;
  example::ExampleTarget target_;
};

TEST_F(FuzzRules, OwnIdsAreAllowedForeignOnesAreNot) {
  target_.onFrame(frame(0x000, {0x01, 0x01}), 0);  // operational
  const CanIdSet allowed = allowedTransmitIds(node(), true);
  for (uint32_t id : {0x701U, 0x581U, 0x081U, 0x181U, 0x7E4U}) {
    EXPECT_TRUE(allowed.contains(id)) << std::hex << id;
  }
  for (uint32_t id : {0x702U, 0x582U, 0x082U, 0x000U, 0x7E5U, 0x601U}) {
    EXPECT_FALSE(allowed.contains(id)) << std::hex << id;
  }
  EXPECT_FALSE(allowedTransmitIds(node(), false).contains(0x7E4U));
}

TEST_F(FuzzRules, TheNmtStateLimitsTheServices) {
  const CanIdSet preOperational = allowedTransmitIds(node(), true);
  EXPECT_TRUE(preOperational.contains(0x581U));
  EXPECT_TRUE(preOperational.contains(0x081U));
  EXPECT_FALSE(preOperational.contains(0x181U));   // no PDO before operational
  target_.onFrame(frame(0x000, {0x02, 0x01}), 0);  // stopped
  const CanIdSet stopped = allowedTransmitIds(node(), true);
  EXPECT_TRUE(stopped.contains(0x701U));
  EXPECT_TRUE(stopped.contains(0x7E4U));
  EXPECT_FALSE(stopped.contains(0x581U));
  EXPECT_FALSE(stopped.contains(0x081U));
  EXPECT_FALSE(stopped.contains(0x181U));
}

TEST_F(FuzzRules, ConfiguredCobIdsMoveTheAllowedIds) {
  sdo({0x23, 0x14, 0x10, 0x00, 0x81, 0x00, 0x00, 0x80});  // EMCY not valid
  EXPECT_FALSE(allowedTransmitIds(node(), true).contains(0x081U));
  sdo({0x23, 0x14, 0x10, 0x00, 0x95, 0x00, 0x00, 0x00});  // EMCY valid on 0x095
  EXPECT_TRUE(allowedTransmitIds(node(), true).contains(0x095U));
  sdo({0x23, 0x05, 0x10, 0x00, 0x90, 0x00, 0x00, 0x40});  // SYNC producer on 0x090
  EXPECT_TRUE(allowedTransmitIds(node(), true).contains(0x090U));
  EXPECT_EQ(checkConfiguredCanIds(node()), "");
}

TEST_F(FuzzRules, AValidCobIdWithARestrictedCanIdIsReported) {
  EXPECT_EQ(checkConfiguredCanIds(node()), "");
  node().dictionary().storeUnsigned(0x1014, 0, 0x585);  // bypasses the write checks
  EXPECT_EQ(checkConfiguredCanIds(node()), "valid EMCY COB-ID 0x585 has a restricted CAN-ID");
  node().dictionary().storeUnsigned(0x1014, 0, 0x80000585U);
  EXPECT_EQ(checkConfiguredCanIds(node()), "");
  node().dictionary().storeUnsigned(0x1005, 0, 0x601);
  EXPECT_EQ(checkConfiguredCanIds(node()), "SYNC COB-ID 0x601 has a restricted CAN-ID");
  node().dictionary().storeUnsigned(0x1005, 0, 0x80);
  node().dictionary().storeUnsigned(0x1800, 1, 0x701);
  EXPECT_NE(checkConfiguredCanIds(node()), "");
}

TEST_F(FuzzRules, AnAdditionalSdoServerAnswersOnItsOwnCanIdOnly) {
  EXPECT_FALSE(allowedTransmitIds(node(), true).contains(0x6C1U));
  sdo({0x23, 0x01, 0x12, 0x02, 0xC1, 0x06, 0x00, 0x00});  // 0x1201:02 = 0x6C1
  EXPECT_TRUE(allowedTransmitIds(node(), true).contains(0x6C1U));
  EXPECT_FALSE(allowedTransmitIds(node(), true).contains(0x6C2U));
  EXPECT_EQ(checkConfiguredCanIds(node()), "");
  node().dictionary().storeUnsigned(0x1201, 1, 0x605);  // bypasses the write checks
  EXPECT_EQ(checkConfiguredCanIds(node()),
            "valid SDO server COB-ID 0x605 at 0x1201 has a restricted or 29-bit CAN-ID");
  node().dictionary().storeUnsigned(0x1201, 1, 0x20000681U);
  EXPECT_NE(checkConfiguredCanIds(node()), "");
  node().dictionary().storeUnsigned(0x1201, 1, 0xA0000681U);
  EXPECT_EQ(checkConfiguredCanIds(node()), "");
}

TEST_F(FuzzRules, FramesMustHaveTheirFormAndAnAllowedId) {
  const CanIdSet allowed = allowedTransmitIds(node(), true);
  EXPECT_EQ(checkTransmittedFrame(frame(0x701, {0x05}), allowed), "");
  EXPECT_EQ(checkTransmittedFrame(frame(0x581, {0x60, 0x17, 0x10, 0, 0, 0, 0, 0}), allowed), "");
  EXPECT_NE(checkTransmittedFrame(frame(0x702, {0x05}), allowed), "");
  EXPECT_NE(checkTransmittedFrame(frame(0x701, {0x05, 0x00}), allowed), "");  // DLC 2
  EXPECT_NE(checkTransmittedFrame(frame(0x581, {0x60, 0x17, 0x10}), allowed), "");
  CanFrame beyond = frame(0x181, {1, 2});
  beyond.data[5] = 0x55;
  EXPECT_EQ(checkTransmittedFrame(beyond, allowed),
            "transmitted frame 181 [2] 01 02 (00) (00) (00) (55) (00) (00): data byte beyond "
            "the DLC is not zero");
  CanFrame remote = frame(0x181, {});
  remote.rtr = true;
  EXPECT_NE(checkTransmittedFrame(remote, allowed), "");
  CanFrame extended = frame(0x181, {});
  extended.extended = true;
  EXPECT_NE(checkTransmittedFrame(extended, allowed), "");
  CanFrame oversized = frame(0x181, {});
  oversized.dlc = 9;
  EXPECT_NE(checkTransmittedFrame(oversized, allowed), "");
}

TEST_F(FuzzRules, DictionaryValuesOutsideTheirDefinitionAreReported) {
  od::ObjectDictionary& dictionary = node().dictionary();
  EXPECT_EQ(checkDictionaryValues(dictionary), "");
  dictionary.storeUnsigned(0x2004, 1, 2);  // BOOLEAN
  EXPECT_EQ(checkDictionaryValues(dictionary), "dictionary value 0x2004:01: BOOLEAN 2");
  dictionary.storeUnsigned(0x2004, 1, 1);
  dictionary.storeUnsigned(0x2004, 2, static_cast<uint8_t>(-101));  // INTEGER8 -100..100
  EXPECT_EQ(checkDictionaryValues(dictionary),
            "dictionary value 0x2004:02: -101 outside -100..100");
  dictionary.storeUnsigned(0x2004, 2, 100);
  EXPECT_EQ(checkDictionaryValues(dictionary), "");
  const od::EntryRef real = dictionary.find(0x2004, 4);  // REAL32 0..10
  const float nan = __builtin_nanf("");
  memcpy(dictionary.ramAddress(real), &nan, sizeof(nan));
  EXPECT_EQ(checkDictionaryValues(dictionary), "dictionary value 0x2004:04: nan outside 0..10");
  const float ten = 10.0F;
  memcpy(dictionary.ramAddress(real), &ten, sizeof(ten));
  EXPECT_EQ(checkDictionaryValues(dictionary), "");
  const od::EntryRef label = dictionary.find(0x2006, 0);  // VISIBLE_STRING of 32
  dictionary.ramAddress(label)[label.size()] = 'x';
  EXPECT_EQ(checkDictionaryValues(dictionary),
            "dictionary value 0x2006:00: string without its terminating zero");
}

TEST_F(FuzzRules, TheChecksRunAgainWhenAValueTheNodeIdOrTheStateChanges) {
  CheckedState checked;
  EXPECT_FALSE(checked.same(node()));  // nothing checked yet
  CanIdSet allowed = allowedTransmitIds(node(), true);
  checked.remember(node(), allowed);
  EXPECT_TRUE(checked.same(node()));
  EXPECT_TRUE(checked.allowed().contains(0x581));
  od::ObjectDictionary& dictionary = node().dictionary();
  dictionary.storeUnsigned(0x2004, 2, 7);  // any value, even one within its limits
  EXPECT_FALSE(checked.same(node()));
  checked.remember(node(), allowed);
  auto* values = static_cast<uint8_t*>(dictionary.values());
  std::vector<uint8_t> before(values, values + dictionary.definition().valuesSize);
  target_.onFrame(frame(0x000, {0x01, 0x01}), 0);  // operational
  memcpy(values, before.data(), before.size());    // the same values: only the state differs
  EXPECT_FALSE(checked.same(node()));
  allowed = allowedTransmitIds(node(), true);
  checked.remember(node(), allowed);
  EXPECT_TRUE(checked.allowed().contains(0x181));  // the TPDOs' ids now
  target_.onFrame(frame(0x000, {0x80, 0x00}), 0);  // pre-operational
  before.assign(values, values + dictionary.definition().valuesSize);
  checked.remember(node(), allowedTransmitIds(node(), true));
  target_.onFrame(frame(0x7E5, {0x04, 0x01, 0, 0, 0, 0, 0, 0}), 0);  // LSS configuration
  target_.onFrame(frame(0x7E5, {0x11, 0x05, 0, 0, 0, 0, 0, 0}), 0);  // pending node-id 5
  target_.onFrame(frame(0x7E5, {0x04, 0x00, 0, 0, 0, 0, 0, 0}), 0);
  target_.onFrame(frame(0x000, {0x82, 0x00}), 0);  // reset communication: node-id 5
  ASSERT_EQ(node().nodeId(), 5U);
  ASSERT_EQ(node().state(), NmtState::kPreOperational);
  memcpy(values, before.data(), before.size());  // the same values: only the node-id differs
  EXPECT_FALSE(checked.same(node()));
}

TEST_F(FuzzRules, StoredParametersMustLoad) {
  const od::Definition& definition = node().dictionary().definition();
  EXPECT_EQ(checkStoredParameters(definition, 1, storage_), "");  // nothing stored
  sdo({0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65});          // 0x1010:01 = "save"
  ASSERT_GT(storage_.modifyingCalls(), 0U);
  EXPECT_EQ(checkStoredParameters(definition, 1, storage_), "");
  // The first region is group 1's; its first save went to slot 0, at offset 0. A flipped
  // payload bit leaves no intact image of the group.
  storage_.bytes()[kImageHeaderSize] ^= 0x01U;
  EXPECT_EQ(checkStoredParameters(definition, 1, storage_),
            "stored parameters: group 1 loads as 'corrupt'");
}

TEST_F(FuzzRules, StateMachinesOfAHealthyNodeAreValid) {
  EXPECT_EQ(checkStateMachines(node(), true), "");
  sdo({0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0});  // segmented upload of the device name
  ASSERT_TRUE(node().sdo().busy());
  EXPECT_EQ(checkStateMachines(node(), true), "");
  target_.onFrame(frame(0x7E5, {0x04, 0x01, 0, 0, 0, 0, 0, 0}), 0);  // LSS configuration
  EXPECT_EQ(checkStateMachines(node(), true), "");
  EXPECT_EQ(checkStateMachines(node(), false), "LSS slave active on a device without LSS");
}

TEST_F(FuzzRules, AHeartbeatErrorNeedsItsTimedOutEntry) {
  sdo({0x23, 0x16, 0x10, 0x01, 0x64, 0x00, 0x05, 0x00});  // 0x1016:01 = node 5, 100 ms
  EXPECT_EQ(checkStateMachines(node(), true), "");
  node().raiseError(0x8130, kErrorCommunication, nullptr, 200);  // no such entry: not checked
  node().raiseError(0x8130, kErrorCommunication, nullptr, 0);    // life guarding's
  EXPECT_EQ(checkStateMachines(node(), true), "");
  node().raiseError(0x8130, kErrorCommunication, nullptr, 1);  // entry 1 has not timed out
  EXPECT_EQ(checkStateMachines(node(), true),
            "EMCY 0x8130 of 0x1016 sub-index 1 active while its entry has not timed out");
}

TEST(FuzzWatchingCan, AFrameDuringBusOffIsNoted) {
  WatchingCan can;
  const std::unique_ptr<FuzzedDevice> device = createFuzzedDevice("example", can, {});
  can.watch(device.get());
  device->powerOn(0);
  device->node().onControllerEvent(CanControllerEvent::kBusOff, device->node().now());
  EXPECT_EQ(can.problem(), "");           // the boot-up before, nothing during
  can.tryTransmit(frame(0x701, {0x7F}));  // as a node that ignored bus-off would
  EXPECT_EQ(can.problem(), "frame 701 [1] 7F handed to a bus-off controller");
}

TEST(FuzzWatchingCan, AFrameDuringAnLssBitTimingSwitchIsNoted) {
  WatchingCan can;
  const std::unique_ptr<FuzzedDevice> device = createFuzzedDevice("example", can, {});
  can.watch(device.get());
  device->powerOn(0);
  device->onFrame(frame(0x7E5, {0x04, 0x01, 0, 0, 0, 0, 0, 0}), 0);  // configuration
  device->onFrame(frame(0x7E5, {0x15, 0x64, 0, 0, 0, 0, 0, 0}), 0);  // activate, 100 ms
  ASSERT_TRUE(device->node().lss().transmissionSuspended());
  device->process(50000);
  EXPECT_EQ(can.problem(), "");
  can.tryTransmit(frame(0x701, {0x7F}));
  EXPECT_EQ(can.problem(), "frame 701 [1] 7F sent during an LSS bit timing switch");
}

TEST(FuzzDeviceInvariant, TheJointsStatusWordMustShowItsState) {
  port::RecordingCan can;
  const std::unique_ptr<FuzzedDevice> device = createFuzzedDevice("mseries", can, {});
  device->powerOn(0);
  EXPECT_EQ(device->checkDevice(), "");  // 0x0404 under pulse control
  od::ObjectDictionary& dictionary = device->node().dictionary();
  dictionary.storeUnsigned(0x6041, 0, 0x0040);  // CiA 402's switch on disabled: bit 6
  EXPECT_EQ(device->checkDevice(), "the status word sets bit 6, 7, 9 or 11");
  dictionary.storeUnsigned(0x6041, 0, 0x1404);  // bit 12 in mode 0
  EXPECT_EQ(device->checkDevice(), "the status word sets bit 12 or 13 outside homing");
  dictionary.storeUnsigned(0x6041, 0, 0x0437);  // operation enabled: not the drive's state
  EXPECT_EQ(device->checkDevice(), "the status word does not show the drive's state");
  const std::unique_ptr<FuzzedDevice> example = createFuzzedDevice("example", can, {});
  example->powerOn(0);
  EXPECT_EQ(example->checkDevice(), "");  // a device without an invariant of its own
}

}  // namespace
}  // namespace costa::fuzz
