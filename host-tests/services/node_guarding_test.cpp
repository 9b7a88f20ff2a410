// NodeGuarding alone: the reply with its toggle bit, the life time 0x100C x 0x100D, their writes.
#include "costa/node_guarding.hpp"

#include <gtest/gtest.h>

#include "service_fixture.hpp"

namespace costa::test {
namespace {

using Event = NodeGuarding::Event;

class NodeGuardingTest : public ServiceTest {
 protected:
  NodeGuardingTest() : guarding_(dictionary_, tx_, clock_) { guarding_.reset(kNodeId, 0); }

  /// Guard time `ms`, life time factor `factor`.
  void guard(uint16_t ms, uint8_t factor) {
    store(0x100C, 0, ms);
    store(0x100D, 0, factor);
  }

  NodeGuarding guarding_;
};

TEST_F(NodeGuardingTest, RepliesWithTheStateAndAToggleBitStartingAtZero) {
  EXPECT_EQ(guarding_.onRequest(NmtState::kPreOperational, kStart), Event::kNone);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  EXPECT_EQ(guarding_.onRequest(NmtState::kStopped, kStart), Event::kNone);
  EXPECT_EQ(sent(), frames({frame(0x705, {0x7F}), frame(0x705, {0x85}), frame(0x705, {0x04})}));
}

TEST_F(NodeGuardingTest, ResetRestartsTheToggleBitAtTheGivenValue) {
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  guarding_.reset(kNodeId, 1);
  EXPECT_EQ(guarding_.onRequest(NmtState::kPreOperational, kStart), Event::kNone);
  guarding_.reset(0x12, 0);  // and the node-id
  EXPECT_EQ(guarding_.onRequest(NmtState::kPreOperational, kStart), Event::kNone);
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05}), frame(0x705, {0xFF}), frame(0x712, {0x7F})}));
}

TEST_F(NodeGuardingTest, WithoutRequestsThereIsNoLifeGuarding) {
  guard(100, 3);
  EXPECT_EQ(guarding_.nextDeadline(), kNever);
  EXPECT_EQ(guarding_.process(afterMs(10000)), Event::kNone);
}

TEST_F(NodeGuardingTest, TheLifeTimeExpiresOnceAfterGuardTimeTimesFactor) {
  guard(100, 3);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  EXPECT_EQ(guarding_.nextDeadline(), afterMs(300));
  EXPECT_EQ(clock_.next, afterMs(300));
  EXPECT_EQ(guarding_.process(afterMs(300) - 1U), Event::kNone);
  EXPECT_EQ(guarding_.process(afterMs(300)), Event::kLifeTimeExpired);
  EXPECT_TRUE(guarding_.expired());
  EXPECT_EQ(guarding_.process(afterMs(900)), Event::kNone);
  EXPECT_EQ(guarding_.nextDeadline(), kNever);
}

TEST_F(NodeGuardingTest, ARequestAfterTheExpiryResumesGuarding) {
  guard(100, 3);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  EXPECT_EQ(guarding_.process(afterMs(300)), Event::kLifeTimeExpired);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, afterMs(400)), Event::kResumed);
  EXPECT_FALSE(guarding_.expired());
  EXPECT_EQ(guarding_.nextDeadline(), afterMs(700));
  EXPECT_EQ(sent(), frames({frame(0x705, {0x05}), frame(0x705, {0x85})}));  // answered anyway
}

TEST_F(NodeGuardingTest, EachRequestRestartsTheLifeTime) {
  guard(100, 2);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, afterMs(150)), Event::kNone);
  EXPECT_EQ(guarding_.process(afterMs(300)), Event::kNone);
  EXPECT_EQ(guarding_.process(afterMs(350)), Event::kLifeTimeExpired);
}

TEST_F(NodeGuardingTest, AZeroGuardTimeOrFactorMeansNoLifeGuarding) {
  guard(0, 3);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  EXPECT_EQ(guarding_.nextDeadline(), kNever);
  guard(100, 0);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  EXPECT_EQ(guarding_.process(afterMs(100000)), Event::kNone);
}

TEST_F(NodeGuardingTest, AWriteWhileGuardedRestartsTheLifeTimeFromTheWrite) {
  guard(100, 3);
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  clock_.advance(afterMs(200));
  EXPECT_EQ(write(guarding_, 0x100D, 0, 5, 1), AbortCode::kNone);
  EXPECT_EQ(guarding_.nextDeadline(), afterMs(700));
  EXPECT_EQ(write(guarding_, 0x100C, 0, 10, 2), AbortCode::kNone);
  EXPECT_EQ(guarding_.nextDeadline(), afterMs(250));
  EXPECT_EQ(write(guarding_, 0x100C, 0, 10, 4), AbortCode::kLengthTooHigh);
  EXPECT_EQ(value(0x100C, 0), 10U);
}

TEST_F(NodeGuardingTest, ALifeTimeLongerThan35MinutesIsWaitedInSteps) {
  guard(65535, 255);  // 4.6 h
  const uint64_t life = uint64_t{65535} * 255U * 1000U;
  EXPECT_EQ(guarding_.onRequest(NmtState::kOperational, kStart), Event::kNone);
  Microseconds now = kStart;
  uint64_t waited = 0;
  while (waited + kLongestDelay < life) {
    now = guarding_.nextDeadline();
    waited += kLongestDelay;
    EXPECT_EQ(guarding_.process(now), Event::kNone) << waited;
  }
  EXPECT_EQ(guarding_.nextDeadline(), static_cast<Microseconds>(kStart + life));
  EXPECT_EQ(guarding_.process(guarding_.nextDeadline()), Event::kLifeTimeExpired);
}

}  // namespace
}  // namespace costa::test
