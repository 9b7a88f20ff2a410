// The 32-bit microsecond clock (costa/time.hpp): comparisons across its wrap, LongTimer, and the
// CiA 301 periods longer than half the clock's range (SYNC period, node guarding life time).
#include "costa/time.hpp"
#include "costa/node_clock.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

constexpr Microseconds kJustBeforeWrap = 0xFFFFFF00U;

TEST(Time, ComparisonsHoldAcrossTheWrap) {
  EXPECT_TRUE(before(kJustBeforeWrap, 0x10U));
  EXPECT_FALSE(before(0x10U, kJustBeforeWrap));
  EXPECT_TRUE(reached(0x10U, kJustBeforeWrap));
  EXPECT_FALSE(reached(kJustBeforeWrap, 0x10U));
  EXPECT_TRUE(reached(0x10U, 0x10U));
  EXPECT_FALSE(reached(0x10U, kNever));  // "no deadline" never comes
  EXPECT_EQ(earliest(0x10U, kJustBeforeWrap), kJustBeforeWrap);
  EXPECT_EQ(earliest(kNever, 0x10U), 0x10U);
  EXPECT_EQ(earliest(0x10U, kNever), 0x10U);
  EXPECT_EQ(earliest(kNever, kNever), kNever);
}

TEST(Time, ADeadlineIsNeverTheValueForNoDeadline) {
  EXPECT_EQ(at(kNever - 5U, 5U), 0U);  // one microsecond late rather than never
  EXPECT_EQ(at(kJustBeforeWrap, 0x100U), 0U);
  EXPECT_EQ(at(kJustBeforeWrap, 0x110U), 0x10U);
}

TEST(Time, AtOnceIsDueEvenAtTheClockValueForNoDeadline) {
  EXPECT_EQ(atOnce(0x10U), 0x10U);
  EXPECT_EQ(atOnce(kNever), kNever - 1U);
  NodeClock clock;
  clock.start(kNever);
  clock.scheduleNow();
  EXPECT_TRUE(clock.due());
  clock.next = kNever;
  clock.schedule(clock.now);  // what "now" would be: no deadline
  EXPECT_FALSE(clock.due());
}

TEST(Time, ALongTimerWaitsInStepsAndFiresOnceAtTheEnd) {
  LongTimer timer;
  EXPECT_FALSE(timer.running());
  const uint64_t delay = 3ULL * kLongestDelay + 5U;  // about 1 h 47 min
  timer.start(kJustBeforeWrap, delay);
  const Microseconds end = kJustBeforeWrap + static_cast<Microseconds>(delay);
  int steps = 0;
  Microseconds now = kJustBeforeWrap;
  while (!timer.fired(now)) {
    ASSERT_TRUE(timer.running());
    ASSERT_TRUE(before(now, timer.next()));
    ASSERT_LE(timer.next() - now, kLongestDelay);  // every step is within the clock's range
    now = timer.next();
    ++steps;
    ASSERT_LT(steps, 10);
  }
  EXPECT_EQ(now, end);
  EXPECT_EQ(timer.due(), end);
  EXPECT_EQ(steps, 4);
  EXPECT_FALSE(timer.running());
  EXPECT_FALSE(timer.fired(now + 1U));  // once
}

TEST(Time, ALongTimerCalledLateCatchesUp) {
  LongTimer timer;
  timer.start(0, 2ULL * kLongestDelay);
  const Microseconds late = kLongestDelay + 1000U;  // the first step's end has passed
  EXPECT_FALSE(timer.fired(late));                  // takes the next step from the first's end
  EXPECT_EQ(timer.next(), static_cast<Microseconds>(2ULL * kLongestDelay));
  EXPECT_TRUE(timer.fired(timer.next()));
}

using LongPeriods = ExampleNodeTest;

// 30 minutes of virtual time, in transcript minutes.
constexpr const char* kHalfHour = "wait 1800000\n";

TEST_F(LongPeriods, ASyncPeriodLongerThanHalfTheClockIsKept) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 06 10 00 00 28 6B EE   # period 4,000,000,000 us (66 min 40 s)
    tx 581 [8] 60 06 10 00 00 00 00 00
    rx 601 [8] 23 05 10 00 80 00 00 40   # this node produces
    tx 581 [8] 60 05 10 00 00 00 00 00
  )");
  EXPECT_TRANSCRIPT(std::string(kHalfHour) + kHalfHour + "wait 399999\nsilence\nwait 1\n" +
                    "tx 080 [0]\n" + kHalfHour + kHalfHour + "wait 399999\nsilence\nwait 1\n" +
                    "tx 080 [0]\n");
}

TEST_F(LongPeriods, ALifeTimeLongerThanHalfTheClockIsKept) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 0C 10 00 60 EA 00 00   # guard time 60,000 ms
    tx 581 [8] 60 0C 10 00 00 00 00 00
    rx 601 [8] 2F 0D 10 00 3C 00 00 00   # life time factor 60: one hour
    tx 581 [8] 60 0D 10 00 00 00 00 00
    rx 701 [0] RTR
    tx 701 [1] 7F
  )");
  EXPECT_TRANSCRIPT(std::string(kHalfHour) + "wait 1799999\nsilence\nwait 1\n" +
                    "tx 081 [8] 30 81 11 00 00 00 00 00\n");
}

}  // namespace
}  // namespace costa::test
