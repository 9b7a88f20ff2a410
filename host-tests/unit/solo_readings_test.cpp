// The SOLO's measurement objects read by SDO from the simulated drive (manual lines 1296-1410):
// phase voltages and currents, bus voltage, DC motor current and voltage, the per-unit angle,
// the hardware version; and how motor type 0x3015 and feedback mode 0x3013 change them
// (docs/errata-solo.md S14).
#include <math.h>
#include <stdio.h>

#include "device_fixture.hpp"
#include "sfxt.hpp"

namespace costa::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

class SoloReadings : public DeviceTest {
 protected:
  SoloReadings() : DeviceTest("solo", 1) {}
  void SetUp() override { ASSERT_EQ(play("tx 701 [1] 00"), ""); }

  /// The value of `index` read by SDO (the SOLO's 0x42 response with four bytes, errata P1).
  uint32_t read(uint16_t index) { return uploadFourBytes(index, 0, 0x42); }
  double readSfxt(uint16_t index) { return solo::sfxtToDouble(static_cast<int32_t>(read(index))); }
  int32_t readInt(uint16_t index) { return static_cast<int32_t>(read(index)); }

  /// Digital speed control at `rpm` of motor type `motor` with feedback `feedback`.
  void run(uint8_t motor, uint8_t feedback, uint16_t rpm) {
    char text[512];
    snprintf(text, sizeof text, R"(
      rx 601 [8] 22 15 30 00 %02X 00 00 00
      tx 581 [8] 60 15 30 00 00 00 00 00
      rx 601 [8] 22 16 30 00 00 00 00 00
      tx 581 [8] 60 16 30 00 00 00 00 00
      rx 601 [8] 22 13 30 00 %02X 00 00 00
      tx 581 [8] 60 13 30 00 00 00 00 00
      rx 601 [8] 22 02 30 00 01 00 00 00
      tx 581 [8] 60 02 30 00 00 00 00 00
      rx 601 [8] 22 05 30 00 %02X %02X 00 00
      tx 581 [8] 60 05 30 00 00 00 00 00
      wait 500
    )",
             motor, feedback, rpm & 0xFFU, rpm >> 8);
    ASSERT_EQ(play(text), "");
    ASSERT_EQ(readInt(0x3036), rpm);  // steady
  }
};

TEST_F(SoloReadings, AtRestOnlyTheBusVoltageAndTheTemperatureAreNonZero) {
  EXPECT_TRANSCRIPT(R"(
    wait 20
    rx 601 [8] 40 38 30 00 00 00 00 00   # angle
    tx 581 [8] 42 38 30 00 00 00 00 00
    rx 601 [8] 40 2D 30 00 00 00 00 00   # phase-A voltage
    tx 581 [8] 42 2D 30 00 00 00 00 00
    rx 601 [8] 40 2E 30 00 00 00 00 00   # phase-B voltage
    tx 581 [8] 42 2E 30 00 00 00 00 00
    rx 601 [8] 40 2F 30 00 00 00 00 00   # phase-A current
    tx 581 [8] 42 2F 30 00 00 00 00 00
    rx 601 [8] 40 30 30 00 00 00 00 00   # phase-B current
    tx 581 [8] 42 30 30 00 00 00 00 00
    rx 601 [8] 40 31 30 00 00 00 00 00   # bus voltage 24 V
    tx 581 [8] 42 31 30 00 00 00 30 00
    rx 601 [8] 40 32 30 00 00 00 00 00   # DC motor current
    tx 581 [8] 42 32 30 00 00 00 00 00
    rx 601 [8] 40 33 30 00 00 00 00 00   # DC motor voltage
    tx 581 [8] 42 33 30 00 00 00 00 00
    rx 601 [8] 40 39 30 00 00 00 00 00   # board temperature 25 degrees C
    tx 581 [8] 42 39 30 00 00 00 32 00
  )");
}

TEST_F(SoloReadings, HardwareVersionIsReadOnlyAndZeroWithoutABoard) {
  // D15, S14: the simulated SOLO has no board revision to report.
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 3B 30 00 00 00 00 00
    tx 581 [8] 42 3B 30 00 00 00 00 00
    rx 601 [8] 22 3B 30 00 01 00 00 00
    tx 581 [8] 80 3B 30 00 02 00 01 06
  )");
}

