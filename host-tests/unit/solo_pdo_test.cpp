// The SOLO's fixed PDO mappings (manual lines 544-560) and its triggering rules (lines 564-606):
// every RPDO writes its object, every TPDO carries its object, bit 30 of a TPDO COB-ID decides
// whether a remote frame is answered, and the transmission types of both directions.
#include <stdio.h>

#include <string>

#include "device_fixture.hpp"

namespace costa::test {
namespace {

/// "B0 B1 B2 B3": `value` little-endian, as a transcript writes data bytes.
std::string wireBytes(uint32_t value) {
  char text[16];
  snprintf(text, sizeof text, "%02X %02X %02X %02X", value & 0xFFU, (value >> 8) & 0xFFU,
           (value >> 16) & 0xFFU, value >> 24);
  return text;
}

/// "LL HH": an index as the two index bytes of an SDO frame.
std::string indexBytes(uint16_t index) {
  char text[8];
  snprintf(text, sizeof text, "%02X %02X", index & 0xFFU, index >> 8);
  return text;
}

std::string hex(uint32_t value) {
  char text[12];
  snprintf(text, sizeof text, "%X", value);
  return text;
}

/// Writes `value` to `index`.`sub` by an expedited 4-byte download and expects the confirmation.
std::string download(uint16_t index, uint8_t sub, uint32_t value) {
  char subText[4];
  snprintf(subText, sizeof subText, "%02X", sub);
  const std::string address = indexBytes(index) + " " + subText;
  return "rx 601 [8] 23 " + address + " " + wireBytes(value) + "\ntx 581 [8] 60 " + address +
         " 00 00 00 00\n";
}

/// Reads `index` by SDO and expects `value` (the SOLO's 0x42 upload response, errata P1).
std::string upload(uint16_t index, uint32_t value) {
  return "rx 601 [8] 40 " + indexBytes(index) + " 00 00 00 00 00\ntx 581 [8] 42 " +
         indexBytes(index) + " 00 " + wireBytes(value) + "\n";
}

class SoloPdo : public DeviceTest {
 protected:
  SoloPdo() : DeviceTest("solo", 1) {}
  void SetUp() override { ASSERT_EQ(play("tx 701 [1] 00"), ""); }

