// PdoEngine alone, transmit side: events, inhibit time, event timer, SYNC types, remote requests.
#include <gtest/gtest.h>

#include "pdo_fixture.hpp"

namespace costa::test {
namespace {

using PdoTransmit = PdoEngineTest;

const CanFrame kTpdo1 = frame(0x185, {0x34, 0x12, 0xEF, 0xCD, 0xAB, 0x89});
const CanFrame kTpdo2 = frame(0x285, {0x34, 0x12});

TEST_F(PdoTransmit, AnEventDrivenTpdoIsSentWhenAMappedEntryChanges) {
  pdos_.start(kStart);
  EXPECT_EQ(pdos_.nextDeadline(), kNever);
  pdos_.markChanged(0x2000, 1);  // not mapped by any TPDO
  EXPECT_EQ(pdos_.nextDeadline(), kNever);
  pdos_.markChanged(0x2001, 2);
  EXPECT_EQ(pdos_.nextDeadline(), kStart);  // at once
  EXPECT_EQ(clock_.next, kStart);
  pdos_.process(kStart);
  EXPECT_EQ(sent(), frames({kTpdo1}));
  EXPECT_EQ(pdos_.nextDeadline(), kNever);
}

TEST_F(PdoTransmit, AnApplicationRequestSendsTheTpdoWithItsCurrentValues) {
  pdos_.start(kStart);
  od_.values.x2001_transmitted_values.status = 0xBEEF;
  EXPECT_TRUE(pdos_.requestTransmission(0x1800));
  EXPECT_FALSE(pdos_.requestTransmission(0x1802));
  pdos_.process(kStart);
  EXPECT_EQ(sent(), frames({frame(0x185, {0xEF, 0xBE, 0xEF, 0xCD, 0xAB, 0x89})}));
}

TEST_F(PdoTransmit, NoEventIsTakenWhileNotOperational) {
  pdos_.markChanged(0x2001, 1);
  pdos_.start(kStart);
  pdos_.process(kStart);
  pdos_.stop();
  EXPECT_TRUE(pdos_.requestTransmission(0x1800));  // the TPDO exists, but it is stopped
  pdos_.process(kStart);
  EXPECT_TRUE(sent().empty());
}

TEST_F(PdoTransmit, TheInhibitTimeDelaysTheNextTransmission) {
  invalidate(0x1800, 0x185);
  EXPECT_EQ(write(pdos_, 0x1800, 3, 10, 2), AbortCode::kNone);  // 1 ms
  validate(0x1800, 0x185);
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.requestTransmission(0x1800));
  pdos_.process(kStart);
  EXPECT_TRUE(pdos_.requestTransmission(0x1800));
  pdos_.process(after(999));
  EXPECT_EQ(pdos_.nextDeadline(), after(1000));
  pdos_.process(after(1000));
  EXPECT_EQ(sent(), frames({kTpdo1, kTpdo1}));
}

TEST_F(PdoTransmit, TheEventTimerSendsWithoutEvents) {
  EXPECT_EQ(write(pdos_, 0x1800, 5, 50, 2), AbortCode::kNone);
  pdos_.start(kStart);
  EXPECT_EQ(pdos_.nextDeadline(), afterMs(50));
  pdos_.process(afterMs(50));
  EXPECT_EQ(pdos_.nextDeadline(), afterMs(100));
  pdos_.process(afterMs(100));
  EXPECT_EQ(sent(), frames({kTpdo1, kTpdo1}));
}

TEST_F(PdoTransmit, ASynchronousTpdoIsSentAtEverySyncOfItsType) {
  pdos_.start(kStart);
  pdos_.onSync(0, after(100), kNever);
  EXPECT_EQ(sent(), frames({kTpdo2}));
  EXPECT_EQ(write(pdos_, 0x1801, 2, 3, 1), AbortCode::kNone);
  for (uint32_t i = 1; i <= 6U; ++i) {
    pdos_.onSync(0, after(100 * i), kNever);
  }
  EXPECT_EQ(sent(), frames({kTpdo2, kTpdo2}));  // the 3rd and the 6th
  pdos_.markChanged(0x2001, 1);  // TPDO 1 (event-driven) maps it too; TPDO 2 takes no events
  pdos_.process(after(800));
  EXPECT_EQ(sent(), frames({kTpdo1}));
}

TEST_F(PdoTransmit, ASynchronousTpdoThatMissesTheSyncWindowIsDroppedAndCounted) {
  pdos_.start(kStart);
  can_.setAccepting(false);
  pdos_.onSync(0, after(100), after(600));
  can_.setAccepting(true);
  tx_.flush(after(601));
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(tx_.expired(), 1U);
}

TEST_F(PdoTransmit, ASyncStartValueDelaysTheFirstTransmissionToThatCounter) {
  invalidate(0x1801, 0x285);
  EXPECT_EQ(write(pdos_, 0x1801, 6, 3, 1), AbortCode::kNone);
  validate(0x1801, 0x285);
  pdos_.start(kStart);
  pdos_.onSync(1, after(100), kNever);
  pdos_.onSync(2, after(200), kNever);
  EXPECT_TRUE(sent().empty());
  pdos_.onSync(3, after(300), kNever);
  pdos_.onSync(4, after(400), kNever);
  EXPECT_EQ(sent(), frames({kTpdo2, kTpdo2}));
}

TEST_F(PdoTransmit, AnAcyclicTpdoIsSentAtTheSyncAfterAnEvent) {
  EXPECT_EQ(write(pdos_, 0x1801, 2, 0, 1), AbortCode::kNone);
  pdos_.start(kStart);
  pdos_.onSync(0, after(100), kNever);
  EXPECT_TRUE(sent().empty());
  pdos_.markChanged(0x2001, 1);
  pdos_.process(after(150));  // TPDO 1 (event-driven) at once, TPDO 2 not before the SYNC
  EXPECT_EQ(sent(), frames({kTpdo1}));
  pdos_.onSync(0, after(200), kNever);
  pdos_.onSync(0, after(300), kNever);
  EXPECT_EQ(sent(), frames({kTpdo2}));
}

TEST_F(PdoTransmit, TheProfileMaySendTypeZeroAtEverySync) {
  profile_.tpdoType0 = TpdoType0::kEverySync;
  EXPECT_EQ(write(pdos_, 0x1801, 2, 0, 1), AbortCode::kNone);
  pdos_.start(kStart);
  pdos_.onSync(0, after(100), kNever);
  pdos_.onSync(0, after(200), kNever);
  EXPECT_EQ(sent(), frames({kTpdo2, kTpdo2}));
}

TEST_F(PdoTransmit, ARemoteRequestIsAnsweredByEventDrivenTpdosThatAllowIt) {
  EXPECT_FALSE(pdos_.remoteRequest(0, kStart));  // not running
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.remoteRequest(0, kStart));
  EXPECT_TRUE(pdos_.remoteRequest(1, kStart));  // synchronous: not answered under CiA 301
  EXPECT_EQ(sent(), frames({kTpdo1}));
  invalidate(0x1800, 0x185);
  EXPECT_FALSE(pdos_.remoteRequest(0, kStart));
  validate(0x1800, 0x40000185U);  // bit 30: no RTR allowed
  EXPECT_TRUE(pdos_.remoteRequest(0, kStart));
  EXPECT_TRUE(sent().empty());
}

