// What --trace says about frames.
#include <gtest/gtest.h>

#include "example_od.hpp"
#include "frame_text.hpp"
#include "frame_trace.hpp"

namespace costa::host {
namespace {

class Trace : public ::testing::Test {
 protected:
  Trace()
      : dictionary_(gen::example::kDefinition, &values_),
        tracer_(&dictionary_, &gen::example::kNames) {
    dictionary_.setNodeId(1);
    dictionary_.restoreDefaults(0, 0xFFFF);
  }
  std::string describe(const char* text) {
    CanFrame frame;
    std::string error;
    EXPECT_TRUE(parseFrame(text, &frame, &error)) << error;
    return tracer_.describe(frame, 1);
  }
  gen::example::Values values_{};
  od::ObjectDictionary dictionary_;
  FrameTracer tracer_;
};

TEST_F(Trace, SegmentedUploadShowsTheWholeString) {
  EXPECT_EQ(describe("601 [8] 40 08 10 00 00 00 00 00"), "SDO upload 0x1008:00");
  EXPECT_EQ(describe("581 [8] 41 08 10 00 0D 00 00 00"),
            "SDO upload response 0x1008:00 segmented, 13 bytes  Manufacturer device name");
  EXPECT_EQ(describe("601 [8] 60 00 00 00 00 00 00 00"), "SDO upload segment request");
  EXPECT_EQ(describe("581 [8] 00 43 6F 73 74 61 20 65"), "SDO upload segment 43 6F 73 74 61 20 65");
  EXPECT_EQ(describe("581 [8] 13 78 61 6D 70 6C 65 00"),
            "SDO upload segment 78 61 6D 70 6C 65 (last) 0x1008:00 = \"Costa example\"");
}

TEST_F(Trace, ExpeditedValuesAreShownByType) {
  EXPECT_EQ(describe("601 [8] 2B 17 10 00 E8 03 00 00"), "SDO download 0x1017:00 = 1000 (0x03E8)");
  EXPECT_EQ(describe("581 [8] 60 17 10 00 00 00 00 00"),
            "SDO download response 0x1017:00  Producer heartbeat time");
  EXPECT_EQ(describe("581 [8] 43 04 20 03 60 79 FE FF"),
            "SDO upload response 0x2004:03 -100000  Mixed record.Position");
  EXPECT_EQ(describe("581 [8] 80 00 30 00 00 00 02 06"),
            "SDO abort 0x3000:00 0x06020000 (object does not exist)");
}

TEST_F(Trace, NetworkManagementAndErrorControl) {
  EXPECT_EQ(describe("000 [2] 01 00"), "NMT start all nodes");
  EXPECT_EQ(describe("000 [2] 82 05"), "NMT reset communication node 5");
  EXPECT_EQ(describe("701 [1] 00"), "boot-up");
  EXPECT_EQ(describe("701 [1] 7F"), "heartbeat pre-operational");
  EXPECT_EQ(describe("701 [0] RTR"), "node guard request");
  EXPECT_EQ(describe("701 [1] 85"), "node guard reply operational toggle 1");
  EXPECT_EQ(describe("080 [0]"), "SYNC");
  EXPECT_EQ(describe("081 [8] 30 81 11 00 00 00 00 00"),
            "EMCY node 1 code 0x8130 register 0x11 data 00 00 00 00 00");
  EXPECT_EQ(describe("7E5 [8] 04 01 00 00 00 00 00 00"), "LSS request switch state global");
}

}  // namespace
}  // namespace costa::host
