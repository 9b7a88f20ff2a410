// Text form of frames shared by traces and transcripts.
#include <gtest/gtest.h>

#include "frame_text.hpp"
#include "transcript.hpp"

namespace costa::host {
namespace {

TEST(FrameText, FormatsDataRemoteAndExtendedFrames) {
  CanFrame frame;
  frame.id = 0x601;
  frame.dlc = 3;
  frame.data[0] = 0x40;
  frame.data[1] = 0x08;
  frame.data[2] = 0xAB;
  EXPECT_EQ(formatFrame(frame), "601 [3] 40 08 AB");
  frame.rtr = true;
  frame.dlc = 0;
  frame.id = 0x701;
  EXPECT_EQ(formatFrame(frame), "701 [0] RTR");
  CanFrame extended;
  extended.extended = true;
  extended.id = 0x18FF0001;
  EXPECT_EQ(formatFrame(extended), "18FF0001 [0]");
}

TEST(FrameText, ParsesWhatItFormats) {
  for (const char* text : {"601 [8] 40 08 10 00 00 00 00 00", "701 [0] RTR", "701 [1] RTR",
                           "000 [2] 01 00", "080 [0]", "1FFFFFFF [1] FF"}) {
    CanFrame frame;
    std::string error;
    ASSERT_TRUE(parseFrame(text, &frame, &error)) << text << ": " << error;
    EXPECT_EQ(formatFrame(frame), text);
  }
}

TEST(FrameText, WildcardsMatchAnyByte) {
  CanFrame expected;
  unsigned wildcards = 0;
  std::string error;
  ASSERT_TRUE(parseFrame("280 [4] xx 00 xx FE", &expected, &error, &wildcards));
  EXPECT_EQ(wildcards, 0x5U);
  CanFrame actual;
  ASSERT_TRUE(parseFrame("280 [4] 12 00 34 FE", &actual, &error));
  EXPECT_TRUE(matchesFrame(expected, wildcards, actual));
  actual.data[1] = 1;
  EXPECT_FALSE(matchesFrame(expected, wildcards, actual));
}

TEST(FrameText, RejectsMalformedText) {
  CanFrame frame;
  std::string error;
  EXPECT_FALSE(parseFrame("", &frame, &error));
  EXPECT_FALSE(parseFrame("801 [0]", &frame, &error));      // 11-bit id out of range
  EXPECT_FALSE(parseFrame("601 [9] 00", &frame, &error));   // DLC
  EXPECT_FALSE(parseFrame("601 [2] 00", &frame, &error));   // count
  EXPECT_FALSE(parseFrame("601 [1] 100", &frame, &error));  // byte
  EXPECT_FALSE(parseFrame("60G [0]", &frame, &error));      // hex
  EXPECT_FALSE(parseFrame("601 8 00", &frame, &error));     // brackets
}

TEST(Transcript, ParsesStepsAndReportsErrorsWithLines) {
  test::Transcript transcript;
  std::string error;
  ASSERT_TRUE(test::parseTranscript(
      "# header\ndevice example\nnode-id 3\nrx 603 [8] 40 00 10 00 00 00 00 00  # read\n"
      "tx 583 [8] 43 00 10 00 xx xx xx xx\nwait 20\nsilence\n",
      "t", &transcript, &error))
      << error;
  EXPECT_EQ(transcript.device, "example");
  EXPECT_EQ(transcript.nodeId, 3);
  ASSERT_EQ(transcript.steps.size(), 4U);
  EXPECT_EQ(transcript.steps[0].line, 4);
  EXPECT_EQ(transcript.steps[1].wildcards, 0xF0U);
  EXPECT_EQ(transcript.steps[2].milliseconds, 20U);

  test::Transcript bad;
  EXPECT_FALSE(test::parseTranscript("device x\nsend 601 [0]\n", "t", &bad, &error));
  EXPECT_EQ(error, "t:2: unknown keyword 'send'");
  EXPECT_FALSE(test::parseTranscript("device x\nrx 601 [1] xx\n", "t", &bad, &error));
  test::Transcript noDevice;
  EXPECT_FALSE(test::parseTranscript("rx 601 [0]\n", "t", &noDevice, &error));
  EXPECT_FALSE(test::parseTranscript("device x\nnode-id 200\n", "t", &bad, &error));
  EXPECT_FALSE(test::parseTranscript("device x\nignore 181 281\n", "t", &bad, &error));
  EXPECT_EQ(error, "t:2: ignore takes one CAN-ID (one line each)");
}

}  // namespace
}  // namespace costa::host
