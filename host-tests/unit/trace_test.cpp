// What --trace says about frames.
#include <gtest/gtest.h>

#include "example_od.hpp"
#include "frame_text.hpp"
#include "frame_trace.hpp"
#include "santeng_od.hpp"
#include "santeng_profile.hpp"

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

TEST_F(Trace, TimeShowsTheDateAndTimeOfDay) {
  EXPECT_EQ(describe("100 [6] 10 27 00 00 00 00"), "TIME 1984-01-01 00:00:10.000 (day 0)");
  // 2026-11-23 is day 15,667 after 1984-01-01; 13:45:30.250 is 49,530,250 ms.
  EXPECT_EQ(describe("100 [6] 8A C5 F3 02 33 3D"), "TIME 2026-11-23 13:45:30.250 (day 15667)");
  EXPECT_EQ(describe("100 [6] 00 00 00 00 3B 00"), "TIME 1984-02-29 00:00:00.000 (day 59)");
  EXPECT_EQ(describe("100 [5] 10 27 00 00 00"), "TIME (malformed, ignored)");
  EXPECT_EQ(describe("100 [6] 00 5C 26 05 00 00"), "TIME (malformed, ignored)");  // 24:00
}

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

TEST_F(Trace, BlockDownloadSegmentsAreNumbered) {
  EXPECT_EQ(describe("601 [8] C6 06 20 00 0C 00 00 00"),
            "SDO block download 0x2006:00, 12 bytes, CRC");
  EXPECT_EQ(describe("581 [8] A4 06 20 00 02 00 00 00"),
            "SDO block download response 0x2006:00, blksize 2, CRC  Device label");
  EXPECT_EQ(describe("601 [8] 01 48 65 6C 6C 6F 20 43"),
            "SDO block segment 1 48 65 6C 6C 6F 20 43");
  EXPECT_EQ(describe("601 [8] 82 6F 73 74 61 21 00 00"),
            "SDO block segment 2 6F 73 74 61 21 00 00 (last)");
  EXPECT_EQ(describe("581 [8] A2 02 01 00 00 00 00 00"), "SDO block download ack 2, blksize 1");
  EXPECT_EQ(describe("601 [8] C9 75 73 00 00 00 00 00"),
            "SDO block download end, 2 bytes unused, CRC 0x7375");
  EXPECT_EQ(describe("581 [8] A1 00 00 00 00 00 00 00"), "SDO block download end response");
  EXPECT_EQ(describe("601 [8] 40 08 10 00 00 00 00 00"), "SDO upload 0x1008:00");
}

TEST_F(Trace, BlockDownloadSegmentsAfterAnIncompleteAck) {
  describe("601 [8] C4 06 20 00 00 00 00 00");
  EXPECT_EQ(describe("601 [8] 83 61 62 63 00 00 00 00"),
            "SDO block segment 3 61 62 63 00 00 00 00 (last)");
  EXPECT_EQ(describe("581 [8] A2 01 03 00 00 00 00 00"), "SDO block download ack 1, blksize 3");
  EXPECT_EQ(describe("601 [8] C1 61 62 63 00 00 00 00"),  // sequence 65, last: still a segment
            "SDO block segment 65 61 62 63 00 00 00 00 (last)");
  EXPECT_EQ(describe("601 [8] 80 06 20 00 00 00 00 08"),
            "SDO abort 0x2006:00 0x08000000 (general error)");
  EXPECT_EQ(describe("601 [8] 01 61 00 00 00 00 00 00"),  // no block transfer any more
            "SDO download segment 61 00 00 00 00 00 00");
}

