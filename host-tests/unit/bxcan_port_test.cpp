// The bxCAN driver against a simulated register block: start-up, filter, transmit mailboxes and
// receive FIFO, register by register.
#include <gtest/gtest.h>

#include <initializer_list>

#include "costa/port/stm32/bxcan_port.hpp"
#include "simulated_bxcan.hpp"

namespace costa::test {
namespace {

using namespace port::stm32;
using namespace port::stm32::bxcan;

constexpr uint32_t kBtr = 0x011C0003;  // 250 kbit/s at 16 MHz
constexpr uint32_t kWaitLimit = 50;
constexpr uint32_t kUntouched = 0xA5A5A5A5;

class BxCanPortTest : public ::testing::Test {
 protected:
  BxCanPortTest() : port_(sim_.registers, kWaitLimit) { sim_.attach(port_); }

  void fillMailboxes() {
    for (BxCanTxMailbox& box : sim_.registers.tx) {
      box.tir = kUntouched;
      box.tdtr = kUntouched;
      box.tdlr = kUntouched;
      box.tdhr = kUntouched;
    }
  }
  bool untouched(const BxCanTxMailbox& box) {
    return box.tir == kUntouched && box.tdtr == kUntouched && box.tdlr == kUntouched &&
           box.tdhr == kUntouched;
  }

