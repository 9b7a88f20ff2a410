// HeartbeatConsumer alone: 0x1016 entries, timeout and resumed events, and its write rules.
#include "costa/heartbeat_consumer.hpp"

#include <gtest/gtest.h>

#include "service_fixture.hpp"

namespace costa::test {
namespace {

using Kind = HeartbeatConsumer::EventKind;

class HeartbeatConsumerTest : public ServiceTest {
 protected:
  HeartbeatConsumerTest() : consumer_(dictionary_, clock_, monitors_, 2) {}

  /// Entry `sub` of 0x1016: node `nodeId` every `ms`.
  static uint32_t entryValue(uint8_t nodeId, uint16_t ms) {
    return (static_cast<uint32_t>(nodeId) << 16U) | ms;
  }
  void monitor(uint8_t sub, uint8_t nodeId, uint16_t ms) {
    store(0x1016, sub, entryValue(nodeId, ms));
    consumer_.configure(true);
  }

  HeartbeatMonitor monitors_[2];
  HeartbeatConsumer consumer_;
};

TEST_F(HeartbeatConsumerTest, MonitoringStartsAtTheFirstHeartbeat) {
  monitor(1, 0x20, 100);
  EXPECT_EQ(consumer_.nextDeadline(), kNever);
  EXPECT_EQ(consumer_.process(afterMs(1000)).kind, Kind::kNone);  // none yet: no timeout
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, afterMs(1000)).kind, Kind::kNone);
  EXPECT_EQ(consumer_.nextDeadline(), afterMs(1100));
  const HeartbeatMonitor* entry = consumer_.monitor(1);
  ASSERT_NE(entry, nullptr);
  EXPECT_TRUE(entry->active);
  EXPECT_EQ(entry->lastState, 0x05U);
  EXPECT_TRUE(sent().empty());  // a consumer never sends
}

TEST_F(HeartbeatConsumerTest, ATimeoutIsReportedOnceThenTheReturn) {
  monitor(2, 0x20, 100);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x7F, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.process(afterMs(100) - 1U).kind, Kind::kNone);
  const HeartbeatConsumer::Event timeout = consumer_.process(afterMs(100));
  EXPECT_EQ(timeout.kind, Kind::kTimeout);
  EXPECT_EQ(timeout.nodeId, 0x20U);
  EXPECT_EQ(timeout.entry, 2U);
  EXPECT_EQ(consumer_.process(afterMs(500)).kind, Kind::kNone);  // once
  EXPECT_EQ(consumer_.nextDeadline(), kNever);
  const HeartbeatConsumer::Event back = consumer_.onHeartbeat(0x20, 0x05, afterMs(600));
  EXPECT_EQ(back.kind, Kind::kResumed);
  EXPECT_EQ(back.nodeId, 0x20U);
  EXPECT_EQ(back.entry, 2U);
  EXPECT_EQ(consumer_.nextDeadline(), afterMs(700));
}

// A timed-out entry that gets a new value is withdrawn: one event, due at once; the new value
// is monitored from its first heartbeat. An entry that did not time out, or a value written
// again, withdraws nothing.
TEST_F(HeartbeatConsumerTest, ANewValueWithdrawsATimedOutEntryOnce) {
  monitor(1, 0x20, 100);
  monitor(2, 0x21, 100);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.process(afterMs(100)).kind, Kind::kTimeout);
  store(0x1016, 2, entryValue(0x22, 100));  // never timed out
  consumer_.configure(false);
  store(0x1016, 1, entryValue(0x20, 100));  // unchanged
  consumer_.configure(false);
  EXPECT_EQ(consumer_.process(afterMs(150)).kind, Kind::kNone);
  store(0x1016, 1, entryValue(0x20, 200));  // timed out, then a new time
  consumer_.configure(false);
  store(0x1016, 1, entryValue(0x23, 200));  // changed again before process(): still one event
  consumer_.configure(false);
  const HeartbeatConsumer::Event withdrawn = consumer_.process(afterMs(200));
  EXPECT_EQ(withdrawn.kind, Kind::kWithdrawn);
  EXPECT_EQ(withdrawn.nodeId, 0x20U);  // the producer that had timed out, not 0x23
  EXPECT_EQ(withdrawn.entry, 1U);
  EXPECT_EQ(consumer_.process(afterMs(200)).kind, Kind::kNone);
  EXPECT_FALSE(consumer_.monitor(1)->active);
  EXPECT_EQ(consumer_.onHeartbeat(0x23, 0x05, afterMs(300)).kind, Kind::kNone);  // not resumed
  EXPECT_EQ(consumer_.process(afterMs(500)).kind, Kind::kTimeout);
}

