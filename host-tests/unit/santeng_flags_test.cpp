// Santeng emergency stop, stop, faults and flags (errata B5-B10, D1) and the controller's own
// readings (B11, B12, D18, D19), on a virtual clock.
#include "santeng_fixture.hpp"

namespace costa::test {
namespace {

using SantengFlags = SantengTest;

TEST_F(SantengFlags, AtRestOnlyTheSerialModeFlagIsSet) {
  EXPECT_EQ(read8(0x2111, 0), 0x01);  // FS f1: commands through the serial/CAN interpreter
  EXPECT_EQ(read8(0x2112, 0), 0x00);
  EXPECT_EQ(read8(0x2121, 1), 0x00);
  EXPECT_EQ(read8(0x2121, 2), 0x00);
}

TEST_F(SantengFlags, EmergencyStopLatchesUntilReleased) {  // lines 497-511
  write(0x2006, 1, 0);
  write(0x2000, 1, 1000);
  wait(10);
  write(0x200C, 0, 0);                // EX: any value
  EXPECT_EQ(read8(0x2112, 0), 0x10);  // FF f5
  EXPECT_EQ(read8(0x2111, 0), 0x09);  // FS f4: power stage off
  wait(500);
  EXPECT_EQ(read16(0x2103, 1), 500);  // coasting down at 1000 RPM/s
  EXPECT_EQ(read16(0x2101, 1), 0);    // nothing applied
  wait(1000);
  EXPECT_EQ(read16(0x2103, 1), 0);
  write(0x2000, 1, 800);  // a command is kept, not applied while the stop is latched
  wait(100);
  EXPECT_EQ(read16(0x2103, 1), 0);
  EXPECT_EQ(read8(0x2112, 0), 0x10);
  write(0x200D, 0, 0);  // MG
  EXPECT_EQ(read8(0x2112, 0), 0x00);
  EXPECT_EQ(read8(0x2111, 0), 0x01);
  wait(1);
  EXPECT_EQ(read16(0x2103, 1), 800);  // 0x2006 = 0: at once
}

TEST_F(SantengFlags, FaultsTurnThePowerStageOffWhileActive) {  // lines 776-778: FF = 2
  write(0x2006, 2, 0);
  write(0x2000, 2, -400);
  wait(1);
  ASSERT_EQ(sim("fault overvoltage on"), "");
  EXPECT_EQ(read8(0x2112, 0), 0x02);  // "Overvoltage" (line 778), "Overpressure" at 760 (B8)
  EXPECT_EQ(read8(0x2111, 0), 0x09);
  wait(400);
  EXPECT_EQ(read16(0x2103, 2), 0);
  ASSERT_EQ(sim("fault overheat on"), "");
  EXPECT_EQ(read8(0x2112, 0), 0x03);
  ASSERT_EQ(sim("fault overvoltage off"), "");
  ASSERT_EQ(sim("fault overheat off"), "");
  EXPECT_EQ(read8(0x2112, 0), 0x00);
  wait(1);
  EXPECT_EQ(read16(0x2103, 2), -400);  // the command applies again
}

TEST_F(SantengFlags, EveryFaultHasItsBit) {
  const struct {
    const char* name;
    uint8_t bit;
  } faults[] = {{"overheat", 0x01}, {"overvoltage", 0x02}, {"undervoltage", 0x04},
                {"short", 0x08},    {"sensor", 0x20},      {"mosfet", 0x40}};
  for (const auto& fault : faults) {
    ASSERT_EQ(sim(std::string("fault ") + fault.name + " on"), "");
    EXPECT_EQ(read8(0x2112, 0), fault.bit) << fault.name;
    ASSERT_EQ(sim(std::string("fault ") + fault.name + " off"), "");
  }
  EXPECT_EQ(read8(0x2112, 0), 0x00);
}

TEST_F(SantengFlags, BlockedMotorInClosedLoopStopsWithLoopError) {  // lines 814-816: FM = 6
  ASSERT_EQ(sim("set mode 1 speed"), "");
  ASSERT_EQ(sim("stall 1 on"), "");
  write(0x2000, 1, 500);
  wait(100);
  EXPECT_EQ(read8(0x2121, 1), 0x06);  // f2 motor stops, f3 loop error
  EXPECT_EQ(read8(0x2121, 2), 0x00);
  EXPECT_EQ(read8(0x2111, 0), 0x11);  // FS f5: stall detected
  EXPECT_EQ(read16(0x2103, 1), 0);
  EXPECT_EQ(read16(0x2100, 1), 10);  // stall current: 100 per mille applied, 1.0 A
  ASSERT_EQ(sim("stall 1 off"), "");
  EXPECT_EQ(read8(0x2121, 1), 0x00);
  wait(1);
  EXPECT_EQ(read16(0x2103, 1), 101);
}

TEST_F(SantengFlags, BlockedMotorInOpenLoopHasNoLoopError) {
  ASSERT_EQ(sim("stall 2 on"), "");
  EXPECT_EQ(read8(0x2121, 2), 0x00);  // not commanded: not stalled
  write(0x2000, 2, 200);
  wait(10);
  EXPECT_EQ(read8(0x2121, 2), 0x02);
}

TEST_F(SantengFlags, StopInAllModesStopsOneChannel) {  // lines 513-519, D1
  write(0x2006, 1, 0);
  write(0x2006, 2, 0);
  write(0x2000, 1, 500);
  write(0x2000, 2, 500);
  wait(1);
  write(0x200E, 2, 0);
  wait(1000);
  EXPECT_EQ(read16(0x2103, 1), 500);
  EXPECT_EQ(read16(0x2103, 2), 0);  // braked at 1000 RPM/s
  write(0x2000, 2, 300);            // the next command ends the stop
  wait(1);
  EXPECT_EQ(read16(0x2103, 2), 300);
}

TEST_F(SantengFlags, VoltagesAndTemperaturesAtRestAndUnderLoad) {  // line 660
  EXPECT_EQ(uploadFourBytes(0x210D, 1, 0x4B), 135U);
  EXPECT_EQ(uploadFourBytes(0x210D, 2, 0x4B), 246U);
  EXPECT_EQ(uploadFourBytes(0x210D, 3, 0x4B), 4730U);
  EXPECT_EQ(read8(0x210F, 1), 30);
  EXPECT_EQ(read8(0x210F, 2), 25);
  EXPECT_EQ(read8(0x210F, 3), 25);
  write(0x2006, 1, 0);
  write(0x2006, 2, 0);
  write(0x2000, 1, 1000);
  write(0x2000, 2, -1000);
  wait(10);
  EXPECT_EQ(read16(0x2100, 1), 20);  // 2.0 A at 1000 RPM
  EXPECT_EQ(read16(0x210C, 2), 20);  // full command: the battery current is the motor's
  EXPECT_EQ(uploadFourBytes(0x210D, 2, 0x4B), 244U);  // 4 A x 0.05 ohm = 0.2 V less
  EXPECT_EQ(read8(0x210F, 2), 26);                    // 0.5 degrees per ampere
}

TEST_F(SantengFlags, DigitalInputsOutputsAndTime) {
  ASSERT_EQ(sim("input 3 on"), "");
  ASSERT_EQ(sim("input 32 on"), "");
  EXPECT_EQ(uploadFourBytes(0x210E, 0, 0x43), 0x80000004U);
  ASSERT_EQ(sim("input 32 off"), "");
  EXPECT_EQ(uploadFourBytes(0x210E, 0, 0x43), 0x00000004U);
  ASSERT_EQ(sim("output 2 on"), "");
  EXPECT_EQ(read8(0x2113, 0), 0x02);
  wait(2500);
  EXPECT_EQ(uploadFourBytes(0x2119, 0, 0x43), 2U);  // whole seconds since power-on
  wait(500);
  EXPECT_EQ(uploadFourBytes(0x2119, 0, 0x43), 3U);
}

}  // namespace
}  // namespace costa::test
