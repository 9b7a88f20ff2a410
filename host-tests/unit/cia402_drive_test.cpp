// The CiA 402 drive profile (stack/cia402/drive.hpp) as CiA 402 defines it (DriveOptions{}),
// through frames: a master writes the control word by SDO and by RPDO, reads the status word,
// switches modes, quick-stops, resets a fault and homes; the scripted axis (drive_bus.hpp) moves
// when the test says. Node-id 1; TPDO1 (status word, mode display) follows the status word.
#include "drive_bus.hpp"

namespace costa::test {
namespace {

using cia402::Motion;
using cia402::PowerState;

class DriveTest : public ::testing::Test {
 protected:
  explicit DriveTest(const cia402::DriveOptions& options = cia402::DriveOptions{})
      : bus_(options) {}
  void SetUp() override { ASSERT_EQ(play("tx 701 [1] 00"), ""); }

  std::string play(const std::string& text) { return playText(text, bus_); }
  uint64_t value(uint16_t index, uint8_t subIndex) {
    return bus_.node().dictionary().readUnsigned(index, subIndex, 0xDEADBEEFU);
  }

  /// The standard way up: operational, then 0x06, 0x07, 0x0F with the status word read back.
  std::string enable() {
    return play(R"(
      rx 000 [2] 01 01
      rx 601 [8] 2B 40 60 00 06 00 00 00   # shutdown: transition 2
      tx 581 [8] 60 40 60 00 00 00 00 00
      tx 181 [3] 31 04 00                  # ready to switch on (TPDO1 follows the status word)
      rx 601 [8] 2B 40 60 00 07 00 00 00   # switch on: 3
      tx 581 [8] 60 40 60 00 00 00 00 00
      tx 181 [3] 33 04 00
      rx 601 [8] 2B 40 60 00 0F 00 00 00   # enable operation: 4
      tx 581 [8] 60 40 60 00 00 00 00 00
      tx 181 [3] 37 04 00
    )");
  }

  /// Homing mode (6), then a rising bit 4 starts homing.
  std::string startHoming() {
    return play(R"(
      rx 601 [8] 2F 60 60 00 06 00 00 00
      tx 581 [8] 60 60 60 00 00 00 00 00
      tx 181 [3] 37 04 06                  # homing not started: 10 set
      rx 601 [8] 2B 40 60 00 1F 00 00 00   # homing operation start
      tx 581 [8] 60 40 60 00 00 00 00 00
      tx 181 [3] 37 00 06                  # in progress
    )");
  }

  DriveBus bus_;
};

TEST_F(DriveTest, PowerOnIsSwitchOnDisabled) {
  EXPECT_EQ(bus_.drive().state(), PowerState::kSwitchOnDisabled);
  EXPECT_EQ(play(R"(
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 40 04 00 00   # switch on disabled, at rest
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kFree);
}

TEST_F(DriveTest, ShutdownSwitchOnEnableAndBackDown) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(bus_.drive().state(), PowerState::kOperationEnabled);
  EXPECT_EQ(bus_.axis().last.motion, Motion::kStop);  // no mode: the axis holds
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 07 00 00 00   # disable operation: 5
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 33 04 00
    rx 601 [8] 2B 40 60 00 06 00 00 00   # shutdown: 6
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 31 04 00
    rx 601 [8] 2B 40 60 00 00 00 00 00   # disable voltage: 7
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 40 04 00
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kFree);
}

TEST_F(DriveTest, EnableFromSwitchOnDisabledIsNotCia402) {
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 40 04 00 00   # still switch on disabled
  )"),
            "");
}

TEST_F(DriveTest, ModesSwitchAndShowInTheDisplay) {
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 60 60 00 03 00 00 00   # profile velocity
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 40 61 60 00 00 00 00 00
    tx 581 [8] 4F 61 60 00 03 00 00 00
    rx 601 [8] 2F 60 60 00 02 00 00 00   # velocity mode: not in 0x6502
    tx 581 [8] 80 60 60 00 30 00 09 06
    rx 601 [8] 2F 60 60 00 FF 00 00 00   # -1: not in 0x6502 either
    tx 581 [8] 80 60 60 00 30 00 09 06
    rx 601 [8] 40 61 60 00 00 00 00 00
    tx 581 [8] 4F 61 60 00 03 00 00 00   # unchanged
    rx 601 [8] 2F 60 60 00 00 00 00 00   # 0: no mode change
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 40 61 60 00 00 00 00 00
    tx 581 [8] 4F 61 60 00 03 00 00 00
  )"),
            "");
  EXPECT_EQ(bus_.drive().mode(), cia402::kProfileVelocity);
}

