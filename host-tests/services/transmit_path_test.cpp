// TransmitPath alone: direct sends, the queue behind a refusing controller or a gate, expiry.
#include "costa/transmit_path.hpp"

#include <gtest/gtest.h>

#include "service_fixture.hpp"

namespace costa::test {
namespace {

using TransmitPathTest = ServiceTest;

const CanFrame kFirst = frame(0x181, {0x01});
const CanFrame kSecond = frame(0x182, {0x02, 0x03});
const CanFrame kThird = frame(0x183, {0x04, 0x05, 0x06});

TEST_F(TransmitPathTest, AFrameGoesToTheControllerAtOnceWhenNothingWaits) {
  tx_.send(kFirst);
  EXPECT_EQ(sent(), frames({kFirst}));
  EXPECT_FALSE(tx_.pending());
  EXPECT_EQ(tx_.refused(), 0U);
}

TEST_F(TransmitPathTest, ARefusedFrameIsQueuedAndFlushedLaterInOrder) {
  can_.setAccepting(false);
  tx_.send(kFirst);
  tx_.send(kSecond);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(tx_.queued(), 2U);
  EXPECT_EQ(tx_.refused(), 1U);  // the second one was not offered: the first waits ahead of it
  tx_.flush(kStart);             // still refused: nothing leaves, the refusal is counted
  EXPECT_EQ(tx_.refused(), 2U);
  can_.setAccepting(true);
  tx_.send(kThird);  // behind the waiting frames, although the controller has room again
  EXPECT_TRUE(sent().empty());
  tx_.flush(kStart);
  EXPECT_EQ(sent(), frames({kFirst, kSecond, kThird}));
  EXPECT_FALSE(tx_.pending());
}

TEST_F(TransmitPathTest, AFullQueueDropsTheNewestFrameAndCountsIt) {
  can_.setAccepting(false);
  for (uint32_t i = 0; i < kQueueDepth + 2U; ++i) {
    tx_.send(frame(0x100 + i, {static_cast<uint8_t>(i)}));
  }
  EXPECT_EQ(tx_.queued(), kQueueDepth);
  EXPECT_EQ(tx_.dropped(), 2U);
  can_.setAccepting(true);
  tx_.flush(kStart);
  EXPECT_EQ(sent(),
            frames({frame(0x100, {0}), frame(0x101, {1}), frame(0x102, {2}), frame(0x103, {3})}));
}

TEST_F(TransmitPathTest, AClosedGateHoldsEveryFrameUntilItOpensAndTheCallerFlushes) {
  tx_.setGate(TransmitPath::kBusOff, true);
  EXPECT_TRUE(tx_.held());
  tx_.send(kFirst);
  tx_.flush(kStart);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(tx_.refused(), 0U);  // held, not refused by the controller
  tx_.setGate(TransmitPath::kBusOff, false);
  EXPECT_FALSE(tx_.held());
  EXPECT_TRUE(sent().empty());  // opening alone sends nothing
  tx_.flush(kStart);
  EXPECT_EQ(sent(), frames({kFirst}));
}

TEST_F(TransmitPathTest, TransmissionResumesOnlyWhenEveryGateIsOpen) {
  tx_.setGate(TransmitPath::kBusOff, true);
  tx_.setGate(TransmitPath::kBitTiming, true);
  tx_.send(kFirst);
  tx_.setGate(TransmitPath::kBusOff, false);
  tx_.flush(kStart);
  EXPECT_TRUE(sent().empty());
  EXPECT_TRUE(tx_.held());
  tx_.setGate(TransmitPath::kBitTiming, false);
  tx_.flush(kStart);
  EXPECT_EQ(sent(), frames({kFirst}));
}

TEST_F(TransmitPathTest, AFrameWhoseExpiryHasPassedIsDroppedAtTheFlushAndCounted) {
  can_.setAccepting(false);
  tx_.send(kFirst, after(100));
  tx_.send(kSecond, after(300));
  tx_.send(kThird);
  can_.setAccepting(true);
  tx_.flush(after(200));  // kFirst is late; kSecond still in time; kThird never expires
  EXPECT_EQ(sent(), frames({kSecond, kThird}));
  EXPECT_EQ(tx_.expired(), 1U);
}

TEST_F(TransmitPathTest, AFrameIsStillSentAtItsExpiryTime) {
  can_.setAccepting(false);
  tx_.send(kFirst, after(100));
  can_.setAccepting(true);
  tx_.flush(after(100));
  EXPECT_EQ(sent(), frames({kFirst}));
  EXPECT_EQ(tx_.expired(), 0U);
}

TEST_F(TransmitPathTest, DiscardQueuedEmptiesTheQueueAndCountsWhatItHeld) {
  can_.setAccepting(false);
  tx_.send(kFirst);
  tx_.send(kSecond);
  tx_.discardQueued();
  EXPECT_FALSE(tx_.pending());
  EXPECT_EQ(tx_.discarded(), 2U);
  can_.setAccepting(true);
  tx_.flush(kStart);
  EXPECT_TRUE(sent().empty());
  tx_.send(kThird);  // the next frame goes straight out
  EXPECT_EQ(sent(), frames({kThird}));
}

TEST_F(TransmitPathTest, ABurstLeavesAQuarterOfTheQueueFree) {
  can_.setAccepting(false);
  EXPECT_TRUE(tx_.roomForBurst());
  for (size_t i = 0; i < kQueueDepth - kQueueDepth / 4U; ++i) {
    EXPECT_TRUE(tx_.roomForBurst()) << i;
    tx_.send(kFirst);
  }
  EXPECT_FALSE(tx_.roomForBurst());
  EXPECT_EQ(tx_.queued(), 3U);
}

}  // namespace
}  // namespace costa::test
