// costa-slave --trace's indicators: the states of a node's CiA 303-3 LEDs as trace text, and
// room for them on every device's node.
#include <gtest/gtest.h>

#include "in_process_bus.hpp"
#include "node_indicators.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

TEST(NodeIndicators, TellEachChangeOfTheStatesOnce) {
  InProcessBus bus("example", 1);
  ASSERT_EQ(playText("tx 701 [1] 00", bus), "");
  host::NodeIndicators indicators(bus.node());
  EXPECT_TRUE(indicators.attached());
  (void)indicators.process(bus.now());
  EXPECT_EQ(indicators.change(), "RUN blinking, ERROR off");
  (void)indicators.process(bus.now());
  EXPECT_EQ(indicators.change(), "");
  ASSERT_EQ(playText("rx 000 [2] 01 01", bus), "");
  (void)indicators.process(bus.now());
  EXPECT_EQ(indicators.change(), "RUN on, ERROR off");
  bus.node().onControllerEvent(CanControllerEvent::kBusOff, bus.now());
  (void)indicators.process(bus.now());
  EXPECT_EQ(indicators.change(), "RUN blinking, ERROR on");  // 0x1029: pre-operational
}

TEST(NodeIndicators, FindRoomOnEveryDevicesNode) {
  for (const char* device : {"example", "solo", "gra", "grn", "santeng", "mseries"}) {
    InProcessBus bus(device, 5);
    host::NodeIndicators indicators(bus.node());
    EXPECT_TRUE(indicators.attached()) << device;
  }
}

TEST(NodeIndicators, NameEveryState) {
  EXPECT_STREQ(host::indicatorStateName(IndicatorState::kTripleFlash), "triple flash");
  EXPECT_STREQ(host::indicatorStateName(IndicatorState::kSingleFlash), "single flash");
  EXPECT_STREQ(host::indicatorStateName(IndicatorState::kFlickering), "flickering");
}

}  // namespace
}  // namespace costa::test
