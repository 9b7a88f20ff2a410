// bxCAN bit timing: CAN_BTR values for common clocks, the CiA 305 table, refusals.
#include <gtest/gtest.h>

#include "costa/port/stm32/bxcan_bit_timing.hpp"

namespace costa::port::stm32 {
namespace {

struct Expected {
  uint32_t clockHz;
  uint32_t bitRate;
  uint16_t prescaler;
  uint8_t segment1;
  uint8_t segment2;
  uint32_t btr;
  uint32_t samplePointPermille;
};

// Worked by hand from RM0090's formula: bit = (1 + BS1 + BS2) x prescaler / f(APB1).
constexpr Expected kTable[] = {
    {42000000, 1000000, 3, 11, 2, 0x011A0002, 857},  // 14 tq
    {42000000, 500000, 6, 11, 2, 0x011A0005, 857},  {42000000, 250000, 12, 11, 2, 0x011A000B, 857},
    {42000000, 125000, 21, 13, 2, 0x011C0014, 875},  // 16 tq
    {42000000, 50000, 56, 12, 2, 0x011B0037, 866},   // 15 tq
    {42000000, 20000, 140, 12, 2, 0x011B008B, 866}, {42000000, 10000, 280, 12, 2, 0x011B0117, 866},
    {36000000, 1000000, 2, 15, 2, 0x011E0001, 888},  // 18 tq
    {36000000, 800000, 3, 12, 2, 0x011B0002, 866},  {36000000, 500000, 4, 15, 2, 0x011E0003, 888},
    {36000000, 250000, 9, 13, 2, 0x011C0008, 875},  {36000000, 125000, 18, 13, 2, 0x011C0011, 875},
    {36000000, 50000, 45, 13, 2, 0x011C002C, 875},  {36000000, 20000, 120, 12, 2, 0x011B0077, 866},
    {36000000, 10000, 225, 13, 2, 0x011C00E0, 875}, {16000000, 250000, 4, 13, 2, 0x011C0003, 875},
    {8000000, 1000000, 1, 5, 2, 0x01140000, 750},  // 8 tq: BS2 stays 2 tq
};

TEST(BxCanBitTiming, CommonClocksAndRates) {
  for (const Expected& e : kTable) {
    const BxCanBitTiming t = bxCanBitTiming(e.clockHz, e.bitRate);
    SCOPED_TRACE(testing::Message() << e.clockHz << " Hz, " << e.bitRate << " bit/s");
    ASSERT_TRUE(t.valid());
    EXPECT_EQ(t.prescaler, e.prescaler);
    EXPECT_EQ(t.segment1, e.segment1);
    EXPECT_EQ(t.segment2, e.segment2);
    EXPECT_EQ(t.jumpWidth, 2U);
    EXPECT_EQ(t.btr(), e.btr);
    EXPECT_EQ(t.samplePointPermille(), e.samplePointPermille);
    EXPECT_EQ(uint64_t{t.prescaler} * t.quantaPerBit() * e.bitRate, e.clockHz);
  }
}

TEST(BxCanBitTiming, EquallyGoodSamplePointsPreferMoreQuantaThenTheEarlierOne) {
  // 16 MHz / 1 Mbit/s at 75 %: 8 tq (6/8) and 16 tq (12/16) are both exact; 16 tq wins.
  EXPECT_EQ(bxCanBitTiming(16000000, 1000000, 750).quantaPerBit(), 16U);
  // 10 MHz / 1 Mbit/s at 75 %: 10 tq, and 7/10 and 8/10 are equally far; 7/10 wins.
  const BxCanBitTiming t = bxCanBitTiming(10000000, 1000000, 750);
  EXPECT_EQ(t.quantaPerBit(), 10U);
  EXPECT_EQ(t.segment1, 6U);
  EXPECT_EQ(t.segment2, 3U);
  EXPECT_EQ(t.jumpWidth, 3U);
}

TEST(BxCanBitTiming, ALongerPhaseTwoGivesALargerJumpWidth) {
  // 80 % at 10 tq: BS1 7, BS2 2.  75 % at 16 tq: BS1 11, BS2 4, SJW 4.
  const BxCanBitTiming late = bxCanBitTiming(10000000, 1000000, 800);
  EXPECT_EQ(late.segment1, 7U);
  EXPECT_EQ(late.segment2, 2U);
  const BxCanBitTiming early = bxCanBitTiming(16000000, 1000000, 750);
  EXPECT_EQ(early.segment1, 11U);
  EXPECT_EQ(early.segment2, 4U);
  EXPECT_EQ(early.jumpWidth, 4U);
  EXPECT_EQ(early.btr(), 0x033A0000U);
}

TEST(BxCanBitTiming, RefusesWhatTheClockCannotProduceExactly) {
  EXPECT_FALSE(bxCanBitTiming(42000000, 800000).valid());  // 52.5 clocks per bit
  EXPECT_FALSE(bxCanBitTiming(42000000, 33333).valid());   // not a divisor
  EXPECT_FALSE(bxCanBitTiming(42000000, 1000).valid());    // prescaler would exceed 1024
  EXPECT_FALSE(bxCanBitTiming(3000000, 1000000).valid());  // 3 tq: no room for BS2 = 2
  EXPECT_FALSE(bxCanBitTiming(16000000, 0).valid());
  EXPECT_FALSE(bxCanBitTiming(16000000, 250000, 1000).valid());
  EXPECT_EQ(BxCanBitTiming{}.btr(), 0U);
}

TEST(BxCanBitTiming, Cia305TableIndices) {
  const uint32_t rates[] = {1000000, 800000, 500000, 250000, 125000, 0, 50000, 20000, 10000};
  for (uint8_t index = 0; index < 9; ++index) {
    EXPECT_EQ(cia305BitRate(index), rates[index]) << int{index};
    const BxCanBitTiming t = bxCanBitTimingForCia305Index(36000000, index);
    EXPECT_EQ(t.valid(), rates[index] != 0) << int{index};
    if (t.valid()) {
      EXPECT_EQ(t.btr(), bxCanBitTiming(36000000, rates[index]).btr()) << int{index};
    }
  }
  EXPECT_EQ(cia305BitRate(9), 0U);  // automatic bit rate detection: no timing of its own
  EXPECT_EQ(cia305BitRate(255), 0U);
  EXPECT_FALSE(bxCanBitTimingForCia305Index(36000000, 9).valid());
  EXPECT_FALSE(bxCanBitTimingForCia305Index(42000000, 1).valid());  // 800 kbit/s at 42 MHz
  EXPECT_TRUE(bxCanBitTimingForCia305Index(42000000, 2).valid());
}

}  // namespace
}  // namespace costa::port::stm32
