// TIME (CiA 301 7.2.6) through wire frames: the example consumes TIME on 0x100 (0x1012 =
// 0x80000100). TIME_OF_DAY: milliseconds after midnight in bytes 0..3 (28 bits), days since
// 1984-01-01 in bytes 4..5.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using TimeOfDayTest = ExampleNodeTest;

TimeOfDay clockOfDay(Node& node) {
  TimeOfDay time;
  EXPECT_TRUE(node.timeOfDay(&time));
  return time;
}

TimeOfDay timeOf(uint32_t milliseconds, uint16_t days) {
  TimeOfDay time;
  time.milliseconds = milliseconds;
  time.days = days;
  return time;
}

TEST_F(TimeOfDayTest, AConsumedFrameSetsTheClockOfDayWhichRunsOn) {
  TimeOfDay none;
  EXPECT_FALSE(bus_.node().timeOfDay(&none));  // never set
  EXPECT_TRANSCRIPT(R"(
    rx 100 [6] 10 27 00 00 2C 01   # 00:00:10.000, day 300
  )");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(10000, 300));
  EXPECT_TRANSCRIPT("wait 1500");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(11500, 300));
  EXPECT_TRANSCRIPT(R"(
    rx 100 [6] FF 5B 26 F5 2D 01   # reserved top bits set: 86,399,999 ms (23:59:59.999), day 301
  )");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(86399999, 301));
  EXPECT_TRANSCRIPT("wait 2");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(1, 302));  // midnight passed
  EXPECT_EQ(bus_.node().statistics().timeFramesIgnored, 0U);
}

TEST_F(TimeOfDayTest, TheApplicationCannotSetATimePastMidnight) {
  EXPECT_FALSE(bus_.node().setTimeOfDay(timeOf(86400000, 3)));  // 24:00:00.000
  TimeOfDay none;
  EXPECT_FALSE(bus_.node().timeOfDay(&none));  // still never set
  ASSERT_TRUE(bus_.node().setTimeOfDay(timeOf(86399999, 3)));
  EXPECT_FALSE(bus_.node().setTimeOfDay(timeOf(0xFFFFFFFFU, 4)));
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(86399999, 3));  // the refused one changed nothing
}

TEST_F(TimeOfDayTest, TheClockOfDayKeepsTimeForHoursAcrossTheMicrosecondClocksWrap) {
  EXPECT_TRANSCRIPT("rx 100 [6] 00 00 00 00 00 00   # midnight, day 0");
  for (int halfHour = 0; halfHour < 10; ++halfHour) {  // 5 h: the 32-bit µs clock wraps
    EXPECT_TRANSCRIPT("wait 1800000");                 // every 71.6 min
  }
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(18000000, 0));
}

TEST_F(TimeOfDayTest, TimeIsRoutedWithEveryPdoValid) {
  // RPDO3/4 and TPDO3/4 valid too: the routing table holds NMT, SYNC, SDO, LSS, TIME and 8 PDOs.
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 02 14 01 01 04 00 00
    tx 581 [8] 60 02 14 01 00 00 00 00
    rx 601 [8] 23 03 14 01 01 05 00 00
    tx 581 [8] 60 03 14 01 00 00 00 00
    rx 601 [8] 23 02 18 01 81 03 00 00
    tx 581 [8] 60 02 18 01 00 00 00 00
    rx 601 [8] 23 03 18 01 81 04 00 00
    tx 581 [8] 60 03 18 01 00 00 00 00
    rx 100 [6] 10 27 00 00 2C 01
  )");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(10000, 300));
  // Every route found its place: the last one built (TPDO4's remote request) too.
  // (EMCY of nodes 2 and 3, GFC and SRDO 2 are consumed too.)
  CanIdFilter filters[20];
  const size_t count = bus_.node().receiveFilters(filters, 20);
  ASSERT_EQ(count, 19U);  // 18 CAN-IDs and the error control range
  EXPECT_EQ(filters[17].id, 0x7E5U);
  EXPECT_EQ(filters[16].id, 0x601U);
  EXPECT_EQ(filters[15].id, 0x501U);
  EXPECT_EQ(filters[14].id, 0x481U);
}

TEST_F(TimeOfDayTest, MalformedFramesAreIgnoredAndCounted) {
  EXPECT_TRANSCRIPT("rx 100 [6] 10 27 00 00 2C 01");
  EXPECT_TRANSCRIPT(R"(
    rx 100 [5] 20 4E 00 00 2C
    rx 100 [7] 20 4E 00 00 2C 01 00
    rx 100 [8] 20 4E 00 00 2C 01 00 00
    rx 100 [0] RTR
    rx 100 [6] 00 5C 26 05 2C 01   # 86,400,000 ms: not a time of day
    silence
  )");
  EXPECT_EQ(bus_.node().statistics().timeFramesIgnored, 5U);
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(10000, 300));  // unchanged
}

