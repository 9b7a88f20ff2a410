// TimeService alone: the clock of day running on from where it was set, at the edges of the
// 32-bit microsecond clock (the longest time between two folds, a midnight passed then) and of a
// millisecond.
#include "costa/time_service.hpp"

#include <gtest/gtest.h>

#include "costa/frame_router.hpp"
#include "service_fixture.hpp"

namespace costa::test {
namespace {

TimeOfDay timeOf(uint32_t milliseconds, uint16_t days) {
  TimeOfDay time;
  time.milliseconds = milliseconds;
  time.days = days;
  return time;
}

class TimeServiceTest : public ServiceTest {
 protected:
  TimeServiceTest() : time_(dictionary_, tx_, clock_, router_) { time_.configure(); }

  /// The clock of day at `now`.
  TimeOfDay at(Microseconds now) const {
    TimeOfDay result;
    EXPECT_TRUE(time_.timeOfDay(now, &result));
    return result;
  }

  RouteEntry routes_[4];
  FrameRouter router_{routes_, 4};
  TimeService time_;
};

TEST_F(TimeServiceTest, AMillisecondCountsOnceWhole) {
  ASSERT_TRUE(time_.setTimeOfDay(timeOf(5000, 2), kStart));
  EXPECT_EQ(at(after(999)), timeOf(5000, 2));
  EXPECT_EQ(at(after(1000)), timeOf(5001, 2));
  EXPECT_EQ(at(after(1999)), timeOf(5001, 2));
}

TEST_F(TimeServiceTest, TheLongestTimeWithoutAFoldRunsOnAndPassesMidnight) {
  // 2^32 - 1 µs after it was set: 4,294,967 ms, the most a query can add to the clock of day.
  ASSERT_TRUE(time_.setTimeOfDay(timeOf(0, 7), kStart));
  EXPECT_EQ(at(after(UINT32_MAX)), timeOf(4294967, 7));
  ASSERT_TRUE(time_.setTimeOfDay(timeOf(82800000, 7), kStart));  // 23:00
  EXPECT_EQ(at(after(UINT32_MAX)), timeOf(82800000 + 4294967 - 86400000, 8));
  ASSERT_TRUE(time_.setTimeOfDay(timeOf(86399999, 0xFFFF), kStart));  // the last day's end
  EXPECT_EQ(at(after(1000)), timeOf(0, 0));
}

TEST_F(TimeServiceTest, AFoldKeepsTheMicrosecondsBelowAMillisecond) {
  ASSERT_TRUE(time_.setTimeOfDay(timeOf(86000000, 1), kStart));
  const Microseconds fold = time_.nextDeadline();  // 10 min after it was set
  ASSERT_EQ(fold, after(600000000));
  time_.process(fold + 999U, true);  // folds 600,000 ms in, midnight passed: 00:03:20.000
  EXPECT_EQ(at(fold + 999U), timeOf(200000, 2));
  EXPECT_EQ(at(fold + 1000U), timeOf(200001, 2));  // the 999 µs left over count on
}

}  // namespace
}  // namespace costa::test
