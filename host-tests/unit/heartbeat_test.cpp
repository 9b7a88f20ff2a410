// Heartbeat producer (0x1017) on a virtual clock.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Heartbeat = ExampleNodeTest;

TEST_F(Heartbeat, DisabledByDefault) {
  EXPECT_EQ(play("wait 10000\nsilence"), "");
}

TEST_F(Heartbeat, FirstOnePeriodAfterTheWriteThenEveryPeriod) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 E8 03 00 00   # 1000 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 999
    silence
    wait 1
    tx 701 [1] 7F
    wait 999
    silence
    wait 1
    tx 701 [1] 7F
  )");
}

TEST_F(Heartbeat, CarriesTheCurrentState) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 64 00 00 00   # 100 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 100
    tx 701 [1] 7F
    rx 000 [2] 01 01
    wait 100
    tx 701 [1] 05
    rx 000 [2] 02 01
    wait 100
    tx 701 [1] 04
  )");
}

TEST_F(Heartbeat, NewPeriodRestartsTheTimerAndZeroStopsIt) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 E8 03 00 00
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 500
    rx 601 [8] 2B 17 10 00 C8 00 00 00   # 200 ms, counted from this write
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 199
    silence
    wait 1
    tx 701 [1] 7F
    rx 601 [8] 2B 17 10 00 00 00 00 00
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 5000
    silence
  )");
}

TEST_F(Heartbeat, KeepsItsRhythmWhenProcessIsLate) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 64 00 00 00
    tx 581 [8] 60 17 10 00 00 00 00 00
  )");
  // The loop is called late: at 150 ms instead of 100 ms. The next heartbeat stays at 200 ms.
  const Microseconds written = bus_.now();
  bus_.node().process(written + 150000U);
  EXPECT_EQ(bus_.unread(), 1U);
  EXPECT_EQ(bus_.node().process(written + 150000U), written + 200000U);
  // Called very late (more than a period): the rhythm restarts from then.
  bus_.node().process(written + 1000000U);
  EXPECT_EQ(bus_.node().process(written + 1000000U), written + 1100000U);
}

TEST_F(Heartbeat, ReportsItsDeadlineToTheCaller) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 F4 01 00 00   # 500 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
  )");
  EXPECT_EQ(bus_.node().process(bus_.now()), bus_.now() + 500000U);
}

}  // namespace
}  // namespace costa::test
