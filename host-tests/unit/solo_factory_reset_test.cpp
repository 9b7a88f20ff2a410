// 0x3014 Reset Factory (manual lines 1048-1053, errata D11, M2): the SOLO keeps its M objects
// in EEPROM across power cycles (M1); 0x3014 = 0x00000001 brings back every default "after a
// power recycle". Each power cycle is a new SOLO over the same parameter memory.
#include <memory>
#include <string>

#include "costa/port/memory/memory_storage.hpp"
#include "device_fixture.hpp"
#include "solo_od.hpp"
#include "solo_target.hpp"

namespace costa::test {
namespace {

class SoloFactoryReset : public ::testing::Test {
 protected:
  /// Powers a SOLO (node 1) on over `eeprom_` and plays `text` against it.
  std::string powerUpAndPlay(const std::string& text) {
    InProcessBus bus([this](CanTransmitter& can) -> std::unique_ptr<host::DeviceTarget> {
      return std::make_unique<host::HostedTarget<solo::SoloTarget>>(
          nullptr, can, DeviceConfig{0, false, &eeprom_, nullptr});
    });
    return playText("tx 701 [1] 00\n" + text, bus);
  }

  port::MemoryStorageOf<solo::SoloTarget::kStorageBytes> eeprom_;
};

// The M objects written here, and their values as written.
constexpr const char* kWritten = R"(
  rx 601 [8] 40 11 30 00 00 00 00 00
  tx 581 [8] 42 11 30 00 F4 01 00 00   # speed limit 500 rpm
  rx 601 [8] 40 0F 30 00 00 00 00 00
  tx 581 [8] 42 0F 30 00 04 00 00 00   # 4 poles
  rx 601 [8] 40 13 30 00 00 00 00 00
  tx 581 [8] 42 13 30 00 02 00 00 00   # Hall sensors
  rx 601 [8] 40 16 30 00 00 00 00 00
  tx 581 [8] 42 16 30 00 02 00 00 00   # position mode
  rx 601 [8] 40 15 18 01 00 00 00 00
  tx 581 [8] 42 15 18 01 85 02 00 C0   # TPDO2 on 0x285, enabled, RTR allowed
)";

// The same objects at their defaults (lines 1015, 1029, 1040, 1075, 783).
constexpr const char* kDefaults = R"(
  rx 601 [8] 40 11 30 00 00 00 00 00
  tx 581 [8] 42 11 30 00 30 75 00 00   # 30000 rpm
  rx 601 [8] 40 0F 30 00 00 00 00 00
  tx 581 [8] 42 0F 30 00 08 00 00 00   # 8 poles
  rx 601 [8] 40 13 30 00 00 00 00 00
  tx 581 [8] 42 13 30 00 00 00 00 00   # sensorless
  rx 601 [8] 40 16 30 00 00 00 00 00
  tx 581 [8] 42 16 30 00 01 00 00 00   # torque mode (line 1075)
  rx 601 [8] 40 15 18 01 00 00 00 00
  tx 581 [8] 42 15 18 01 00 00 00 00   # disabled
)";

TEST_F(SoloFactoryReset, DefaultsReturnAtTheNextPowerUp) {
  ASSERT_EQ(powerUpAndPlay(R"(
    rx 601 [8] 23 11 30 00 F4 01 00 00
    tx 581 [8] 60 11 30 00 00 00 00 00
    rx 601 [8] 23 0F 30 00 04 00 00 00
    tx 581 [8] 60 0F 30 00 00 00 00 00
    rx 601 [8] 23 13 30 00 02 00 00 00
    tx 581 [8] 60 13 30 00 00 00 00 00
    rx 601 [8] 23 16 30 00 02 00 00 00
    tx 581 [8] 60 16 30 00 00 00 00 00
    rx 601 [8] 23 15 18 01 85 02 00 C0
    tx 581 [8] 60 15 18 01 00 00 00 00
  )"),
            "");
  // Kept across a power cycle (M1).
  ASSERT_EQ(powerUpAndPlay(std::string(kWritten) + R"(
    rx 601 [8] 23 14 30 00 01 00 00 00   # line 1053: reset factory, data 0x00000001
    tx 581 [8] 60 14 30 00 00 00 00 00
  )" + kWritten),  // still in force until the power recycle
            "");
  EXPECT_EQ(powerUpAndPlay(std::string(kDefaults) + R"(
    rx 601 [8] 40 14 30 00 00 00 00 00
    tx 581 [8] 42 14 30 00 00 00 00 00   # 0x3014 is V: 0 again
    rx 601 [8] 23 11 30 00 58 02 00 00   # parameters are kept again from here on
    tx 581 [8] 60 11 30 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(powerUpAndPlay(R"(
    rx 601 [8] 40 11 30 00 00 00 00 00
    tx 581 [8] 42 11 30 00 58 02 00 00   # 600 rpm
    rx 601 [8] 40 0F 30 00 00 00 00 00
    tx 581 [8] 42 0F 30 00 08 00 00 00
  )"),
            "");
}

TEST_F(SoloFactoryReset, ZeroDoesNothing) {
  // D11: 0 is accepted and does nothing.
  ASSERT_EQ(powerUpAndPlay(R"(
    rx 601 [8] 23 11 30 00 F4 01 00 00
    tx 581 [8] 60 11 30 00 00 00 00 00
    rx 601 [8] 23 14 30 00 00 00 00 00
    tx 581 [8] 60 14 30 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(powerUpAndPlay(R"(
    rx 601 [8] 40 11 30 00 00 00 00 00
    tx 581 [8] 42 11 30 00 F4 01 00 00
  )"),
            "");
}

TEST_F(SoloFactoryReset, AParameterMemoryThatFailsAnswers08000020) {
  ASSERT_EQ(powerUpAndPlay(R"(
    rx 601 [8] 23 11 30 00 F4 01 00 00   # 500 rpm, kept
    tx 581 [8] 60 11 30 00 00 00 00 00
  )"),
            "");
  eeprom_.cutPowerAfter(0);  // from now on nothing reaches the EEPROM
  EXPECT_EQ(powerUpAndPlay(R"(
    rx 601 [8] 23 11 30 00 58 02 00 00   # 600 rpm: in force, but not kept
    tx 581 [8] 80 11 30 00 20 00 00 08
    rx 601 [8] 40 11 30 00 00 00 00 00
    tx 581 [8] 42 11 30 00 58 02 00 00
    rx 601 [8] 23 14 30 00 01 00 00 00   # reset factory: the stored parameters stay
    tx 581 [8] 80 14 30 00 20 00 00 08
  )"),
            "");
  eeprom_.restorePower();
  EXPECT_EQ(powerUpAndPlay(R"(
    rx 601 [8] 40 11 30 00 00 00 00 00
    tx 581 [8] 42 11 30 00 F4 01 00 00   # what was kept before the failure
  )"),
            "");
}

}  // namespace
}  // namespace costa::test
