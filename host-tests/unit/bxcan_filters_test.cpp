// BxCanPort::setFilters(): the node's acceptance filters in the bank registers, checked bit by
// bit and by what the banks let through (RM0090's 16-bit mask filters, evaluated here for every
// standard identifier), for the example node's own filters.
#include <gtest/gtest.h>

#include <vector>

#include "costa/port/stm32/bxcan_port.hpp"
#include "example_fixture.hpp"
#include "simulated_bxcan.hpp"

namespace costa::test {
namespace {

using namespace port::stm32;
using namespace port::stm32::bxcan;

constexpr uint32_t kBtr = 0x011C0003;

/// Whether the banks of CAN1 pass a standard frame (RM0090: a 16-bit mask filter matches when
/// (received XOR identifier) AND mask is 0 over STID, RTR, IDE, EXID[17:15]).
bool banksPass(const BxCanRegisters& r, uint32_t id, bool rtr) {
  const uint32_t can2Start = (r.fmr & fmr::kCan2sbMask) >> fmr::kCan2sbShift;
  for (uint32_t bank = 0; bank < can2Start && bank < 28U; ++bank) {
    const uint32_t bit = 1U << bank;
    if ((r.fa1r & bit) == 0U || (r.ffa1r & bit) != 0U) {
      continue;  // inactive, or FIFO 1, which the driver does not read
    }
    if ((r.fm1r & bit) != 0U || (r.fs1r & bit) != 0U) {
      // 32-bit mask mode is what start() uses: identifier bits 31:21, IDE 2, RTR 1.
      if ((r.fm1r & bit) == 0U && (r.fs1r & bit) != 0U) {
        const uint32_t received = (id << 21U) | (rtr ? 2U : 0U);
        if (((received ^ r.filter[bank].fr1) & r.filter[bank].fr2) == 0U) {
          return true;
        }
      }
      continue;
    }
    const uint32_t received = (id << 5U) | (rtr ? 1U << 4U : 0U);
    for (uint32_t half : {r.filter[bank].fr1, r.filter[bank].fr2}) {
      if (((received ^ (half & 0xFFFFU)) & (half >> 16U)) == 0U) {
        return true;
      }
    }
  }
  return false;
}

class BxCanFilters : public ::testing::Test {
 protected:
  BxCanFilters() : port_(sim_.registers, 50) { sim_.attach(port_); }
  void SetUp() override { ASSERT_TRUE(port_.start(kBtr)); }

