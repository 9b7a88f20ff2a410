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
