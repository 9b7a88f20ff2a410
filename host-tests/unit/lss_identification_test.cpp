// LSS slave (CiA 305): the services that pick a device by its identity — switch state
// selective, identify remote slave, identify non-configured remote slave and single LSS
// Fastscan steps. Driven directly with frames; every response is checked byte for byte.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "lss_test_bus.hpp"

namespace costa::test {
namespace {

const LssIdentity& kIdentity = kLssTestIdentity;

/// "rx 7E5 [8] cs v0 v1 v2 v3 b5 b6 b7": a request carrying a little-endian value.
std::string request(uint8_t cs, uint32_t value, uint8_t byte5 = 0, uint8_t byte6 = 0,
                    uint8_t byte7 = 0) {
  char text[64];
  snprintf(text, sizeof(text), "rx 7E5 [8] %02X %02X %02X %02X %02X %02X %02X %02X\n", cs,
           value & 0xFFU, (value >> 8U) & 0xFFU, (value >> 16U) & 0xFFU, value >> 24U, byte5, byte6,
           byte7);
  return text;
}

std::string fastscan(uint32_t idNumber, uint8_t bitChecked, uint8_t lssSub, uint8_t lssNext) {
  return request(0x51, idNumber, bitChecked, lssSub, lssNext);
}

const char* const kIdentifySlave = "tx 7E4 [8] 4F 00 00 00 00 00 00 00\n";

/// The test identity without a node-id, so that it takes part in Fastscan.
class LssIdentificationTest : public LssSlaveTest {
 protected:
  LssIdentificationTest() { bus_.reset(kIdentity, 0xFF, 0xFF); }