  /// The 4 data bytes of `index` read by SDO (the SOLO's 0x42 response, errata P1).
  std::string readBySdo(uint16_t index) { return wireBytes(uploadFourBytes(index, 0, 0x42)); }
};

// ---------------------------------------------------------------------------------------------
// RPDO2..RPDO6: enabled with bit 31 (errata P3), applied at once with type 0xFF (line 606).

struct RpdoRow {
  const char* name;
  uint16_t communication;  // 0x1415..0x1419
  uint16_t object;         // the fixed mapping (line 550-554)
  uint32_t value;          // within the object's limits
};

const RpdoRow kRpdos[] = {
    {"Rpdo2SpeedReference", 0x1415, 0x3005, 0x00001234},
    {"Rpdo3TorqueReference", 0x1416, 0x3004, 0x00012345},
    {"Rpdo4DirectCurrentReference", 0x1417, 0x301A, 0x00023456},
    {"Rpdo5ControlMode", 0x1418, 0x3016, 0x00000002},
    {"Rpdo6MotorDirection", 0x1419, 0x300C, 0x00000001},
};

class SoloRpdoMapping : public SoloPdo, public ::testing::WithParamInterface<RpdoRow> {};

TEST_P(SoloRpdoMapping, FourBytesReachTheMappedObject) {
  const RpdoRow& row = GetParam();
  const uint32_t canId = 0x210U + (row.communication - 0x1414U);
  const uint32_t before = row.object == 0x3016 ? 1U : 0U;  // control mode's default: torque
  const std::string rpdo = "rx " + hex(canId) + " [4] " + wireBytes(row.value) + "\n";
  EXPECT_TRANSCRIPT(download(row.communication, 1, 0x80000000U | canId) +
                    download(row.communication, 2, 0xFF) + upload(row.object, before) +
                    "rx 000 [2] 01 01\n" + rpdo + "silence\n" + upload(row.object, row.value) +
                    "silence\n");
}

INSTANTIATE_TEST_SUITE_P(EveryRpdo, SoloRpdoMapping, ::testing::ValuesIn(kRpdos),
                         [](const ::testing::TestParamInfo<RpdoRow>& param) {
                           return std::string(param.param.name);
                         });

// ---------------------------------------------------------------------------------------------
// TPDO3..TPDO6: enabled with bit 31 and RTR allowed with bit 30 (errata P3), type 0 (every SYNC,
// errata P6). Each carries what an SDO read of its object returns at the same moment.

struct TpdoRow {
  const char* name;
  uint16_t communication;  // 0x1816..0x1819
  uint16_t object;         // the fixed mapping (lines 557-560)
  const char* setup;       // gives the object a value that tells it apart from the others
  uint32_t value;          // the object's value after `setup`
};

// Digital speed control of a BLDC with encoders at a steady 1000 rpm, Id reference 0.5 A:
// Iq = 0.01 A per rev/s = 0.1667 A (raw 0x5555), Id = 0.5 A (0x00010000).
constexpr const char* kRunning = R"(
  rx 601 [8] 22 15 30 00 01 00 00 00
  tx 581 [8] 60 15 30 00 00 00 00 00
  rx 601 [8] 22 16 30 00 00 00 00 00
  tx 581 [8] 60 16 30 00 00 00 00 00
  rx 601 [8] 22 13 30 00 01 00 00 00
  tx 581 [8] 60 13 30 00 00 00 00 00
  rx 601 [8] 22 02 30 00 01 00 00 00
  tx 581 [8] 60 02 30 00 00 00 00 00
  rx 601 [8] 22 1A 30 00 00 00 01 00
  tx 581 [8] 60 1A 30 00 00 00 00 00
  rx 601 [8] 22 05 30 00 E8 03 00 00
  tx 581 [8] 60 05 30 00 00 00 00 00
  wait 500
)";

// The host overwrites 0x3020 with bit 2 (over-temperature): one EMCY, 0x1001 = generic +
// temperature (errata S6).
constexpr const char* kOverTemperature = R"(
  rx 601 [8] 22 20 30 00 04 00 00 00
  tx 581 [8] 60 20 30 00 00 00 00 00
  tx 081 [8] 00 00 00 09 00 00 00 00
  wait 20
)";

// At rest the board stays at the ambient 25 °C (raw 0x00320000).
constexpr const char* kAtRest = "wait 20";

const TpdoRow kTpdos[] = {
    {"Tpdo3Iq", 0x1816, 0x3034, kRunning, 0x00005555},
    {"Tpdo4Id", 0x1817, 0x3035, kRunning, 0x00010000},
    {"Tpdo5ErrorRegister", 0x1818, 0x3020, kOverTemperature, 0x00000004},
    {"Tpdo6BoardTemperature", 0x1819, 0x3039, kAtRest, 0x00320000},
};

class SoloTpdoMapping : public SoloPdo, public ::testing::WithParamInterface<TpdoRow> {};

TEST_P(SoloTpdoMapping, SyncAndRemoteFrameSendTheMappedObject) {
  const TpdoRow& row = GetParam();
  const uint32_t id = 0x290U + (row.communication - 0x1814U);
  const std::string canId = hex(id);
  EXPECT_TRANSCRIPT(download(row.communication, 1, 0xC0000000U | id) +
                    download(row.communication, 2, 0) + "rx 000 [2] 01 01\n" + row.setup);
  const std::string bytes = readBySdo(row.object);
  EXPECT_EQ(bytes, wireBytes(row.value));
  EXPECT_TRANSCRIPT("rx 080 [0]\ntx " + canId + " [4] " + bytes + "\nsilence\nrx " + canId +
                    " [0] RTR\ntx " + canId + " [4] " + bytes + "\nsilence\n");
}

INSTANTIATE_TEST_SUITE_P(EveryTpdo, SoloTpdoMapping, ::testing::ValuesIn(kTpdos),
                         [](const ::testing::TestParamInfo<TpdoRow>& param) {
                           return std::string(param.param.name);
                         });

// ---------------------------------------------------------------------------------------------
// Triggering rules.