TEST_F(DriveTest, ProfilePositionBySdo) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 60 60 00 01 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 04 01
    rx 601 [8] 23 7A 60 00 E8 03 00 00   # target 1000: nothing yet
    tx 581 [8] 60 7A 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # new set-point (bit 4 rising)
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 10 01                  # acknowledged (12), moving (10 clear)
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 01
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kPosition);
  EXPECT_EQ(bus_.axis().last.position, 1000);
  EXPECT_EQ(bus_.axis().last.velocity, 500);        // 0x6081
  EXPECT_EQ(bus_.axis().last.acceleration, 1000U);  // 0x6083
  EXPECT_EQ(bus_.axis().last.deceleration, 2000U);  // 0x6084
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play(R"(
    tx 181 [3] 37 04 01                  # target reached
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 E8 03 00 00
  )"),
            "");
}

TEST_F(DriveTest, ASetPointDuringAMoveWaitsForTheMoveToEnd) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 60 60 00 01 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 04 01
    rx 601 [8] 23 7A 60 00 E8 03 00 00   # target 1000
    tx 581 [8] 60 7A 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # new set-point, bit 5 clear
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 10 01
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 01
    rx 601 [8] 23 7A 60 00 D0 07 00 00   # target 2000 while the axis moves to 1000
    tx 581 [8] 60 7A 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # new set-point, bit 5 clear: it waits
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 10 01                  # acknowledged all the same
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 01
    rx 601 [8] 23 7A 60 00 B8 0B 00 00   # target 3000
    tx 581 [8] 60 7A 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # one waits at a time: 3000 replaces 2000
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 10 01
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 01
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.position, 1000);  // the first move goes on
  bus_.axis().arrive();
  bus_.axisMoved();
  // At 1000 the waiting set-point starts at once: bit 10 stays clear, no TPDO.
  EXPECT_EQ(play(""), "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kPosition);
  EXPECT_EQ(bus_.axis().last.position, 3000);
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play("tx 181 [3] 37 04 01"), "");  // target reached
}

TEST_F(DriveTest, RelativeSetPointsAddToThePreviousOne) {
  ASSERT_EQ(enable(), "");
  bus_.axis().current.position = 100;
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 60 60 00 01 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 04 01
    rx 601 [8] 23 7A 60 00 32 00 00 00   # 50
    tx 581 [8] 60 7A 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 7F 00 00 00   # relative (6), at once (5), new set-point (4)
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 10 01
    rx 601 [8] 2B 40 60 00 6F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 01
    rx 601 [8] 2B 40 60 00 7F 00 00 00   # again: relative to the previous set-point
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 10 01
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.position, 200);  // 100 + 50 + 50
}

TEST_F(DriveTest, AnRpdoWithControlWordAndTargetIsTakenAsOne) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 60 60 00 01 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 04 01
    rx 201 [6] 1F 00 D0 07 00 00         # RPDO1: new set-point and target 2000 together
    tx 181 [3] 37 10 01
    rx 201 [6] 0F 00 D0 07 00 00
    tx 181 [3] 37 00 01
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.position, 2000);  // the target of the same RPDO
}

TEST_F(DriveTest, ProfileVelocityAndHalt) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 23 FF 60 00 64 00 00 00   # 100
    tx 581 [8] 60 FF 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 03 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 10 03                  # 12: speed 0; 10: not at the target velocity
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kVelocity);
  EXPECT_EQ(bus_.axis().last.velocity, 100);
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play(R"(
    tx 181 [3] 37 04 03                  # velocity reached, not 0
    rx 601 [8] 2B 40 60 00 0F 01 00 00   # halt
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 03
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kStop);
  EXPECT_EQ(bus_.axis().last.deceleration, 2000U);  // CiA 402: the profile deceleration
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play(R"(
    tx 181 [3] 37 14 03                  # halted: at rest is reached
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # the halt ends: the velocity comes back
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 10 03
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kVelocity);
}

TEST_F(DriveTest, QuickStopThenSwitchOnDisabled) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 23 FF 60 00 64 00 00 00
    tx 581 [8] 60 FF 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 03 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 10 03
  )"),
            "");
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play(R"(
    tx 181 [3] 37 04 03
    rx 601 [8] 2B 40 60 00 0B 00 00 00   # quick stop: 11
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 17 00 03                  # quick stop active, decelerating
  )"),
            "");
  EXPECT_EQ(bus_.drive().state(), PowerState::kQuickStopActive);
  EXPECT_EQ(bus_.axis().last.motion, Motion::kStop);
  EXPECT_EQ(bus_.axis().last.deceleration, 4000U);  // 0x6085
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play("tx 181 [3] 40 14 03"), "");  // stopped: 12 to switch on disabled (option 2)
  EXPECT_EQ(bus_.drive().state(), PowerState::kSwitchOnDisabled);
}