TEST_F(SoloReadings, ThreePhaseReadingsFollowTheAngleOfARunningBldc) {
  run(1, 1, 1000);  // BLDC-PMSM, encoder
  // Iq = 0.01 A per rev/s at a steady speed; back-EMF = 24 V at 30000 rpm.
  const double current = 1000.0 / 6000.0;
  const double emf = 24.0 * 1000.0 / 30000.0;
  double previousAngle = 10.0;
  for (int sample = 0; sample < 8; ++sample) {
    SCOPED_TRACE(sample);
    const double angle = readSfxt(0x3038);
    EXPECT_GE(angle, -1.0);  // per unit of pi: [-1, 1) within the manual's [-2, 2]
    EXPECT_LT(angle, 1.0);
    EXPECT_NE(angle, previousAngle);  // 66.7 electrical turns per second
    previousAngle = angle;
    const double theta = kPi * angle;
    EXPECT_NEAR(readSfxt(0x3034), current, 1e-4);
    EXPECT_NEAR(readSfxt(0x302F), current * sin(theta), 1e-3);
    EXPECT_NEAR(readSfxt(0x3030), current * sin(theta - 2.0 * kPi / 3.0), 1e-3);
    EXPECT_NEAR(readSfxt(0x302D), emf * cos(theta), 1e-3);
    EXPECT_NEAR(readSfxt(0x302E), emf * cos(theta - 2.0 * kPi / 3.0), 1e-3);
    EXPECT_NEAR(readSfxt(0x3031), 24.0, 0.01);
    EXPECT_EQ(read(0x3032), 0U);  // not a DC brushed motor
    EXPECT_EQ(read(0x3033), 0U);
    ASSERT_EQ(play("wait 13"), "");  // at least one 10 ms step of the drive
  }
}

TEST_F(SoloReadings, DcMotorCurrentAndVoltageOnlyForADcBrushedMotor) {
  run(0, 1, 1000);  // DC brushed (the default motor type)
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 32 30 00 00 00 00 00
    tx 581 [8] 42 32 30 00 55 55 00 00   # 0.1667 A: the torque current
    rx 601 [8] 40 33 30 00 00 00 00 00
    tx 581 [8] 42 33 30 00 9A 99 01 00   # 0.8 V: 24 V x 1000 / 30000 rpm
    rx 601 [8] 22 15 30 00 01 00 00 00   # BLDC-PMSM
    tx 581 [8] 60 15 30 00 00 00 00 00
    wait 10
    rx 601 [8] 40 32 30 00 00 00 00 00
    tx 581 [8] 42 32 30 00 00 00 00 00
    rx 601 [8] 40 33 30 00 00 00 00 00
    tx 581 [8] 42 33 30 00 00 00 00 00
  )");
}

TEST_F(SoloReadings, HallSensorsCountThreeTimesThePolesPerRevolution) {
  // Line 1381: "Hall sensor counted pulses in 1 revolution = Motor's number of poles x 3".
  run(1, 2, 1000);  // Hall sensors, 8 poles (default): 24 counts per revolution
  int32_t before = readInt(0x3037);
  ASSERT_EQ(play("wait 600"), "");  // 10 revolutions
  EXPECT_NEAR(readInt(0x3037) - before, 240, 1);
  ASSERT_EQ(play(R"(
    rx 601 [8] 22 0F 30 00 04 00 00 00   # 4 poles: 12 counts per revolution
    tx 581 [8] 60 0F 30 00 00 00 00 00
  )"),
            "");
  before = readInt(0x3037);
  ASSERT_EQ(play("wait 600"), "");
  EXPECT_NEAR(readInt(0x3037) - before, 120, 1);
  ASSERT_EQ(play(R"(
    rx 601 [8] 22 13 30 00 01 00 00 00   # encoder: 4 x 1000 lines per revolution
    tx 581 [8] 60 13 30 00 00 00 00 00
  )"),
            "");
  before = readInt(0x3037);
  ASSERT_EQ(play("wait 600"), "");
  EXPECT_NEAR(readInt(0x3037) - before, 40000, 1);
}

}  // namespace
}  // namespace costa::test