TEST_F(Trace, BlockUploadSegmentsAreNumbered) {
  EXPECT_EQ(describe("601 [8] A4 08 10 00 7F 00 00 00"),
            "SDO block upload 0x1008:00, blksize 127, pst 0, CRC");
  EXPECT_EQ(describe("581 [8] C6 08 10 00 0D 00 00 00"),
            "SDO block upload response 0x1008:00, 13 bytes, CRC  Manufacturer device name");
  EXPECT_EQ(describe("601 [8] A3 00 00 00 00 00 00 00"), "SDO block upload start");
  EXPECT_EQ(describe("581 [8] 01 43 6F 73 74 61 20 65"),
            "SDO block segment 1 43 6F 73 74 61 20 65");
  EXPECT_EQ(describe("581 [8] 82 78 61 6D 70 6C 65 00"),
            "SDO block segment 2 78 61 6D 70 6C 65 00 (last)");
  EXPECT_EQ(describe("601 [8] A2 02 7F 00 00 00 00 00"), "SDO block upload ack 2, blksize 127");
  EXPECT_EQ(describe("581 [8] C5 32 17 00 00 00 00 00"),
            "SDO block upload end, 1 byte unused, CRC 0x1732");
  EXPECT_EQ(describe("601 [8] A1 00 00 00 00 00 00 00"), "SDO block upload end response");
  EXPECT_EQ(describe("581 [8] 60 17 10 00 00 00 00 00"),
            "SDO download response 0x1017:00  Producer heartbeat time");
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

// The tracer reads the local node's frames with the node's own profile (here the SOLO's EMCY
// layout), other nodes' frames as CiA 301.
TEST(TraceWithProfile, EmcyWithTheRegisterInTheFourthByte) {
  DeviceProfile profile;
  profile.emcy.layout = EmcyLayout::kErrorRegisterInFourthByte;
  FrameTracer tracer(nullptr, nullptr, profile);
  const auto describe = [&tracer](const char* text) {
    CanFrame frame;
    std::string error;
    EXPECT_TRUE(parseFrame(text, &frame, &error)) << error;
    return tracer.describe(frame, 0x0A);
  };
  EXPECT_EQ(describe("08A [8] 00 00 00 08 00 00 00 00"), "EMCY node 10 register 0x08");
  EXPECT_EQ(describe("08A [8] 00 00 00 00 00 00 00 00"), "EMCY node 10 register 0x00");
  EXPECT_EQ(describe("08A [8] 00 00 00 08 00 00 01 00"),
            "EMCY node 10 register 0x08 data 00 00 00 08 00 00 01 00");
  EXPECT_EQ(describe("08A [2] 00 00"), "EMCY node 10 data 00 00");
  EXPECT_EQ(describe("081 [8] 30 81 11 00 00 00 00 00"),
            "EMCY node 1 code 0x8130 register 0x11 data 00 00 00 00 00");
}

// The Santeng's lenient SDO server (W2-W4): its short requests and its 0x2C are read as it
// serves them; another node's (and a CiA 301 node's) stay malformed or segmented.
TEST(TraceWithProfile, SantengShortRequestsAndCountAlone) {
  gen::santeng::Values values{};
  od::ObjectDictionary dictionary(gen::santeng::kDefinition, &values);
  dictionary.setNodeId(1);
  FrameTracer tracer(&dictionary, &gen::santeng::kNames, santeng::profile());
  const auto describe = [&tracer](const char* text) {
    CanFrame frame;
    std::string error;
    EXPECT_TRUE(parseFrame(text, &frame, &error)) << error;
    return tracer.describe(frame, 1);
  };
  EXPECT_EQ(describe("601 [7] 23 01 20 01 00 09 34"),
            "SDO download 0x2001:01 = 3410176 (7 bytes, the rest taken as 0)");
  EXPECT_EQ(describe("601 [4] 40 03 21 01"), "SDO upload 0x2103:01 (4 bytes, the rest taken as 0)");
  EXPECT_EQ(describe("601 [3] 40 03 21"), "SDO request (malformed, ignored)");
  EXPECT_EQ(describe("602 [7] 23 01 20 01 00 09 34"), "SDO request (malformed, ignored)");
  EXPECT_EQ(describe("601 [8] 2C 0E 20 01 00 00 00 00"), "SDO download 0x200E:01 = 0 (0x00)");
  EXPECT_EQ(describe("601 [8] 23 00 20 01 0C FE 00 00"), "SDO download 0x2000:01 = -500");
  EXPECT_EQ(describe("602 [8] 2C 0E 20 01 00 00 00 00"), "SDO download 0x200E:01 segmented");
  FrameTracer cia301(&dictionary, &gen::santeng::kNames);
  CanFrame frame;
  std::string error;
  ASSERT_TRUE(parseFrame("601 [7] 23 01 20 01 00 09 34", &frame, &error)) << error;
  EXPECT_EQ(cia301.describe(frame, 1), "SDO request (malformed, ignored)");
}

TEST(TraceWithProfile, HeartbeatByteWhileAnErrorIsActive) {
  DeviceProfile profile;
  profile.errorControl.heartbeatWhileError = 0x04;
  FrameTracer tracer(nullptr, nullptr, profile);
  const auto describe = [&tracer](const char* text) {
    CanFrame frame;
    std::string error;
    EXPECT_TRUE(parseFrame(text, &frame, &error)) << error;
    return tracer.describe(frame, 1);
  };
  EXPECT_EQ(describe("701 [1] 04"),
            "heartbeat: an error is active (the device's byte; NMT state unchanged)");
  EXPECT_EQ(describe("701 [1] 05"), "heartbeat operational");
  EXPECT_EQ(describe("702 [1] 04"), "heartbeat stopped");  // another node: CiA 301
}

}  // namespace
}  // namespace costa::host
