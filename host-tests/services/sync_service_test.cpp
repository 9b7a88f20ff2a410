// SyncService alone: consumer (EMCY 0x8240, window), producer (period, counter), parameter rules.
#include "costa/sync_service.hpp"

#include <gtest/gtest.h>

#include "costa/emcy_producer.hpp"
#include "costa/frame_router.hpp"
#include "service_fixture.hpp"

namespace costa::test {
namespace {

class SyncServiceTest : public ServiceTest {
 protected:
  SyncServiceTest()
      : emcy_(dictionary_, emcyProfile_, clock_, conditions_, 4, pending_, 4),
        router_(routes_, 4),
        sync_(dictionary_, tx_, emcy_, clock_, router_) {
    emcy_.setNodeId(kNodeId);
  }

  /// Makes this node the SYNC producer with `periodUs`, configured at kStart.
  void produce(uint32_t periodUs, uint8_t overflow = 0) {
    store(0x1005, 0, 0x40000080U);
    store(0x1006, 0, periodUs);
    store(0x1019, 0, overflow);
    sync_.configure(kStart);
  }
  void sendEmcy() { emcy_.process(clock_.now, NmtState::kOperational, tx_); }

  EmcyProfile emcyProfile_;
  EmcyCondition conditions_[4];
  PendingEmcy pending_[4];
  EmcyProducer emcy_;
  RouteEntry routes_[4];
  FrameRouter router_;
  SyncService sync_;
  SyncEvent event_;
};

TEST_F(SyncServiceTest, TheConsumerTakesDataFramesOnTheSyncCobIdOnly) {
  sync_.configure(kStart);
  EXPECT_EQ(sync_.canId(), 0x080U);
  EXPECT_FALSE(sync_.producer());
  EXPECT_EQ(sync_.nextDeadline(), kNever);
  EXPECT_TRUE(sync_.accepts(frame(0x080, {})));
  EXPECT_FALSE(sync_.accepts(remote(0x080)));
  CanFrame extended = frame(0x080, {});
  extended.extended = true;
  EXPECT_FALSE(sync_.accepts(extended));
  EXPECT_FALSE(sync_.accepts(frame(0x081, {})));
}

TEST_F(SyncServiceTest, AReceivedSyncGivesItsTimeAndTheEndOfTheWindow) {
  store(0x1007, 0, 2000);
  sync_.configure(kStart);
  EXPECT_TRUE(sync_.onFrame(frame(0x080, {}), after(500), &event_));
  EXPECT_EQ(event_.counter, 0U);
  EXPECT_EQ(event_.time, after(500));
  EXPECT_EQ(event_.windowEnd, after(2500));
  store(0x1007, 0, 0);  // no window: synchronous PDOs never expire
  sync_.configure(kStart);
  EXPECT_TRUE(sync_.onFrame(frame(0x080, {}), after(600), &event_));
  EXPECT_EQ(event_.windowEnd, kNever);
  EXPECT_TRUE(sent().empty());
}

TEST_F(SyncServiceTest, ALengthThatDoesNotMatchTheCounterSettingRaisesEmcy8240) {
  sync_.configure(kStart);
  EXPECT_FALSE(sync_.onFrame(frame(0x080, {0x01}), kStart, &event_));
  EXPECT_TRUE(emcy_.active(SyncService::kEmcyUnexpectedLength, 0));
  EXPECT_TRUE(sync_.onFrame(frame(0x080, {}), kStart, &event_));  // a right one clears it
  EXPECT_FALSE(emcy_.active(SyncService::kEmcyUnexpectedLength, 0));
  sendEmcy();
  EXPECT_EQ(sent(), frames({frame8(0x85, {0x40, 0x82, 0x11}), frame8(0x85, {})}));
}

TEST_F(SyncServiceTest, WithACounterOverflowValueTheSyncCarriesTheCounter) {
  store(0x1019, 0, 3);
  sync_.configure(kStart);
  EXPECT_FALSE(sync_.onFrame(frame(0x080, {}), kStart, &event_));
  EXPECT_TRUE(sync_.onFrame(frame(0x080, {0x02}), kStart, &event_));
  EXPECT_EQ(event_.counter, 2U);
}

TEST_F(SyncServiceTest, TheProducerSendsEveryPeriod) {
  produce(10000);
  EXPECT_TRUE(sync_.producer());
  EXPECT_EQ(sync_.nextDeadline(), after(10000));
  EXPECT_EQ(clock_.next, after(10000));
  EXPECT_FALSE(sync_.process(after(9999), true, &event_));
  EXPECT_TRUE(sync_.process(after(10000), true, &event_));
  EXPECT_EQ(event_.counter, 0U);
  EXPECT_EQ(event_.time, after(10000));
  EXPECT_EQ(sync_.nextDeadline(), after(20000));
  EXPECT_TRUE(sync_.process(after(20000), true, &event_));
  EXPECT_EQ(sent(), frames({frame(0x080, {}), frame(0x080, {})}));
}

TEST_F(SyncServiceTest, TheProducersCounterRunsFromOneToTheOverflowValue) {
  produce(1000, 3);
  for (uint32_t i = 1; i <= 4U; ++i) {
    EXPECT_TRUE(sync_.process(after(1000 * i), true, &event_)) << i;
  }
  EXPECT_EQ(event_.counter, 1U);
  EXPECT_EQ(sent(),
            frames({frame(0x080, {1}), frame(0x080, {2}), frame(0x080, {3}), frame(0x080, {1})}));
}

TEST_F(SyncServiceTest, WhileNotAllowedTheProducerKeepsItsRhythmSilently) {
  produce(1000);
  EXPECT_FALSE(sync_.process(after(1000), false, &event_));
  EXPECT_EQ(sync_.nextDeadline(), after(2000));
  EXPECT_TRUE(sync_.process(after(2000), true, &event_));
  EXPECT_EQ(sent(), frames({frame(0x080, {})}));
}

TEST_F(SyncServiceTest, ALateProducerKeepsItsRhythmUnlessLateByAPeriod) {
  produce(1000);
  EXPECT_TRUE(sync_.process(after(1300), true, &event_));
  EXPECT_EQ(sync_.nextDeadline(), after(2000));
  EXPECT_TRUE(sync_.process(after(3500), true, &event_));
  EXPECT_EQ(sync_.nextDeadline(), after(4500));
}

TEST_F(SyncServiceTest, APeriodLongerThan35MinutesIsWaitedInSteps) {
  const uint32_t period = 3000000000U;  // 50 min
  produce(period);
  EXPECT_EQ(sync_.nextDeadline(), after(kLongestDelay));
  EXPECT_FALSE(sync_.process(after(kLongestDelay), true, &event_));
  EXPECT_EQ(sync_.nextDeadline(), after(period));
  EXPECT_TRUE(sync_.process(after(period), true, &event_));
  EXPECT_EQ(sent(), frames({frame(0x080, {})}));
}

TEST_F(SyncServiceTest, CobIdWritesRefuse29BitRestrictedAndChangesWhileProducing) {
  sync_.configure(kStart);
  EXPECT_EQ(write(sync_, 0x1005, 0, 0x20000080U, 4), AbortCode::kInvalidValue);
  EXPECT_EQ(write(sync_, 0x1005, 0, 0x601U, 4), AbortCode::kInvalidValue);  // an SDO CAN-ID
  EXPECT_EQ(write(sync_, 0x1005, 0, 0x40000080U, 4), AbortCode::kNone);
  EXPECT_TRUE(sync_.producer());
  EXPECT_EQ(write(sync_, 0x1005, 0, 0x40000090U, 4), AbortCode::kInvalidValue);
  EXPECT_EQ(write(sync_, 0x1005, 0, 0x90U, 4), AbortCode::kNone);  // stop, then change
  EXPECT_EQ(sync_.canId(), 0x090U);
  EXPECT_FALSE(sync_.producer());
  EXPECT_EQ(value(0x1005, 0), 0x90U);
}

TEST_F(SyncServiceTest, TheCounterOverflowIsZeroOrTwoTo240AndChangesOnlyWithoutAPeriod) {
  sync_.configure(kStart);
  EXPECT_EQ(write(sync_, 0x1019, 0, 1, 1), AbortCode::kInvalidValue);
  EXPECT_EQ(write(sync_, 0x1019, 0, 241, 1), AbortCode::kInvalidValue);
  EXPECT_EQ(write(sync_, 0x1019, 0, 240, 1), AbortCode::kNone);
  EXPECT_EQ(write(sync_, 0x1006, 0, 1000, 4), AbortCode::kNone);
  EXPECT_EQ(write(sync_, 0x1019, 0, 2, 1), AbortCode::kCannotStoreState);
  EXPECT_EQ(value(0x1019, 0), 240U);
}

TEST_F(SyncServiceTest, AnAcceptedWriteReconfiguresFromTheTimeOfTheWriteAndTellsTheRoutes) {
  sync_.configure(kStart);
  router_.clear();
  EXPECT_FALSE(router_.stale());
  clock_.advance(after(700));
  EXPECT_EQ(write(sync_, 0x1005, 0, 0x40000080U, 4), AbortCode::kNone);
  EXPECT_TRUE(router_.stale());
  EXPECT_EQ(write(sync_, 0x1006, 0, 1000, 4), AbortCode::kNone);
  EXPECT_EQ(sync_.nextDeadline(), after(1700));
  EXPECT_EQ(write(sync_, 0x1006, 0, 1000, 2), AbortCode::kLengthTooLow);
}

}  // namespace
}  // namespace costa::test