TEST_F(SoloPdo, TpdoWithoutBit30RefusesRemoteFramesButFollowsSync) {
  // Line 584: bit 30 = 0, "RTR is not allowed on this PDO".
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 19 18 01 91 02 00 80   # TPDO6 on 0x291, enabled, no RTR
    tx 581 [8] 60 19 18 01 00 00 00 00
    rx 000 [2] 01 01
    wait 20
    rx 291 [0] RTR
    silence
    rx 291 [4] RTR
    silence
    rx 080 [0]
    tx 291 [4] 00 00 32 00               # 25 degrees C
    silence
  )");
}

TEST_F(SoloPdo, RemoteFrameIsAnsweredAtOnceForASyncCountingTpdo) {
  // Line 600: types 0x01-0xF0 send at every n-th SYNC "or immediately after receiving RTR
  // request"; the SYNC count goes on.
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 19 18 01 91 02 00 C0   # TPDO6 on 0x291, RTR allowed
    tx 581 [8] 60 19 18 01 00 00 00 00
    rx 601 [8] 22 19 18 02 03 00 00 00   # every 3rd SYNC
    tx 581 [8] 60 19 18 02 00 00 00 00
    rx 601 [8] 22 18 18 01 90 02 00 C0   # TPDO5 on 0x290, RTR allowed
    tx 581 [8] 60 18 18 01 00 00 00 00
    rx 601 [8] 22 18 18 02 F0 00 00 00   # every 240th SYNC
    tx 581 [8] 60 18 18 02 00 00 00 00
    rx 000 [2] 01 01
    wait 20
    rx 080 [0]                           # SYNC 1
    silence
    rx 291 [0] RTR
    tx 291 [4] 00 00 32 00               # 25 degrees C, at once
    rx 290 [0] RTR
    tx 290 [4] 00 00 00 00               # no error
    silence
    rx 080 [0]                           # SYNC 2
    silence
    rx 080 [0]                           # SYNC 3
    tx 291 [4] 00 00 32 00
    silence
  )");
}

// Line 605: types 0x00-0xF0 hold the received data until the next SYNC.
class SoloRpdoSyncType : public SoloPdo, public ::testing::WithParamInterface<uint32_t> {};

TEST_P(SoloRpdoSyncType, HeldUntilTheNextSync) {
  EXPECT_TRANSCRIPT(download(0x1415, 1, 0x80000202U) + download(0x1415, 2, GetParam()) + R"(
    rx 000 [2] 01 01
    rx 202 [4] D0 07 00 00               # speed reference 2000 rpm
    rx 601 [8] 40 05 30 00 00 00 00 00
    tx 581 [8] 42 05 30 00 00 00 00 00   # held
    rx 080 [0]
    silence
    rx 601 [8] 40 05 30 00 00 00 00 00
    tx 581 [8] 42 05 30 00 D0 07 00 00   # applied at the first SYNC
    rx 202 [4] E8 03 00 00               # 1000 rpm
    rx 080 [0]
    rx 601 [8] 40 05 30 00 00 00 00 00
    tx 581 [8] 42 05 30 00 E8 03 00 00
  )");
}

INSTANTIATE_TEST_SUITE_P(Types, SoloRpdoSyncType, ::testing::Values(0x01U, 0x78U, 0xF0U),
                         [](const ::testing::TestParamInfo<uint32_t>& param) {
                           return "Type" + hex(param.param);
                         });

TEST_F(SoloPdo, RpdoTypeFEIsAppliedImmediately) {
  // Line 606: 0xFE-0xFF, "applied immediately".
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 15 14 01 02 02 00 80   # RPDO2 on 0x202
    tx 581 [8] 60 15 14 01 00 00 00 00
    rx 601 [8] 22 15 14 02 FE 00 00 00
    tx 581 [8] 60 15 14 02 00 00 00 00
    rx 000 [2] 01 01
    rx 202 [4] D0 07 00 00
    silence
    rx 601 [8] 40 05 30 00 00 00 00 00
    tx 581 [8] 42 05 30 00 D0 07 00 00
  )");
}

}  // namespace
}  // namespace costa::test
