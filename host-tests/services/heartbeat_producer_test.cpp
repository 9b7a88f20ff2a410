// HeartbeatProducer alone: the state every 0x1017 ms, its rhythm, and writes of 0x1017.
#include "costa/heartbeat_producer.hpp"

#include <gtest/gtest.h>

#include "service_fixture.hpp"

namespace costa::test {
namespace {

class HeartbeatProducerTest : public ServiceTest {
 protected:
  HeartbeatProducerTest() : heartbeat_(dictionary_, tx_, clock_) { heartbeat_.setNodeId(kNodeId); }

  HeartbeatProducer heartbeat_;
};

TEST_F(HeartbeatProducerTest, DisabledWhile1017IsZero) {
  heartbeat_.restart(kStart);
  EXPECT_EQ(heartbeat_.nextDeadline(), kNever);
  heartbeat_.process(afterMs(60000), NmtState::kOperational);
  EXPECT_TRUE(sent().empty());
}

TEST_F(HeartbeatProducerTest, FirstHeartbeatOnePeriodAfterTheRestartThenEveryPeriod) {
  store(0x1017, 0, 100);
  heartbeat_.restart(kStart);
  EXPECT_EQ(heartbeat_.nextDeadline(), afterMs(100));
  EXPECT_EQ(clock_.next, afterMs(100));  // the node hears of the deadline
  heartbeat_.process(afterMs(100) - 1U, NmtState::kPreOperational);
  EXPECT_TRUE(sent().empty());
  heartbeat_.process(afterMs(100), NmtState::kPreOperational);
  EXPECT_EQ(sent(), frames({frame(0x705, {0x7F})}));
  EXPECT_EQ(heartbeat_.nextDeadline(), afterMs(200));
  heartbeat_.process(afterMs(200), NmtState::kPreOperational);  // across the clock's wrap
  EXPECT_EQ(sent(), frames({frame(0x705, {0x7F})}));
}

TEST_F(HeartbeatProducerTest, CarriesTheStateItIsGiven) {
  heartbeat_.restartWith(kStart, 10);
  heartbeat_.process(afterMs(10), NmtState::kOperational);
  heartbeat_.process(afterMs(20), NmtState::kStopped);
  heartbeat_.process(afterMs(30), NmtState::kPreOperational);
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05}), frame(0x705, {0x04}), frame(0x705, {0x7F})}));
}

TEST_F(HeartbeatProducerTest, ALateCallKeepsTheRhythmALateCallByAPeriodRestartsIt) {
  heartbeat_.restartWith(kStart, 100);
  heartbeat_.process(afterMs(130), NmtState::kOperational);  // 30 ms late: next at 200 ms
  EXPECT_EQ(heartbeat_.nextDeadline(), afterMs(200));
  heartbeat_.process(afterMs(450), NmtState::kOperational);  // 250 ms late: one frame, then 550
  EXPECT_EQ(heartbeat_.nextDeadline(), afterMs(550));
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05}), frame(0x705, {0x05})}));
}

TEST_F(HeartbeatProducerTest, AWriteOf1017StoresAndRestartsFromTheTimeOfTheWrite) {
  heartbeat_.restartWith(kStart, 100);
  clock_.advance(afterMs(70));
  EXPECT_EQ(write(heartbeat_, 0x1017, 0, 50, 2), AbortCode::kNone);
  EXPECT_EQ(value(0x1017, 0), 50U);
  EXPECT_EQ(heartbeat_.nextDeadline(), afterMs(120));
  heartbeat_.process(afterMs(100), NmtState::kOperational);  // the old deadline is gone
  EXPECT_TRUE(sent().empty());
  heartbeat_.process(afterMs(120), NmtState::kOperational);
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05})}));
}

TEST_F(HeartbeatProducerTest, WritingZeroStopsProduction) {
  heartbeat_.restartWith(kStart, 100);
  EXPECT_EQ(write(heartbeat_, 0x1017, 0, 0, 2), AbortCode::kNone);
  EXPECT_EQ(heartbeat_.nextDeadline(), kNever);
  heartbeat_.process(afterMs(1000), NmtState::kOperational);
  EXPECT_TRUE(sent().empty());
}

TEST_F(HeartbeatProducerTest, AWriteOfTheWrongLengthAbortsAndChangesNothing) {
  heartbeat_.restartWith(kStart, 100);
  EXPECT_EQ(write(heartbeat_, 0x1017, 0, 50, 4), AbortCode::kLengthTooHigh);
  EXPECT_EQ(write(heartbeat_, 0x1017, 0, 50, 1), AbortCode::kLengthTooLow);
  EXPECT_EQ(value(0x1017, 0), 0U);
  EXPECT_EQ(heartbeat_.nextDeadline(), afterMs(100));
}

TEST_F(HeartbeatProducerTest, StopCancelsTheNextHeartbeat) {
  heartbeat_.restartWith(kStart, 100);
  heartbeat_.stop();
  EXPECT_EQ(heartbeat_.nextDeadline(), kNever);
  heartbeat_.process(afterMs(100), NmtState::kOperational);
  EXPECT_TRUE(sent().empty());
}

TEST_F(HeartbeatProducerTest, AHeartbeatTheControllerRefusesWaitsInTheTransmitQueue) {
  heartbeat_.restartWith(kStart, 100);
  can_.setAccepting(false);
  heartbeat_.process(afterMs(100), NmtState::kOperational);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(tx_.queued(), 1U);
  can_.setAccepting(true);
  tx_.flush(afterMs(101));
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05})}));
}

}  // namespace
}  // namespace costa::test