TEST_F(PdoTransmit, TheProfileMayAnswerRemoteRequestsForEveryType) {
  profile_.tpdoRtrTypes = TpdoRtrTypes::kAllTypes;
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.remoteRequest(1, kStart));
  EXPECT_EQ(sent(), frames({kTpdo2}));
}

TEST_F(PdoTransmit, AnRtrOnlyTpdoOfType252SendsWhatItSampledAtTheSync) {
  EXPECT_EQ(write(pdos_, 0x1801, 2, 252, 1), AbortCode::kNone);
  pdos_.start(kStart);
  pdos_.onSync(0, after(100), kNever);
  EXPECT_TRUE(sent().empty());
  od_.values.x2001_transmitted_values.status = 0x5678;  // after the SYNC: not sent
  EXPECT_TRUE(pdos_.remoteRequest(1, after(200)));
  EXPECT_EQ(sent(), frames({kTpdo2}));
}

TEST_F(PdoTransmit, TheProfileMaySendEventDrivenTpdosOnEnteringOperational) {
  profile_.tpdoOnEnteringOperational = true;
  pdos_.start(kStart);
  pdos_.process(kStart);
  EXPECT_EQ(sent(), frames({kTpdo1}));
}

TEST_F(PdoTransmit, AnInvalidTpdoSendsNothing) {
  invalidate(0x1800, 0x185);
  invalidate(0x1801, 0x285);
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.requestTransmission(0x1800));
  pdos_.process(kStart);
  pdos_.onSync(0, after(100), kNever);
  EXPECT_TRUE(sent().empty());
}

}  // namespace
}  // namespace costa::test
