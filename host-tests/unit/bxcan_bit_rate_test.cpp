// The bxCAN driver re-timing a running controller (CanBitRateControl), register by register on
// a simulated block, and the example node switching CAN_BTR through it on LSS activate bit
// timing.
#include <gtest/gtest.h>

#include "allocation_guard.hpp"
#include "costa/port/stm32/bxcan_bit_timing.hpp"
#include "costa/port/stm32/bxcan_port.hpp"
#include "example_target.hpp"
#include "simulated_bxcan.hpp"

namespace costa::test {
namespace {

using namespace port::stm32;
using namespace port::stm32::bxcan;

constexpr uint32_t kClock = 16000000;
constexpr uint32_t kBtr250 = 0x011C0003;  // 250 kbit/s at 16 MHz: prescaler 4, 16 tq, 87.5 %
constexpr uint32_t kBtr500 = 0x011C0001;  // 500 kbit/s at 16 MHz: prescaler 2, 16 tq, 87.5 %
constexpr uint32_t kWaitLimit = 50;
constexpr uint32_t kRunningMcr = mcr::kDbf | mcr::kAbom | mcr::kTxfp;

static_assert(bxCanBitTiming(kClock, 250000).btr() == kBtr250);

class BxCanBitRateTest : public ::testing::Test {
 protected:
  BxCanBitRateTest() : port_(sim_.registers, kWaitLimit) { sim_.attach(port_); }

  SimulatedBxCan sim_;
  BxCanPort port_;
};

TEST_F(BxCanBitRateTest, ReTimesTheRunningControllerInInitialisationMode) {
  ASSERT_TRUE(port_.start(kBtr250, kClock));
  const uint32_t fmr = sim_.registers.fmr;
  const uint32_t fa1r = sim_.registers.fa1r;
  sim_.samples.clear();
  ASSERT_TRUE(port_.setBitRate(500000));
  EXPECT_EQ(sim_.registers.btr, kBtr500);
  EXPECT_EQ(sim_.registers.mcr, kRunningMcr);  // initialisation left, nothing else changed
  ASSERT_EQ(sim_.samples.size(), 1U);          // one read to enter; leaving is not waited for
  EXPECT_EQ(sim_.samples[0].mcr, kRunningMcr | mcr::kInrq);
  EXPECT_EQ(sim_.samples[0].btr, kBtr250);  // CAN_BTR written only once INAK was seen
  EXPECT_EQ(sim_.registers.fmr, fmr);       // filters as start() left them
  EXPECT_EQ(sim_.registers.fa1r, fa1r);
  ASSERT_TRUE(port_.setBitRate(1000000));  // and again, from the new rate
  EXPECT_EQ(sim_.registers.btr, bxCanBitTiming(kClock, 1000000).btr());
  EXPECT_EQ(sim_.registers.btr, 0x011C0000U);  // prescaler 1
}

TEST_F(BxCanBitRateTest, KeepsTheLoopBackAndSilentBits) {
  ASSERT_TRUE(port_.start(kBtr250 | btr::kLbkm | btr::kSilm, kClock));
  ASSERT_TRUE(port_.setBitRate(500000));
  EXPECT_EQ(sim_.registers.btr, kBtr500 | btr::kLbkm | btr::kSilm);
}

TEST_F(BxCanBitRateTest, RefusesWithoutTouchingTheControllerWhenItCannotKnowTheTiming) {
  EXPECT_FALSE(port_.setBitRate(500000));  // not started
  EXPECT_EQ(sim_.registers.mcr, SimulatedBxCan::kMcrReset);
  EXPECT_EQ(sim_.registers.btr, SimulatedBxCan::kBtrReset);
  ASSERT_TRUE(port_.start(kBtr250));  // no clock given
  sim_.samples.clear();
  EXPECT_FALSE(port_.setBitRate(500000));
  ASSERT_TRUE(port_.start(kBtr250, 42000000));
  sim_.samples.clear();
  EXPECT_FALSE(port_.setBitRate(800000));  // 52.5 clocks per bit
  EXPECT_FALSE(port_.setBitRate(0));
  EXPECT_TRUE(sim_.samples.empty());
  EXPECT_EQ(sim_.registers.mcr, kRunningMcr);
  EXPECT_EQ(sim_.registers.btr, kBtr250);
}

TEST_F(BxCanBitRateTest, GivesUpAndWithdrawsTheRequestWhenTheControllerNeverAcknowledges) {
  ASSERT_TRUE(port_.start(kBtr250, kClock));
  sim_.samples.clear();
  sim_.dead = true;
  EXPECT_FALSE(port_.setBitRate(500000));
  EXPECT_EQ(sim_.samples.size(), kWaitLimit);
  EXPECT_EQ(sim_.registers.btr, kBtr250);
  EXPECT_EQ(sim_.registers.mcr, kRunningMcr);
}

// --- the example node re-timing CAN1 -------------------------------------------------------

DeviceConfig configFor(BxCanPort& port) {
  DeviceConfig config;
  config.bitRateControl = &port;
  return config;
}

class NodeOverBxCanBitRateTest : public BxCanBitRateTest {
 protected:
  NodeOverBxCanBitRateTest() : target_(port_, configFor(port_)) {}
  void SetUp() override {
    ASSERT_TRUE(port_.start(kBtr250, kClock));
    sim_.samples.clear();
    sim_.samples.reserve(64);  // the simulation's record must not allocate inside the scope
    NoAllocationScope scope;
    target_.start(0);
  }

  /// Delivers one LSS request (7E5, DLC 8, bytes 0..3 as `low`) and runs the node at `now`.
  void lssRequest(uint32_t low, Microseconds now) {
    sim_.receive(0x7E5U << 21, 8, low, 0);
    NoAllocationScope scope;
    CanFrame frame;
    while (port_.receive(&frame)) {
      target_.onFrame(frame, now);
    }
    target_.process(now);
  }
  void process(Microseconds now) {
    NoAllocationScope scope;
    target_.process(now);
  }

  example::ExampleTarget target_;
};

TEST_F(NodeOverBxCanBitRateTest, LssActivateBitTimingWritesCanBtrAtTheSwitchMoment) {
  EXPECT_EQ(sim_.registers.btr, kBtr250);  // power-on: the rate start() set, untouched
  EXPECT_TRUE(sim_.samples.empty());
  lssRequest(0x00000104, 1000);  // 04 01: switch state global, configuration
  lssRequest(0x00020013, 2000);  // 13 00 02: configure bit timing, 500 kbit/s
  EXPECT_EQ(sim_.registers.tx[0].tir, (0x7E4U << 21) | ir::kTxrq);
  EXPECT_EQ(sim_.registers.tx[0].tdlr, 0x00000013U);  // 7E4 [8] 13 00 ...: accepted
  lssRequest(0x00006415, 3000);                       // 15 64 00: activate, switch delay 100 ms
  process(102999);
  EXPECT_EQ(sim_.registers.btr, kBtr250);
  EXPECT_TRUE(sim_.samples.empty());
  process(103000);
  EXPECT_EQ(sim_.registers.btr, kBtr500);
  EXPECT_EQ(sim_.registers.mcr, kRunningMcr);
  EXPECT_EQ(sim_.samples.size(), 1U);
  EXPECT_EQ(target_.node().bitTiming(), (LssBitTiming{0, 2}));
  process(203000);
  EXPECT_EQ(sim_.samples.size(), 1U);  // once
}

}  // namespace
}  // namespace costa::test