TEST_F(HeartbeatConsumerTest, EachHeartbeatRestartsTheWait) {
  monitor(1, 0x20, 100);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, afterMs(90)).kind, Kind::kNone);
  EXPECT_EQ(consumer_.process(afterMs(180)).kind, Kind::kNone);
  EXPECT_EQ(consumer_.process(afterMs(190)).kind, Kind::kTimeout);
}

TEST_F(HeartbeatConsumerTest, EntriesWithNodeIdZeroOrTimeZeroAreDisabled) {
  store(0x1016, 1, entryValue(0, 100));
  store(0x1016, 2, entryValue(0x21, 0));
  consumer_.configure(true);
  EXPECT_EQ(consumer_.onHeartbeat(0, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.onHeartbeat(0x21, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.nextDeadline(), kNever);
  EXPECT_EQ(consumer_.process(afterMs(10000)).kind, Kind::kNone);
}

TEST_F(HeartbeatConsumerTest, TwoProducersAreMonitoredIndependently) {
  store(0x1016, 1, entryValue(0x20, 100));
  store(0x1016, 2, entryValue(0x21, 300));
  consumer_.configure(true);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.onHeartbeat(0x21, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.onHeartbeat(0x22, 0x05, kStart).kind, Kind::kNone);  // not monitored
  EXPECT_EQ(consumer_.nextDeadline(), afterMs(100));
  EXPECT_EQ(consumer_.process(afterMs(100)).nodeId, 0x20U);
  EXPECT_EQ(consumer_.nextDeadline(), afterMs(300));
  const HeartbeatConsumer::Event second = consumer_.process(afterMs(300));
  EXPECT_EQ(second.kind, Kind::kTimeout);
  EXPECT_EQ(second.nodeId, 0x21U);
}

TEST_F(HeartbeatConsumerTest, TwoEnabledEntriesForOneNodeAbort06040043) {
  EXPECT_EQ(write(consumer_, 0x1016, 1, entryValue(0x20, 100), 4), AbortCode::kNone);
  EXPECT_EQ(write(consumer_, 0x1016, 2, entryValue(0x20, 200), 4),
            AbortCode::kParameterIncompatible);
  EXPECT_EQ(write(consumer_, 0x1016, 2, entryValue(0x20, 0), 4), AbortCode::kNone);    // disabled
  EXPECT_EQ(write(consumer_, 0x1016, 1, entryValue(0x20, 150), 4), AbortCode::kNone);  // itself
  EXPECT_EQ(value(0x1016, 1), entryValue(0x20, 150));
}

TEST_F(HeartbeatConsumerTest, ReservedBitsAndWrongLengthsAreRefused) {
  EXPECT_EQ(write(consumer_, 0x1016, 1, 0x01200064U, 4), AbortCode::kInvalidValue);
  EXPECT_EQ(write(consumer_, 0x1016, 1, entryValue(0x20, 100), 2), AbortCode::kLengthTooLow);
  EXPECT_EQ(value(0x1016, 1), 0U);
}

TEST_F(HeartbeatConsumerTest, AWriteRestartsTheChangedEntryOnly) {
  store(0x1016, 1, entryValue(0x20, 100));
  store(0x1016, 2, entryValue(0x21, 100));
  consumer_.configure(true);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.onHeartbeat(0x21, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(write(consumer_, 0x1016, 2, entryValue(0x21, 500), 4), AbortCode::kNone);
  ASSERT_NE(consumer_.monitor(2), nullptr);
  EXPECT_FALSE(consumer_.monitor(2)->active);  // waits for its first heartbeat again
  EXPECT_TRUE(consumer_.monitor(1)->active);
  EXPECT_EQ(consumer_.nextDeadline(), afterMs(100));
}

TEST_F(HeartbeatConsumerTest, AResetConfigurationStartsEveryEntryOver) {
  monitor(1, 0x20, 100);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, kStart).kind, Kind::kNone);
  EXPECT_EQ(consumer_.process(afterMs(100)).kind, Kind::kTimeout);
  consumer_.configure(true);
  EXPECT_FALSE(consumer_.monitor(1)->timedOut);
  EXPECT_FALSE(consumer_.monitor(1)->active);
  EXPECT_EQ(consumer_.onHeartbeat(0x20, 0x05, afterMs(200)).kind, Kind::kNone);  // not resumed
}

TEST_F(HeartbeatConsumerTest, OnlyConfiguredSubIndicesHaveAMonitor) {
  consumer_.configure(true);
  EXPECT_EQ(consumer_.monitor(0), nullptr);
  EXPECT_NE(consumer_.monitor(2), nullptr);
  EXPECT_EQ(consumer_.monitor(3), nullptr);
  HeartbeatMonitor one[1];
  HeartbeatConsumer small(dictionary_, clock_, one,
                          1);  // fewer monitors than entries: the first ones
  small.configure(true);
  EXPECT_NE(small.monitor(1), nullptr);
  EXPECT_EQ(small.monitor(2), nullptr);
}

}  // namespace
}  // namespace costa::test