  std::string selective(uint32_t vendor, uint32_t product, uint32_t revision, uint32_t serial) {
    return request(0x40, vendor) + request(0x41, product) + request(0x42, revision) +
           request(0x43, serial);
  }
  std::string identify(uint32_t revisionLow, uint32_t revisionHigh, uint32_t serialLow,
                       uint32_t serialHigh, uint32_t vendor = kIdentity.vendorId,
                       uint32_t product = kIdentity.productCode) {
    return request(0x46, vendor) + request(0x47, product) + request(0x48, revisionLow) +
           request(0x49, revisionHigh) + request(0x4A, serialLow) + request(0x4B, serialHigh);
  }
};

// --- switch state selective -------------------------------------------------------------

TEST_F(LssIdentificationTest,
       SwitchStateSelectiveAnswersAfterTheFourthMatchAndEntersConfiguration) {
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 40 78 56 34 12 00 00 00
    rx 7E5 [8] 41 F0 DE BC 9A 00 00 00
    rx 7E5 [8] 42 01 00 02 00 00 00 00
    silence
  )");
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_TRANSCRIPT(R"(
    rx 7E5 [8] 43 0D F0 FE CA 00 00 00
    tx 7E4 [8] 44 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(slave().state(), LssState::kConfiguration);
}

TEST_F(LssIdentificationTest, SwitchStateSelectiveWithAnyOneFieldWrongDoesNothing) {
  const LssIdentity& id = kIdentity;
  const std::string wrong[] = {
      selective(id.vendorId + 1U, id.productCode, id.revisionNumber, id.serialNumber),
      selective(id.vendorId, id.productCode ^ 0x80000000U, id.revisionNumber, id.serialNumber),
      selective(id.vendorId, id.productCode, id.revisionNumber - 1U, id.serialNumber),
      selective(id.vendorId, id.productCode, id.revisionNumber, id.serialNumber ^ 1U),
  };
  for (const std::string& sequence : wrong) {
    EXPECT_EQ(play(sequence + "silence"), "") << sequence;
    EXPECT_EQ(slave().state(), LssState::kWaiting) << sequence;
  }
}

TEST_F(LssIdentificationTest, SwitchStateSelectiveNeedsTheFramesInOrder) {
  const LssIdentity& id = kIdentity;
  // Product before vendor, serial without revision, serial alone.
  EXPECT_TRANSCRIPT(request(0x41, id.productCode) + request(0x40, id.vendorId) +
                    request(0x42, id.revisionNumber) + request(0x43, id.serialNumber) + "silence");
  EXPECT_TRANSCRIPT(request(0x40, id.vendorId) + request(0x41, id.productCode) +
                    request(0x43, id.serialNumber) + "silence");
  EXPECT_TRANSCRIPT(request(0x43, id.serialNumber) + "silence");
  // A wrong field breaks the sequence: the correct rest no longer counts.
  EXPECT_TRANSCRIPT(request(0x40, id.vendorId) + request(0x41, 0) + request(0x41, id.productCode) +
                    request(0x42, id.revisionNumber) + request(0x43, id.serialNumber) + "silence");
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  // The vendor-id always starts a new sequence, even in the middle of one.
  EXPECT_TRANSCRIPT(request(0x40, id.vendorId) + request(0x41, id.productCode) +
                    selective(id.vendorId, id.productCode, id.revisionNumber, id.serialNumber) +
                    "tx 7E4 [8] 44 00 00 00 00 00 00 00");
  EXPECT_EQ(slave().state(), LssState::kConfiguration);
}

TEST_F(LssIdentificationTest, SwitchStateSelectiveIsIgnoredInConfigurationState) {
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 01 00 00 00 00 00 00");
  const LssIdentity& id = kIdentity;
  const std::string frames[] = {request(0x40, id.vendorId), request(0x41, id.productCode),
                                request(0x42, id.revisionNumber), request(0x43, id.serialNumber)};
  for (const std::string& frame : frames) {
    EXPECT_EQ(play(frame + "silence"), "") << frame;
    EXPECT_FALSE(bus_.accepted()) << frame;
  }
  // And what was sent there does not count after returning to waiting state.
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 00 00 00 00 00 00 00");
  EXPECT_TRANSCRIPT(request(0x43, id.serialNumber) + "silence");
  EXPECT_EQ(slave().state(), LssState::kWaiting);
}

TEST_F(LssIdentificationTest, SwitchStateGlobalForgetsAPartialSelectiveSequence) {
  const LssIdentity& id = kIdentity;
  EXPECT_TRANSCRIPT(request(0x40, id.vendorId) + request(0x41, id.productCode) +
                    request(0x42, id.revisionNumber) + "rx 7E5 [8] 04 00 00 00 00 00 00 00\n" +
                    request(0x43, id.serialNumber) + "silence");
  EXPECT_EQ(slave().state(), LssState::kWaiting);
}

// --- identify remote slave --------------------------------------------------------------

TEST_F(LssIdentificationTest, IdentifyRemoteSlaveAnswersWhenRevisionAndSerialAreInRange) {
  const uint32_t rev = kIdentity.revisionNumber;
  const uint32_t serial = kIdentity.serialNumber;
  const std::string inRange[] = {
      identify(rev, rev, serial, serial),        // bounds equal to the values
      identify(0, 0xFFFFFFFFU, 0, 0xFFFFFFFFU),  // everything
      identify(rev - 1U, rev + 1U, serial - 5U, serial + 5U),
      identify(rev, 0xFFFFFFFFU, 0, serial),  // value on either bound
  };
  for (const std::string& sequence : inRange) {
    EXPECT_EQ(play(sequence + kIdentifySlave), "") << sequence;
    EXPECT_EQ(slave().state(), LssState::kWaiting);
  }
}

TEST_F(LssIdentificationTest, IdentifyRemoteSlaveIsSilentWhenAnyFieldIsOutOfRange) {
  const uint32_t rev = kIdentity.revisionNumber;
  const uint32_t serial = kIdentity.serialNumber;
  const std::string outOfRange[] = {
      identify(rev + 1U, 0xFFFFFFFFU, 0, 0xFFFFFFFFU),  // revision below the range
      identify(0, rev - 1U, 0, 0xFFFFFFFFU),            // revision above the range
      identify(0, 0xFFFFFFFFU, serial + 1U, 0xFFFFFFFFU),
      identify(0, 0xFFFFFFFFU, 0, serial - 1U),
      identify(0, 0xFFFFFFFFU, 0, 0xFFFFFFFFU, kIdentity.vendorId + 1U),
      identify(0, 0xFFFFFFFFU, 0, 0xFFFFFFFFU, kIdentity.vendorId, kIdentity.productCode - 1U),
      identify(rev + 1U, rev - 1U, 0, 0xFFFFFFFFU),  // an empty range
  };
  for (const std::string& sequence : outOfRange) {
    EXPECT_EQ(play(sequence + "silence"), "") << sequence;
  }
}

TEST_F(LssIdentificationTest, IdentifyRemoteSlaveNeedsTheFramesInOrder) {
  const std::string all = identify(0, 0xFFFFFFFFU, 0, 0xFFFFFFFFU);
  // The last five frames alone, and the sequence with the revision bounds swapped.
  EXPECT_TRANSCRIPT(all.substr(all.find('\n') + 1U) + "silence");
  EXPECT_TRANSCRIPT(request(0x46, kIdentity.vendorId) + request(0x47, kIdentity.productCode) +
                    request(0x49, 0xFFFFFFFFU) + request(0x48, 0) + request(0x4A, 0) +
                    request(0x4B, 0xFFFFFFFFU) + "silence");
}

TEST_F(LssIdentificationTest, IdentifyRemoteSlaveWorksInBothStatesAndChangesNoState) {
  const std::string all = identify(0, 0xFFFFFFFFU, 0, 0xFFFFFFFFU);
  EXPECT_TRANSCRIPT(all + kIdentifySlave);
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 01 00 00 00 00 00 00");
  EXPECT_TRANSCRIPT(all + kIdentifySlave);
  EXPECT_TRUE(bus_.accepted());
  EXPECT_EQ(slave().state(), LssState::kConfiguration);
  bus_.reset(kIdentity, 7, 7);  // configured devices answer too
  EXPECT_TRANSCRIPT(all + kIdentifySlave);
}

TEST_F(LssIdentificationTest, ResetForgetsPartialIdentifyAndSelectiveSequences) {
  const LssIdentity& id = kIdentity;
  EXPECT_TRANSCRIPT(request(0x46, id.vendorId) + request(0x47, id.productCode) + request(0x48, 0) +
                    request(0x49, 0xFFFFFFFFU) + request(0x4A, 0) + request(0x40, id.vendorId) +
                    request(0x41, id.productCode) + request(0x42, id.revisionNumber));
  bus_.reset(kIdentity, 0xFF, 0xFF);
  EXPECT_TRANSCRIPT(request(0x4B, 0xFFFFFFFFU) + request(0x43, id.serialNumber) + "silence");
  EXPECT_EQ(slave().state(), LssState::kWaiting);
}

// --- identify non-configured remote slave -----------------------------------------------

TEST_F(LssIdentificationTest, IdentifyNonConfiguredAnswersOnlyWithoutAnyNodeId) {
  const char* const identifyNonConfigured = "rx 7E5 [8] 4C 00 00 00 00 00 00 00\n";
  EXPECT_TRANSCRIPT(std::string(identifyNonConfigured) + "tx 7E4 [8] 50 00 00 00 00 00 00 00");
  EXPECT_TRANSCRIPT("rx 7E5 [8] 04 01 00 00 00 00 00 00");
  EXPECT_TRANSCRIPT(std::string(identifyNonConfigured) + "tx 7E4 [8] 50 00 00 00 00 00 00 00");

  struct Case {
    uint8_t active;
    uint8_t pending;
  };
  for (const Case& c : {Case{5, 5}, Case{0xFF, 5}, Case{5, 0xFF}}) {
    bus_.reset(kIdentity, c.active, c.pending);
    EXPECT_EQ(play(std::string(identifyNonConfigured) + "silence"), "") << int{c.active};
    EXPECT_TRUE(bus_.accepted());
  }
}

// --- LSS Fastscan, single steps ---------------------------------------------------------

TEST_F(LssIdentificationTest, FastscanResetIsAnsweredByNonConfiguredSlavesOnly) {
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + kIdentifySlave);
  bus_.reset(kIdentity, 3, 3);
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + "silence");
  bus_.reset(kIdentity, 0xFF, 3);  // node-id configured, not yet active
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + "silence");
}