TEST_F(DriveTest, FaultReactionFaultAndFaultReset) {
  ASSERT_EQ(enable(), "");
  bus_.axis().current.fault = true;
  bus_.axis().current.atRest = false;
  bus_.axisMoved();
  EXPECT_EQ(play("tx 181 [3] 1F 00 00"), "");  // 13: fault reaction active, stopping
  EXPECT_EQ(bus_.axis().last.motion, Motion::kStop);
  EXPECT_EQ(bus_.axis().last.deceleration, 4000U);
  bus_.axis().current.atRest = true;
  bus_.axisMoved();
  EXPECT_EQ(play(R"(
    tx 181 [3] 08 04 00                  # 14: fault
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # no command leaves fault
    tx 581 [8] 60 40 60 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kFree);
  bus_.axis().faultStays = true;
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 80 00 00 00   # fault reset while the fault stays: still fault
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 00 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(bus_.drive().state(), PowerState::kFault);
  bus_.axis().faultStays = false;
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 80 00 00 00   # fault reset (bit 7 rising): 15
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 40 04 00
    rx 601 [8] 2B 40 60 00 86 00 00 00   # bit 7 held is no new reset; shutdown: 2
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 31 04 00
  )"),
            "");
}

TEST_F(DriveTest, HomingStartAndAttained) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(startHoming(), "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kHoming);
  EXPECT_EQ(bus_.axis().last.homingMethod, 35);  // 0x6098
  bus_.axis().current.homing = cia402::HomingState::kAttained;
  bus_.axis().current.position = 0;
  bus_.axis().current.atRest = true;
  bus_.axisMoved();
  EXPECT_EQ(play("tx 181 [3] 37 14 06"), "");  // attained (12) and reached (10)
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # again: the new run fails
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 06
  )"),
            "");
  bus_.axis().current.homing = cia402::HomingState::kError;
  bus_.axis().current.atRest = true;
  bus_.axisMoved();
  EXPECT_EQ(play("tx 181 [3] 37 24 06"), "");  // homing error (13), at rest
}

TEST_F(DriveTest, AHaltInterruptsHoming) {
  ASSERT_EQ(enable(), "");
  ASSERT_EQ(startHoming(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 1F 01 00 00   # halt (8)
    tx 581 [8] 60 40 60 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kStop);
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play(R"(
    tx 181 [3] 37 04 06                  # interrupted: 13 and 12 clear, 10 set
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # the halt ends; bit 4 held is no new start
    tx 581 [8] 60 40 60 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kStop);
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # a new start
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 00 06
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kHoming);
}

TEST_F(DriveTest, HomingGoesOnWhenBit4Falls) {
  ASSERT_EQ(enable(), "");
  ASSERT_EQ(startHoming(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # bit 4 falls: homing goes on, the status stays
    tx 581 [8] 60 40 60 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kHoming);
  bus_.axis().current.homing = cia402::HomingState::kAttained;
  bus_.axis().current.atRest = true;
  bus_.axisMoved();
  EXPECT_EQ(play("tx 181 [3] 37 14 06"), "");  // attained (12) and reached (10)
}

TEST_F(DriveTest, InterpolatedPositionAtEachSync) {
  ASSERT_EQ(enable(), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 60 60 00 07 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 04 07
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # enable ip mode
    tx 581 [8] 60 40 60 00 00 00 00 00
    tx 181 [3] 37 14 07                  # ip mode active (12)
    rx 301 [4] 10 27 00 00               # RPDO2: set-point 10000, held for the SYNC
    silence
    rx 080 [0]
    tx 181 [3] 37 10 07                  # moving to it
  )"),
            "");
  EXPECT_EQ(bus_.axis().last.motion, Motion::kInterpolate);
  EXPECT_EQ(bus_.axis().last.position, 10000);
  EXPECT_EQ(bus_.axis().last.period, 2000U);  // 0x60C2: 2 x 10^-3 s
  bus_.axis().arrive();
  bus_.axisMoved();
  EXPECT_EQ(play("tx 181 [3] 37 14 07"), "");
}

TEST_F(DriveTest, WithoutEnableIpTheSyncTakesNothing) {
  ASSERT_EQ(enable(), "");
  const int before = bus_.axis().commands;
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 60 60 00 07 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    tx 181 [3] 37 04 07
    rx 301 [4] 10 27 00 00
    rx 080 [0]
    silence
  )"),
            "");
  EXPECT_EQ(bus_.axis().commands, before);
  EXPECT_EQ(bus_.axis().last.motion, Motion::kStop);
}

}  // namespace
}  // namespace costa::test
