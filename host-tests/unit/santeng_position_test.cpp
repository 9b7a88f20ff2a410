// Santeng count position mode (errata B3, B4, D9): 0x2001 the count to go to, 0x2002 the speed
// in RPM, 4 counts per encoder line (lines 537, 684), the ramps of 0x2006/0x2007; 0x2003 loads
// the counter; relative counts since the previous read; the stop of 0x200E. On a virtual clock.
#include "santeng_fixture.hpp"

namespace costa::test {
namespace {

class SantengPosition : public SantengTest {
 protected:
  void SetUp() override {
    SantengTest::SetUp();
    ASSERT_EQ(sim("set mode 1 position"), "");
  }
};

TEST_F(SantengPosition, TheManualsExampleOnTheWay) {  // lines 283-297
  write(0x2001, 1, 4000000);
  write(0x2002, 1, 1000);
  wait(2000);
  // 1 s at 1000 RPM/s up to 1000 RPM (33366 counts, 4000 a revolution), 1 s at 1000 RPM.
  EXPECT_EQ(read32(0x2104, 1), 100033);
  EXPECT_EQ(read16(0x2103, 1), 1000);
  write(0x200E, 1, 0);  // line 301: stop
  wait(2000);
  EXPECT_EQ(read16(0x2103, 1), 0);
  // 1 s braking at 1000 RPM/s: 33300 counts more.
  EXPECT_EQ(read32(0x2104, 1), 133333);
  wait(1000);
  EXPECT_EQ(read32(0x2104, 1), 133333);  // and it stays there
}

TEST_F(SantengPosition, ArrivesExactlyOnTheTargetWithoutOvershoot) {
  write(0x2002, 1, 300);
  write(0x2001, 1, 10000);
  int32_t previous = 0;
  for (int step = 0; step < 300; ++step) {
    wait(10);
    const int32_t count = read32(0x2104, 1);
    ASSERT_GE(count, previous);
    ASSERT_LE(count, 10000);
    previous = count;
  }
  EXPECT_EQ(previous, 10000);
  EXPECT_EQ(read16(0x2103, 1), 0);
  write(0x2001, 1, -2000);  // and back, below zero
  wait(3000);
  EXPECT_EQ(read32(0x2104, 1), -2000);
}

TEST_F(SantengPosition, SpeedZeroStandsStillAndSpeedIsCappedAtMaxRpm) {
  write(0x2001, 1, 1000000);
  wait(1000);
  EXPECT_EQ(read32(0x2104, 1), 0);  // 0x2002 = 0 (B3)
  write(0x2002, 1, -5000);          // the magnitude counts, at most max RPM (1000)
  wait(3000);
  EXPECT_EQ(read16(0x2103, 1), 1000);
}

TEST_F(SantengPosition, LoadingTheCounterMovesTheMotorToTheTargetAgain) {  // lines 557-574
  write(0x2002, 1, 600);
  write(0x2001, 1, 5000);
  wait(3000);
  ASSERT_EQ(read32(0x2104, 1), 5000);
  write(0x2003, 1, -1000);  // "C 2 -1000" on channel 1: the counter is now -1000
  EXPECT_EQ(read32(0x2104, 1), -1000);
  wait(3000);
  EXPECT_EQ(read32(0x2104, 1), 5000);  // and it went back to its target (line 561)
}

TEST_F(SantengPosition, RelativeCountsAreSinceThePreviousRead) {
  ASSERT_EQ(sim("set mode 1 open-loop"), "");
  write(0x2006, 1, 0);
  write(0x2000, 1, 600);  // 40 counts a millisecond
  wait(100);
  EXPECT_EQ(read32(0x2108, 1), 4000);
  wait(50);
  EXPECT_EQ(read32(0x2108, 1), 2000);
  EXPECT_EQ(read32(0x2108, 1), 0);  // nothing moved since
  write(0x2003, 1, 0);              // a load is no motion
  wait(25);
  EXPECT_EQ(read32(0x2108, 1), 1000);
  EXPECT_EQ(read32(0x2109, 1), 42);  // 0.24 hall counts a millisecond, 175 ms
  EXPECT_EQ(read32(0x2108, 2), 0);
}

TEST_F(SantengPosition, StopHoldsUntilTheNextMotionCommand) {
  write(0x2002, 1, 1000);
  write(0x2001, 1, 40000);
  wait(500);
  write(0x200E, 1, 1);  // any value
  wait(2000);
  const int32_t stopped = read32(0x2104, 1);
  EXPECT_LT(stopped, 40000);
  wait(1000);
  EXPECT_EQ(read32(0x2104, 1), stopped);
  write(0x2002, 1, 1000);  // a motion command: on to the target
  wait(4000);
  EXPECT_EQ(read32(0x2104, 1), 40000);
}

TEST_F(SantengPosition, StopAppliesToItsChannelOnly) {
  ASSERT_EQ(sim("set mode 2 position"), "");
  write(0x2002, 1, 1000);
  write(0x2002, 2, 1000);
  write(0x2001, 1, 40000);
  write(0x2001, 2, 40000);
  wait(500);
  write(0x200E, 2, 0);
  wait(5000);
  EXPECT_EQ(read32(0x2104, 1), 40000);
  EXPECT_LT(read32(0x2104, 2), 40000);
}

}  // namespace
}  // namespace costa::test