  SimulatedBxCan sim_;
  BxCanPort port_;
};

CanFrame frame(uint32_t id, uint8_t dlc, std::initializer_list<uint8_t> bytes = {}) {
  CanFrame f;
  f.id = id;
  f.dlc = dlc;
  size_t i = 0;
  for (uint8_t byte : bytes) {
    f.data[i++] = byte;
  }
  return f;
}

/// A frame whose every field differs from what the tests receive.
CanFrame garbage() {
  CanFrame f = frame(0x5AA, 8, {0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE});
  f.rtr = true;
  f.extended = true;
  return f;
}

// --- start ---------------------------------------------------------------------------------

TEST_F(BxCanPortTest, StartLeavesSleepConfiguresInInitialisationAndJoinsTheBus) {
  ASSERT_TRUE(port_.start(kBtr));
  EXPECT_EQ(sim_.registers.mcr, mcr::kDbf | mcr::kAbom | mcr::kTxfp);  // NART, RFLM, TTCM off
  EXPECT_EQ(sim_.registers.msr & (msr::kInak | msr::kSlak), 0U);
  EXPECT_EQ(sim_.registers.btr, kBtr);
  ASSERT_EQ(sim_.samples.size(), 2U);  // one read to enter, one to leave
  // Entering: initialisation requested and sleep left in the same write; nothing set up yet.
  EXPECT_EQ(sim_.samples[0].mcr, mcr::kDbf | mcr::kInrq);
  EXPECT_EQ(sim_.samples[0].btr, SimulatedBxCan::kBtrReset);
  // Leaving: bit timing and filters were set while in initialisation, filter init mode is over.
  EXPECT_EQ(sim_.samples[1].mcr, mcr::kDbf | mcr::kAbom | mcr::kTxfp);
  EXPECT_EQ(sim_.samples[1].msr & msr::kInak, msr::kInak);
  EXPECT_EQ(sim_.samples[1].btr, kBtr);
  EXPECT_EQ(sim_.samples[1].fmr & fmr::kFinit, 0U);
  EXPECT_EQ(sim_.samples[1].fa1r & 1U, 1U);
}

TEST_F(BxCanPortTest, StartKeepsTheDebugFreezeBitAsFound) {
  sim_.registers.mcr = mcr::kSleep;  // DBF cleared by the application
  ASSERT_TRUE(port_.start(kBtr));
  EXPECT_EQ(sim_.registers.mcr, mcr::kAbom | mcr::kTxfp);
}

TEST_F(BxCanPortTest, StartWaitsForASlowAcknowledge) {
  sim_.latency = 7;
  ASSERT_TRUE(port_.start(kBtr));
  EXPECT_EQ(sim_.samples.size(), 16U);  // 8 reads each way
  EXPECT_EQ(sim_.registers.msr & msr::kInak, 0U);
}

TEST_F(BxCanPortTest, StartGivesUpAfterTheBoundWhenTheControllerNeverAcknowledges) {
  sim_.dead = true;
  EXPECT_FALSE(port_.start(kBtr));
  EXPECT_EQ(sim_.samples.size(), kWaitLimit);
  EXPECT_EQ(sim_.registers.btr, SimulatedBxCan::kBtrReset);  // nothing configured outside init
  EXPECT_EQ(sim_.registers.fmr, SimulatedBxCan::kFmrReset);
}

TEST_F(BxCanPortTest, StartGivesUpAfterTheBoundWhenTheBusNeverGoesIdle) {
  sim_.busStuckDominant = true;
  EXPECT_FALSE(port_.start(kBtr));
  EXPECT_EQ(sim_.samples.size(), 1U + kWaitLimit);
  EXPECT_EQ(sim_.registers.mcr & mcr::kInrq, 0U);  // joins by itself once the bus is idle
  EXPECT_EQ(sim_.registers.btr, kBtr);
}

TEST_F(BxCanPortTest, StartSetsUpFilterBankZeroAndLeavesTheOtherBanks) {
  sim_.registers.fm1r = (1U << 14) | 1U;  // bank 0 in list mode, bank 14 (CAN2) too
  sim_.registers.fs1r = 1U << 14;
  sim_.registers.ffa1r = (1U << 14) | 1U;
  sim_.registers.fa1r = 1U << 14;
  sim_.registers.filter[0].fr1 = 0x12345678;
  sim_.registers.filter[0].fr2 = 0xFFFFFFFF;
  sim_.registers.filter[14].fr1 = 0x0BADF00D;
  ASSERT_TRUE(port_.start(kBtr));
  EXPECT_EQ(sim_.registers.fmr, SimulatedBxCan::kFmrReset & ~fmr::kFinit);  // CAN2SB kept
  EXPECT_EQ(sim_.registers.fm1r, 1U << 14);                                 // bank 0: mask mode
  EXPECT_EQ(sim_.registers.fs1r, (1U << 14) | 1U);                          // bank 0: 32 bits
  EXPECT_EQ(sim_.registers.ffa1r, 1U << 14);                                // bank 0: FIFO 0
  EXPECT_EQ(sim_.registers.fa1r, (1U << 14) | 1U);                          // bank 0: active
  EXPECT_EQ(sim_.registers.filter[0].fr1, 0U);                              // identifier
  EXPECT_EQ(sim_.registers.filter[0].fr2, 0U);  // mask: no bit must match
  EXPECT_EQ(sim_.registers.filter[14].fr1, 0x0BADF00DU);
}

// --- transmit ------------------------------------------------------------------------------

TEST_F(BxCanPortTest, TransmitsAStandardDataFrameThroughMailboxZero) {
  fillMailboxes();
  ASSERT_TRUE(port_.tryTransmit(frame(0x701, 1, {0x05})));
  EXPECT_EQ(sim_.registers.tx[0].tir, 0xE0200001U);  // 0x701 << 21, TXRQ
  EXPECT_EQ(sim_.registers.tx[0].tdtr, 1U);
  EXPECT_EQ(sim_.registers.tx[0].tdlr, 0x00000005U);
  EXPECT_EQ(sim_.registers.tx[0].tdhr, 0x00000000U);
  EXPECT_TRUE(untouched(sim_.registers.tx[1]));
  EXPECT_TRUE(untouched(sim_.registers.tx[2]));
}

TEST_F(BxCanPortTest, TransmitsAnExtendedFrameWithDataLittleEndian) {
  CanFrame f = frame(0x1ABCDEF0, 8, {0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88});
  f.extended = true;
  ASSERT_TRUE(port_.tryTransmit(f));
  EXPECT_EQ(sim_.registers.tx[0].tir, 0xD5E6F785U);  // 0x1ABCDEF0 << 3, IDE, TXRQ
  EXPECT_EQ(sim_.registers.tx[0].tdtr, 8U);
  EXPECT_EQ(sim_.registers.tx[0].tdlr, 0x44332211U);
  EXPECT_EQ(sim_.registers.tx[0].tdhr, 0x88776655U);
}

TEST_F(BxCanPortTest, TransmitsRemoteFrames) {
  CanFrame f = frame(0x701, 1);
  f.rtr = true;
  ASSERT_TRUE(port_.tryTransmit(f));
  EXPECT_EQ(sim_.registers.tx[0].tir, 0xE0200003U);  // RTR, TXRQ
  EXPECT_EQ(sim_.registers.tx[0].tdtr, 1U);
  f.id = 0x1FFFFFFF;
  f.extended = true;
  f.dlc = 0;
  ASSERT_TRUE(port_.tryTransmit(f));
  EXPECT_EQ(sim_.registers.tx[0].tir, 0xFFFFFFFFU);
  EXPECT_EQ(sim_.registers.tx[0].tdtr, 0U);
}

TEST_F(BxCanPortTest, IdentifierBitsBeyondTheFormatAndDlcAboveEightAreCut) {
  ASSERT_TRUE(port_.tryTransmit(frame(0xF123, 15)));
  EXPECT_EQ(sim_.registers.tx[0].tir, 0x24600001U);  // 0x123 << 21: no IDE, no RTR
  EXPECT_EQ(sim_.registers.tx[0].tdtr, 8U);
}

TEST_F(BxCanPortTest, UsesTheFirstEmptyMailbox) {
  fillMailboxes();
  sim_.registers.tsr = tsr::tme(1) | tsr::tme(2) | tsr::txok(0);
  ASSERT_TRUE(port_.tryTransmit(frame(0x181, 2, {0xAA, 0xBB})));
  EXPECT_TRUE(untouched(sim_.registers.tx[0]));
  EXPECT_EQ(sim_.registers.tx[1].tir, 0x30200001U);  // 0x181 << 21, TXRQ
  EXPECT_EQ(sim_.registers.tx[1].tdtr, 2U);
  EXPECT_EQ(sim_.registers.tx[1].tdlr, 0x0000BBAAU);
  EXPECT_TRUE(untouched(sim_.registers.tx[2]));

  fillMailboxes();
  sim_.registers.tsr = tsr::tme(2);
  ASSERT_TRUE(port_.tryTransmit(frame(0x182, 0)));
  EXPECT_TRUE(untouched(sim_.registers.tx[0]));
  EXPECT_TRUE(untouched(sim_.registers.tx[1]));
  EXPECT_EQ(sim_.registers.tx[2].tir, 0x30400001U);
}

TEST_F(BxCanPortTest, RefusesWithoutSideEffectsWhenAllMailboxesArePending) {
  fillMailboxes();
  const uint32_t pending = tsr::low(2) | (2U << tsr::kCodeShift) | tsr::txok(0) | tsr::rqcp(1);
  sim_.registers.tsr = pending;
  EXPECT_FALSE(port_.tryTransmit(frame(0x701, 1, {0x7F})));
  for (const BxCanTxMailbox& box : sim_.registers.tx) {
    EXPECT_TRUE(untouched(box));
  }
  EXPECT_EQ(sim_.registers.tsr, pending);
}

// --- receive -------------------------------------------------------------------------------

TEST_F(BxCanPortTest, ReceiveReportsNothingWhenTheFifoIsEmpty) {
  sim_.registers.rf0r = rfr::kFovr;  // an overrun is poll()'s business, not a message
  CanFrame f = frame(0x123, 2, {1, 2});
  EXPECT_FALSE(port_.receive(&f));
  EXPECT_EQ(sim_.registers.rf0r, rfr::kFovr);  // nothing released
  EXPECT_EQ(f.id, 0x123U);                     // nothing written
  EXPECT_EQ(f.data[1], 2U);
}

TEST_F(BxCanPortTest, ReceivesAStandardDataFrameAndReleasesTheMailbox) {
  // SDO upload request 601 [8] 40 00 10 00 00 00 00 00, filter 0, time stamp 0x1234.
  sim_.receive(0xC0200000, 0x12340008, 0x00100040, 0x00000000, 2);
  CanFrame f;
  ASSERT_TRUE(port_.receive(&f));
  EXPECT_TRUE(sameOnWire(f, frame(0x601, 8, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0})));
  EXPECT_FALSE(f.extended);
  EXPECT_FALSE(f.rtr);
  EXPECT_EQ(sim_.registers.rf0r, rfr::kRfom);  // exactly the release bit written
}

TEST_F(BxCanPortTest, ReceivesAnExtendedRemoteFrameWithZeroData) {
  sim_.receive(0xFFFFFFFE, 0x00000002, 0xDEADBEEF, 0xDEADBEEF);  // id 0x1FFFFFFF, IDE, RTR
  CanFrame f = garbage();
  ASSERT_TRUE(port_.receive(&f));
  EXPECT_EQ(f.id, 0x1FFFFFFFU);
  EXPECT_TRUE(f.extended);
  EXPECT_TRUE(f.rtr);
  EXPECT_EQ(f.dlc, 2U);
  for (uint8_t byte : f.data) {
    EXPECT_EQ(byte, 0U);
  }
  EXPECT_EQ(sim_.registers.rf0r, rfr::kRfom);
}

TEST_F(BxCanPortTest, ZeroesTheBytesAfterTheDlc) {
  sim_.receive(0x0E000000, 0x00000003, 0xDDCCBBAA, 0x11223344);  // id 0x070
  CanFrame f = garbage();
  ASSERT_TRUE(port_.receive(&f));
  EXPECT_EQ(f.id, 0x070U);
  EXPECT_FALSE(f.extended);
  EXPECT_FALSE(f.rtr);
  EXPECT_EQ(f.dlc, 3U);
  const uint8_t expected[8] = {0xAA, 0xBB, 0xCC, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(f.data[i], expected[i]) << "byte " << i;
  }
}

TEST_F(BxCanPortTest, PassesADlcAboveEightOnWithEightBytes) {
  sim_.receive(0xC0200000, 0x0000000F, 0x04030201, 0x08070605);
  CanFrame f;
  ASSERT_TRUE(port_.receive(&f));
  EXPECT_EQ(f.dlc, 15U);
  EXPECT_EQ(f.data[0], 0x01U);
  EXPECT_EQ(f.data[7], 0x08U);
}

}  // namespace
}  // namespace costa::test