TEST_F(LssIdentificationTest, FastscanComparesBits31DownToBitChecked) {
  const uint32_t vendor = kIdentity.vendorId;  // 0x12345678: bit 31 is 0, bit 28 is 1
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + kIdentifySlave);
  EXPECT_TRANSCRIPT(fastscan(0x00000000U, 31, 0, 0) + kIdentifySlave);  // bit 31 = 0: match
  EXPECT_TRANSCRIPT(fastscan(0x80000000U, 31, 0, 0) + "silence");       // bit 31 = 1: no
  EXPECT_TRANSCRIPT(fastscan(0x00000000U, 28, 0, 0) + "silence");       // bit 28 differs
  EXPECT_TRANSCRIPT(fastscan(0x10000000U, 28, 0, 0) + kIdentifySlave);
  EXPECT_TRANSCRIPT(fastscan(vendor ^ 1U, 1, 0, 0) + kIdentifySlave);  // bit 0 not checked
  EXPECT_TRANSCRIPT(fastscan(vendor ^ 1U, 0, 0, 0) + "silence");
  EXPECT_TRANSCRIPT(fastscan(vendor, 0, 0, 0) + kIdentifySlave);
  EXPECT_EQ(slave().state(), LssState::kWaiting);
}

TEST_F(LssIdentificationTest, FastscanConfirmsEachValueThenEntersConfiguration) {
  const LssIdentity& id = kIdentity;
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + kIdentifySlave);
  // Asking for the product code before the vendor-id is confirmed: the slave is not there.
  EXPECT_TRANSCRIPT(fastscan(id.productCode, 0, 1, 1) + "silence");
  EXPECT_TRANSCRIPT(fastscan(id.vendorId, 0, 0, 1) + kIdentifySlave);  // on to the product
  EXPECT_TRANSCRIPT(fastscan(id.vendorId, 0, 0, 1) + "silence");       // vendor step is over
  EXPECT_TRANSCRIPT(fastscan(id.productCode, 0, 1, 2) + kIdentifySlave);
  EXPECT_TRANSCRIPT(fastscan(id.revisionNumber, 0, 2, 3) + kIdentifySlave);
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_TRANSCRIPT(fastscan(id.serialNumber ^ 0x100U, 0, 3, 0) + "silence");
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_TRANSCRIPT(fastscan(id.serialNumber, 1, 3, 3) + kIdentifySlave);  // bit steps stay
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_TRANSCRIPT(fastscan(id.serialNumber, 0, 3, 0) + kIdentifySlave);
  EXPECT_EQ(slave().state(), LssState::kConfiguration);
  // Fastscan is a waiting-state service.
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + "silence");
  EXPECT_FALSE(bus_.accepted());
}

