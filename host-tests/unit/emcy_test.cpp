// EMCY producer: conditions, error register, pre-defined error field, inhibit time, COB-ID,
// and the device-selectable frame layout.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Emcy = ExampleNodeTest;

const uint8_t kManufacturer[5] = {1, 2, 3, 4, 5};

TEST_F(Emcy, RaiseAndClearWithErrorRegisterAndHistory) {
  withNode(
      [](Node& node) { EXPECT_TRUE(node.raiseError(0x4210, kErrorTemperature, kManufacturer)); });
  EXPECT_TRANSCRIPT("tx 081 [8] 10 42 09 01 02 03 04 05");
  EXPECT_EQ(value(0x1001, 0), 0x09U);
  EXPECT_EQ(value(0x1003, 0), 1U);
  EXPECT_EQ(value(0x1003, 1), 0x02014210U);
  withNode([](Node& node) { EXPECT_FALSE(node.raiseError(0x4210, kErrorTemperature)); });
  EXPECT_TRANSCRIPT("silence");  // one EMCY per error event
  withNode([](Node& node) { node.raiseError(0x3110, kErrorVoltage); });
  EXPECT_TRANSCRIPT("tx 081 [8] 10 31 0D 00 00 00 00 00");
  EXPECT_EQ(value(0x1003, 0), 2U);
  EXPECT_EQ(value(0x1003, 1), 0x3110U);  // newest first
  EXPECT_EQ(value(0x1003, 2), 0x02014210U);
  withNode([](Node& node) { EXPECT_TRUE(node.clearError(0x4210)); });
  EXPECT_TRANSCRIPT("silence");
  EXPECT_EQ(value(0x1001, 0), 0x05U);
  withNode([](Node& node) {
    EXPECT_FALSE(node.clearError(0x4210));
    EXPECT_TRUE(node.clearError(0x3110));
  });
  EXPECT_TRANSCRIPT("tx 081 [8] 00 00 00 00 00 00 00 00");  // error reset
  EXPECT_EQ(value(0x1001, 0), 0U);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 00 00 00 00
    rx 601 [8] 40 03 10 02 00 00 00 00
    tx 581 [8] 43 03 10 02 10 42 01 02
  )");
}

TEST_F(Emcy, HistoryKeepsTheNewestAndIsClearedByWritingZero) {
  withNode([](Node& node) {
    for (uint16_t i = 1; i <= 10; ++i) {
      node.signalError(static_cast<uint16_t>(0xFF00U + i), kErrorManufacturer);
    }
  });
  EXPECT_EQ(value(0x1003, 0), 8U);
  EXPECT_EQ(value(0x1003, 1), 0xFF0AU);
  EXPECT_EQ(value(0x1003, 8), 0xFF03U);
  EXPECT_TRANSCRIPT(R"(
    tx 081 [8] 01 FF 81 00 00 00 00 00
    tx 081 [8] 02 FF 81 00 00 00 00 00
    tx 081 [8] 03 FF 81 00 00 00 00 00
    tx 081 [8] 04 FF 81 00 00 00 00 00
    tx 081 [8] 05 FF 81 00 00 00 00 00
    tx 081 [8] 06 FF 81 00 00 00 00 00
    tx 081 [8] 07 FF 81 00 00 00 00 00
    tx 081 [8] 08 FF 81 00 00 00 00 00
    rx 601 [8] 2F 03 10 00 01 00 00 00   # only 0 may be written
    tx 581 [8] 80 03 10 00 30 00 09 06
    rx 601 [8] 23 03 10 01 00 00 00 00   # the entries are read-only
    tx 581 [8] 80 03 10 01 02 00 01 06
    rx 601 [8] 2B 03 10 00 00 00 00 00   # UNSIGNED8: two bytes are too many, even zeros
    tx 581 [8] 80 03 10 00 12 00 07 06
    rx 601 [8] 2F 03 10 00 00 00 00 00
    tx 581 [8] 60 03 10 00 00 00 00 00
    rx 601 [8] 40 03 10 00 00 00 00 00
    tx 581 [8] 4F 03 10 00 00 00 00 00
  )");
  // Frames 9 and 10 did not fit the EMCY queue (8 deep) and are counted as lost.
  EXPECT_EQ(bus_.node().emcyLost(), 2U);
  EXPECT_EQ(bus_.node().txDropped(), 0U);  // lost before the transmit queue, not in it
  EXPECT_EQ(value(0x1003, 1), 0U);
}

TEST_F(Emcy, InhibitTimeSpacesFramesWithoutLosingThem) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 15 10 00 64 00 00 00   # 100 x 100 us = 10 ms
    tx 581 [8] 60 15 10 00 00 00 00 00
  )");
  withNode([](Node& node) {
    node.raiseError(0x5000, 0);
    node.raiseError(0x5001, 0);
    node.raiseError(0x5002, 0);
  });
  EXPECT_TRANSCRIPT(R"(
    tx 081 [8] 00 50 01 00 00 00 00 00
    wait 9
    silence
    wait 1
    tx 081 [8] 01 50 01 00 00 00 00 00
    wait 10
    tx 081 [8] 02 50 01 00 00 00 00 00
  )");
}

TEST_F(Emcy, CobIdValidBitAndChangeRules) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 14 10 00 82 00 00 00   # another CAN-ID while valid
    tx 581 [8] 80 14 10 00 30 00 09 06
    rx 601 [8] 23 14 10 00 81 00 00 80   # not valid: no EMCY
    tx 581 [8] 60 14 10 00 00 00 00 00
  )");
  withNode([](Node& node) { node.raiseError(0x5000, 0); });
  EXPECT_TRANSCRIPT(R"(
    silence
    rx 601 [8] 23 14 10 00 90 00 00 00   # valid on 0x090
    tx 581 [8] 60 14 10 00 00 00 00 00
  )");
  withNode([](Node& node) { node.clearError(0x5000); });
  EXPECT_TRANSCRIPT("tx 090 [8] 00 00 00 00 00 00 00 00");
}

TEST_F(Emcy, NotSentWhileStopped) {
  EXPECT_TRANSCRIPT("rx 000 [2] 02 01");
  withNode([](Node& node) { node.raiseError(0x5000, 0); });
  EXPECT_TRANSCRIPT("silence\nrx 000 [2] 80 01\ntx 081 [8] 00 50 01 00 00 00 00 00");
}

class EmcyFourthByteLayout : public ExampleNodeTest {
 protected:
  static NodeSettings settings() {
    NodeSettings settings;
    settings.profile.emcy.layout = EmcyLayout::kErrorRegisterInFourthByte;
    return settings;
  }
  EmcyFourthByteLayout() : ExampleNodeTest(settings()) {}
};

TEST_F(EmcyFourthByteLayout, ErrorRegisterInTheFourthDataByte) {
  withNode([](Node& node) { node.raiseError(0x4210, kErrorTemperature, kManufacturer); });
  EXPECT_TRANSCRIPT("tx 081 [8] 00 00 00 09 00 00 00 00");
}

}  // namespace
}  // namespace costa::test
