// BitTimingSwitch alone: timing in use and pending, switched through a controller that may refuse.
#include "costa/bit_timing_switch.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace costa::test {
namespace {

class RecordingBitRateControl final : public CanBitRateControl {
 public:
  RecordingBitRateControl() = default;

  bool setBitRate(uint32_t bitsPerSecond) noexcept override {
    asked.push_back(bitsPerSecond);
    return accepting;
  }

  bool accepting = true;
  std::vector<uint32_t> asked;
};

constexpr LssBitTiming k250{0, 3};
constexpr LssBitTiming k500{0, 2};

TEST(BitTimingSwitch, WithoutAControllerItRecordsTheTiming) {
  BitTimingSwitch timing(nullptr, k250);
  EXPECT_TRUE(timing.inUse() == k250);
  EXPECT_TRUE(timing.pending() == k250);
  timing.switchTo(LssBitTiming{0, 9});  // even one without a rate
  EXPECT_TRUE(timing.inUse() == (LssBitTiming{0, 9}));
}

TEST(BitTimingSwitch, TheControllerIsRetimedAndTheTimingChangesWhenItAccepts) {
  RecordingBitRateControl controller;
  BitTimingSwitch timing(&controller, k250);
  timing.switchTo(k500);
  EXPECT_TRUE(timing.inUse() == k500);
  controller.accepting = false;
  timing.switchTo(LssBitTiming{0, 4});
  EXPECT_TRUE(timing.inUse() == k500);  // refused: the old one stays
  EXPECT_EQ(controller.asked, (std::vector<uint32_t>{500000, 125000}));
}

TEST(BitTimingSwitch, ATimingWithoutARateIsNeverAskedFor) {
  RecordingBitRateControl controller;
  BitTimingSwitch timing(&controller, k250);
  timing.switchTo(LssBitTiming{0, 5});    // reserved
  timing.switchTo(LssBitTiming{0, 9});    // automatic detection
  timing.switchTo(LssBitTiming{128, 1});  // a manufacturer's table
  EXPECT_TRUE(controller.asked.empty());
  EXPECT_TRUE(timing.inUse() == k250);
}

TEST(BitTimingSwitch, ADevicesOwnTableGivesTheRatesOfSelector128) {
  RecordingBitRateControl controller;
  static constexpr uint32_t kRates[] = {25000, 33333};
  static constexpr BitRateTable kTable{kRates, 2};
  BitTimingSwitch timing(&controller, k250);
  timing.switchTo(LssBitTiming{128, 0}, &kTable);
  EXPECT_TRUE(timing.inUse() == (LssBitTiming{128, 0}));
  timing.switchTo(LssBitTiming{128, 2}, &kTable);  // beyond the table
  timing.switchTo(LssBitTiming{129, 0}, &kTable);  // another manufacturer table
  timing.switchTo(LssBitTiming{128, 1});           // no table given
  EXPECT_TRUE(timing.inUse() == (LssBitTiming{128, 0}));
  timing.setPending(LssBitTiming{128, 1});
  timing.applyPending(&kTable);
  EXPECT_TRUE(timing.inUse() == (LssBitTiming{128, 1}));
  timing.switchTo(k500, &kTable);  // CiA 305's table as before
  EXPECT_EQ(controller.asked, (std::vector<uint32_t>{25000, 33333, 500000}));
}

TEST(BitTimingSwitch, ThePendingTimingAppliesOnlyWhenItDiffers) {
  RecordingBitRateControl controller;
  BitTimingSwitch timing(&controller, k250);
  timing.applyPending();
  EXPECT_TRUE(controller.asked.empty());
  timing.setPending(k500);
  EXPECT_TRUE(timing.inUse() == k250);
  controller.accepting = false;
  timing.applyPending();  // refused: tried again at the next one
  controller.accepting = true;
  timing.applyPending();
  EXPECT_TRUE(timing.inUse() == k500);
  timing.applyPending();
  EXPECT_EQ(controller.asked, (std::vector<uint32_t>{500000, 500000}));
}

}  // namespace
}  // namespace costa::test