TEST_F(LssIdentificationTest, OnlyAFullCompareWithALowerLssNextEntersConfiguration) {
  const LssIdentity& id = kIdentity;
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + fastscan(id.vendorId, 0, 0, 3) +
                    "tx 7E4 [8] 4F 00 00 00 00 00 00 00\ntx 7E4 [8] 4F 00 00 00 00 00 00 00");
  // The scan moved straight to the serial number; a bit step naming LSSNext 0 is answered
  // (and moves the scan on) but confirms nothing.
  EXPECT_TRANSCRIPT(fastscan(id.serialNumber, 1, 3, 0) + kIdentifySlave);
  EXPECT_EQ(slave().state(), LssState::kWaiting);
  EXPECT_TRANSCRIPT(fastscan(id.vendorId, 0, 0, 0) + kIdentifySlave);  // LSSNext == LSSSub
  EXPECT_EQ(slave().state(), LssState::kWaiting);
}

TEST_F(LssIdentificationTest, FastscanResetStartsOverFromTheVendorId) {
  const LssIdentity& id = kIdentity;
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + kIdentifySlave);
  EXPECT_TRANSCRIPT(fastscan(id.vendorId, 0, 0, 1) + kIdentifySlave);
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + kIdentifySlave);
  EXPECT_TRANSCRIPT(fastscan(id.productCode, 0, 1, 2) + "silence");
  EXPECT_TRANSCRIPT(fastscan(id.vendorId, 0, 0, 1) + kIdentifySlave);
}

TEST_F(LssIdentificationTest, ResetStartsTheScanOverAtTheVendorId) {
  const LssIdentity& id = kIdentity;
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + kIdentifySlave);
  EXPECT_TRANSCRIPT(fastscan(id.vendorId, 0, 0, 1) + kIdentifySlave);
  bus_.reset(kIdentity, 0xFF, 0xFF);
  EXPECT_TRANSCRIPT(fastscan(id.productCode, 0, 1, 2) + "silence");
  EXPECT_TRANSCRIPT(fastscan(id.vendorId, 0, 0, 1) + kIdentifySlave);
}

TEST_F(LssIdentificationTest, FastscanWithInvalidFieldsIsIgnored) {
  EXPECT_TRANSCRIPT(fastscan(0, 0x80, 0, 0) + kIdentifySlave);
  const std::string invalid[] = {
      fastscan(0, 32, 0, 0),    fastscan(0, 0x7F, 0, 0), fastscan(0, 0x81, 0, 0),
      fastscan(0, 0xFF, 0, 0),  fastscan(0, 31, 4, 4),   fastscan(0, 31, 0, 4),
      fastscan(0, 31, 0xFF, 0),
  };
  for (const std::string& frame : invalid) {
    EXPECT_EQ(play(frame + "silence"), "") << frame;
    EXPECT_FALSE(bus_.accepted()) << frame;
  }
  EXPECT_TRANSCRIPT(fastscan(0, 31, 0, 0) + kIdentifySlave);  // still at the vendor-id
}

}  // namespace
}  // namespace costa::test