TEST_F(TimeOfDayTest, AStoppedNodeTakesNoTime) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 02 01
    rx 100 [6] 10 27 00 00 2C 01
  )");
  TimeOfDay none;
  EXPECT_FALSE(bus_.node().timeOfDay(&none));
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01               # operational: consumed again
    rx 100 [6] 10 27 00 00 2C 01
  )");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(10000, 300));
}

TEST_F(TimeOfDayTest, TheCanIdChangesOnlyWhileNeitherConsumedNorProduced) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 12 10 00 90 01 00 80   # consume on 0x190: refused while consuming on 0x100
    tx 581 [8] 80 12 10 00 30 00 09 06
    rx 601 [8] 23 12 10 00 00 01 00 00   # stop consuming
    tx 581 [8] 60 12 10 00 00 00 00 00
    rx 100 [6] 10 27 00 00 2C 01         # not consumed now
    rx 601 [8] 23 12 10 00 90 01 00 00   # 0x190, then consume
    tx 581 [8] 60 12 10 00 00 00 00 00
    rx 601 [8] 23 12 10 00 90 01 00 80
    tx 581 [8] 60 12 10 00 00 00 00 00
    rx 100 [6] 10 27 00 00 2C 01         # the old CAN-ID: nobody's
    rx 190 [6] 20 4E 00 00 2C 01         # 00:00:20.000, day 300
    rx 601 [8] 23 12 10 00 00 01 00 A0   # 29-bit
    tx 581 [8] 80 12 10 00 30 00 09 06
    rx 601 [8] 23 12 10 00 00 00 00 02   # bits 11..28
    tx 581 [8] 80 12 10 00 30 00 09 06
    rx 601 [8] 23 12 10 00 90 01 00 00
    tx 581 [8] 60 12 10 00 00 00 00 00
    rx 601 [8] 23 12 10 00 23 01 00 00   # 0x123: restricted (CiA 301 7.3.5: 0x101..0x180)
    tx 581 [8] 80 12 10 00 30 00 09 06
    rx 601 [8] 23 12 10 00 81 05 00 00   # 0x581: restricted (SDO)
    tx 581 [8] 80 12 10 00 30 00 09 06
    rx 601 [8] 40 12 10 00 00 00 00 00
    tx 581 [8] 43 12 10 00 90 01 00 00
  )");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(20000, 300));
  EXPECT_EQ(bus_.node().statistics().timeFramesIgnored, 0U);
}

TEST_F(TimeOfDayTest, ResetCommunicationConsumesOnTheDefaultCanIdAgain) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 12 10 00 00 01 00 00
    tx 581 [8] 60 12 10 00 00 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    rx 100 [6] 10 27 00 00 2C 01
  )");
  EXPECT_EQ(clockOfDay(bus_.node()), timeOf(10000, 300));
}

TEST_F(TimeOfDayTest, AProducerSendsItsClockOfDayAtTheApplicationsPeriod) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 12 10 00 00 01 00 40   # produce on 0x100 (and no longer consume)
    tx 581 [8] 60 12 10 00 00 00 00 00
  )");
  bus_.node().setTimeProducerPeriod(millisecondsToMicroseconds(100));
  EXPECT_TRANSCRIPT("wait 250\nsilence");  // the clock of day is not set: nothing to send
  ASSERT_TRUE(bus_.node().setTimeOfDay(timeOf(86399950, 7)));  // 23:59:59.950, day 7
  EXPECT_TRANSCRIPT(R"(
    wait 99
    silence
    wait 1
    tx 100 [6] 32 00 00 00 08 00   # one period later: 00:00:00.050, day 8
    wait 100
    tx 100 [6] 96 00 00 00 08 00   # 00:00:00.150
    rx 000 [2] 02 01               # stopped: no TIME
    wait 300
    silence
    rx 000 [2] 80 01               # pre-operational: TIME again, on the period's beat
    wait 100
    tx 100 [6] 26 02 00 00 08 00   # 00:00:00.550
  )");
  bus_.node().setTimeProducerPeriod(0);
  EXPECT_TRANSCRIPT("wait 500\nsilence");
  EXPECT_EQ(bus_.node().statistics().timeFramesIgnored, 0U);
}

}  // namespace
}  // namespace costa::test
