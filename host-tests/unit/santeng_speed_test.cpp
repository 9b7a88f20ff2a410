// Santeng speed modes: 0x2000 in per mille of max RPM, ramped at 0x2006/0x2007 (0.1 RPM/s), with
// the manual's worked figures (lines 580-610, errata B1, B2) read back from 0x2103, 0x2101,
// 0x2107 on a virtual clock.
#include "santeng_fixture.hpp"

namespace costa::test {
namespace {

using SantengSpeed = SantengTest;

TEST_F(SantengSpeed, Ac2000RaisesTheSpeedBy200RpmPerSecond) {  // line 590
  write(0x2006, 1, 2000);
  write(0x2000, 1, 1000);
  wait(1000);
  EXPECT_EQ(read16(0x2103, 1), 200);
  wait(1000);
  EXPECT_EQ(read16(0x2103, 1), 400);
  EXPECT_EQ(read16(0x2101, 1), 400);  // the command applied: 400 per mille of 1000 RPM
  EXPECT_EQ(read16(0x2107, 1), 400);
  wait(3000);
  EXPECT_EQ(read16(0x2103, 1), 1000);  // full speed after 5 s
  wait(1000);
  EXPECT_EQ(read16(0x2103, 1), 1000);
}

TEST_F(SantengSpeed, Ac10000ReachesFullSpeedInOneSecond) {  // line 580, the default (B2)
  write(0x2000, 1, 1000);
  wait(500);
  EXPECT_EQ(read16(0x2103, 1), 500);
  wait(499);
  EXPECT_EQ(read16(0x2103, 1), 999);
  wait(1);
  EXPECT_EQ(read16(0x2103, 1), 1000);
}

TEST_F(SantengSpeed, Ac20000ReachesFullPowerInHalfASecond) {  // line 592
  write(0x2006, 1, 20000);
  write(0x2000, 1, 1000);
  wait(250);
  EXPECT_EQ(read16(0x2103, 1), 500);
  wait(250);
  EXPECT_EQ(read16(0x2103, 1), 1000);
}

TEST_F(SantengSpeed, Dc2000LowersTheSpeedBy200RpmPerSecond) {  // line 608
  write(0x2000, 1, 1000);
  wait(2000);
  write(0x2007, 1, 2000);
  write(0x2000, 1, 0);
  wait(1000);
  EXPECT_EQ(read16(0x2103, 1), 800);
  wait(4000);
  EXPECT_EQ(read16(0x2103, 1), 0);
}

TEST_F(SantengSpeed, Dc20000StopsChannel2InHalfASecond) {  // line 610
  write(0x2006, 2, 0);                                     // 0: at once
  write(0x2000, 2, 1000);
  wait(1);
  EXPECT_EQ(read16(0x2103, 2), 1000);
  write(0x2007, 2, 20000);
  write(0x2000, 2, 0);
  wait(250);
  EXPECT_EQ(read16(0x2103, 2), 500);
  wait(250);
  EXPECT_EQ(read16(0x2103, 2), 0);
  EXPECT_EQ(read16(0x2103, 1), 0);  // channel 1 was never commanded
}

TEST_F(SantengSpeed, ReversingBrakesAtTheDecelerationThenAccelerates) {
  write(0x2006, 1, 0);
  write(0x2000, 1, 500);
  wait(1);
  write(0x2006, 1, 10000);
  write(0x2007, 1, 5000);  // 500 RPM/s
  write(0x2000, 1, -500);
  wait(500);
  EXPECT_EQ(read16(0x2103, 1), 250);  // still braking
  wait(500);
  EXPECT_EQ(read16(0x2103, 1), 0);
  wait(250);
  EXPECT_EQ(read16(0x2103, 1), -250);  // now accelerating backwards at 1000 RPM/s
  wait(250);
  EXPECT_EQ(read16(0x2103, 1), -500);
}

TEST_F(SantengSpeed, CommandsArePerMilleOfTheChannelsMaxRpm) {
  ASSERT_EQ(sim("set max-rpm 2 3000"), "");
  write(0x2006, 2, 0);
  write(0x2000, 2, 500);
  wait(1);
  EXPECT_EQ(read16(0x2103, 2), 1500);
  EXPECT_EQ(read16(0x210A, 2), 1500);  // the hall sensors see the same motor
  EXPECT_EQ(read16(0x2107, 2), 500);
  EXPECT_EQ(read16(0x2101, 2), 500);
}

TEST_F(SantengSpeed, ClosedLoopSpeedFollowsTheSameRamp) {
  ASSERT_EQ(sim("set mode 1 speed"), "");
  write(0x2000, 1, -300);
  wait(300);
  EXPECT_EQ(read16(0x2103, 1), -300);
}

TEST_F(SantengSpeed, CountsAndCurrentsFollowTheMotor) {
  write(0x2006, 1, 0);
  write(0x2000, 1, 600);  // 600 RPM: 10 revolutions per second, 40000 counts, 240 hall counts
  wait(1000);
  EXPECT_EQ(read32(0x2104, 1), 40000);
  EXPECT_EQ(read32(0x2105, 1), 240);
  EXPECT_EQ(read16(0x2100, 1), 12);  // 600 / 50: 1.2 A
  EXPECT_EQ(read16(0x210C, 1), 7);   // 1.2 A x 0.6
  EXPECT_EQ(read16(0x2100, 2), 0);
  write(0x2007, 1, 0);
  write(0x2000, 1, -600);  // at once backwards: back where it started after a second
  wait(1000);
  EXPECT_EQ(read32(0x2104, 1), 0);
  EXPECT_EQ(read32(0x2105, 1), 0);
}

TEST_F(SantengSpeed, TheCurrentOfARampEndsWithTheRamp) {
  // Motor current: speed / 50 RPM plus 1 A x 10 per 500 units of ramp in the last millisecond;
  // the default ramps (10000) change the speed by 10000 units (1 RPM) a millisecond: 2 A.
  write(0x2000, 1, 1000);
  wait(500);
  EXPECT_EQ(read16(0x2100, 1), 30);  // 500 RPM: 1 A, and 2 A of acceleration
  wait(500);
  EXPECT_EQ(read16(0x2103, 1), 1000);
  EXPECT_EQ(read16(0x2100, 1), 40);  // the last millisecond of the ramp still accelerated
  wait(1);
  EXPECT_EQ(read16(0x2100, 1), 20);  // 1000 RPM, no acceleration any more
  write(0x2000, 1, 0);
  wait(1000);
  EXPECT_EQ(read16(0x2103, 1), 0);
  EXPECT_EQ(read16(0x2100, 1), 20);  // the last millisecond still braked
  wait(1);
  EXPECT_EQ(read16(0x2100, 1), 0);  // at rest: no current
}

}  // namespace
}  // namespace costa::test