  SimulatedBxCan sim_;
  BxCanPort port_;
};

TEST_F(BxCanFilters, TwoFiltersABankInSixteenBitMaskModeIntoFifo0) {
  const CanIdFilter filters[] = {{0x000, 0x7FF}, {0x601, 0x7FF}, {0x700, 0x780}};
  sim_.registers.fa1r = sim_.registers.fa1r | (1U << 14);  // a bank of CAN2 stays as it is
  ASSERT_TRUE(port_.setFilters(filters, 3));
  EXPECT_EQ(sim_.registers.filter[0].fr1, 0xFFE80000U);  // mask 0x7FF<<5 | IDE, id 0
  EXPECT_EQ(sim_.registers.filter[0].fr2, 0xFFE8C020U);  // id 0x601<<5
  EXPECT_EQ(sim_.registers.filter[1].fr1, 0xF008E000U);  // mask 0x780<<5 | IDE, id 0x700<<5
  EXPECT_EQ(sim_.registers.filter[1].fr2, 0xF008E000U);  // the odd last one twice
  EXPECT_EQ(sim_.registers.fa1r, (1U << 14) | 3U);       // banks 0 and 1 only
  EXPECT_EQ(sim_.registers.fm1r & 0x3FFFU, 0U);
  EXPECT_EQ(sim_.registers.fs1r & 0x3FFFU, 0U);
  EXPECT_EQ(sim_.registers.ffa1r & 0x3FFFU, 0U);
  EXPECT_EQ(sim_.registers.fmr & fmr::kFinit, 0U);
  EXPECT_EQ(sim_.registers.fmr & fmr::kCan2sbMask, SimulatedBxCan::kFmrReset & fmr::kCan2sbMask);
}

TEST_F(BxCanFilters, TheBanksPassExactlyWhatTheNodeListensTo) {
  InProcessBus bus("example", 1);
  std::vector<CanIdFilter> filters(32);
  filters.resize(bus.node().receiveFilters(filters.data(), filters.size()));
  ASSERT_TRUE(port_.setFilters(filters.data(), filters.size()));
  for (uint32_t id = 0; id <= 0x7FF; ++id) {
    bool expected = false;
    for (const CanIdFilter& filter : filters) {
      expected = expected || filter.accepts(id);
    }
    EXPECT_EQ(banksPass(sim_.registers, id, false), expected) << std::hex << id;
    EXPECT_EQ(banksPass(sim_.registers, id, true), expected) << std::hex << id;
  }
}

TEST_F(BxCanFilters, MoreFiltersThanBanksAcceptEverything) {
  std::vector<CanIdFilter> filters;
  for (uint16_t id = 1; id <= 29; ++id) {  // 14 banks hold 28
    filters.push_back(CanIdFilter{id, CanIdFilter::kExact});
  }
  EXPECT_FALSE(port_.setFilters(filters.data(), filters.size()));
  EXPECT_EQ(sim_.registers.fa1r & 0x3FFFU, 1U);  // bank 0 only: 32 bits, mask 0
  EXPECT_EQ(sim_.registers.filter[0].fr2, 0U);
  EXPECT_TRUE(banksPass(sim_.registers, 0x123, false));
  filters.pop_back();
  EXPECT_TRUE(port_.setFilters(filters.data(), filters.size()));
  EXPECT_EQ(sim_.registers.fa1r & 0x3FFFU, 0x3FFFU);
  EXPECT_FALSE(banksPass(sim_.registers, 0x123, false));
  EXPECT_TRUE(banksPass(sim_.registers, 28, true));
}

TEST_F(BxCanFilters, FewerFiltersLaterDeactivateTheBanksNoLongerUsed) {
  const CanIdFilter many[] = {{1, 0x7FF}, {2, 0x7FF}, {3, 0x7FF}, {4, 0x7FF}, {5, 0x7FF}};
  ASSERT_TRUE(port_.setFilters(many, 5));
  EXPECT_EQ(sim_.registers.fa1r & 0x3FFFU, 7U);
  ASSERT_TRUE(port_.setFilters(many, 1));
  EXPECT_EQ(sim_.registers.fa1r & 0x3FFFU, 1U);
  EXPECT_FALSE(banksPass(sim_.registers, 5, false));
  EXPECT_TRUE(banksPass(sim_.registers, 1, false));
}

TEST_F(BxCanFilters, ExtendedFramesPassNoFilter) {
  const CanIdFilter all[] = {{0x000, 0x000}};  // every standard identifier
  ASSERT_TRUE(port_.setFilters(all, 1));
  // IDE is in the mask and 0 in the identifier: a received IDE = 1 disagrees.
  const uint32_t half = sim_.registers.filter[0].fr1;
  EXPECT_NE(((1U << 3U) ^ (half & 0xFFFFU)) & (half >> 16U), 0U);
  EXPECT_TRUE(banksPass(sim_.registers, 0x7FF, false));
}

TEST_F(BxCanFilters, AcceptAllFramesUndoesTheFilters) {
  const CanIdFilter some[] = {{1, 0x7FF}, {2, 0x7FF}, {3, 0x7FF}};
  ASSERT_TRUE(port_.setFilters(some, 3));
  port_.acceptAllFrames();
  EXPECT_EQ(sim_.registers.fa1r & 0x3FFFU, 1U);
  EXPECT_EQ(sim_.registers.fs1r & 1U, 1U);  // bank 0: one 32-bit filter, mask 0
  EXPECT_EQ(sim_.registers.filter[0].fr2, 0U);
  EXPECT_TRUE(banksPass(sim_.registers, 0x5FF, true));
  EXPECT_EQ(sim_.registers.fmr & fmr::kFinit, 0U);
}

}  // namespace
}  // namespace costa::test
