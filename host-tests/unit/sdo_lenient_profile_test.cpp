// The lenient SDO profile fields (SdoProfile::shortestRequest, expeditedKeepsLowBytes,
// expeditedByCountAlone; the Santeng's, docs/errata-santeng.md W2-W4), each through exact
// frames on the example's dictionary, beside the example device's unchanged CiA 301 answer.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

class LenientSdo : public ExampleNodeTest {
 protected:
  static NodeSettings settings() {
    NodeSettings settings;
    settings.profile.sdo.shortestRequest = 4;
    settings.profile.sdo.expeditedKeepsLowBytes = true;
    settings.profile.sdo.expeditedByCountAlone = true;
    return settings;
  }
  LenientSdo() : ExampleNodeTest(settings()) {}
};

/// The example device as it is: CiA 301.
using Cia301Sdo = ExampleNodeTest;

// --- shortestRequest -------------------------------------------------------------------------

TEST_F(LenientSdo, ServesRequestsOfFourToSevenBytesWithEightByteReplies) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [7] 23 00 20 00 A0 86 01      # 0x2000 = 0x000186A0: the missing byte is 0
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 601 [4] 40 00 20 00               # upload with the multiplexer only
    tx 581 [8] 43 00 20 00 A0 86 01 00
    rx 601 [5] 2F 10 20 00 02            # 0x2010 = 2
    tx 581 [8] 60 10 20 00 00 00 00 00
    rx 601 [6] 40 10 20 00 00 00
    tx 581 [8] 4F 10 20 00 02 00 00 00
  )");
  EXPECT_EQ(value(0x2000, 0), 100000U);
}

TEST_F(LenientSdo, IgnoresRequestsShorterThanFourBytesAndRemoteFrames) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [3] 40 00 20
    rx 601 [1] 40
    rx 601 [0]
    rx 601 [8] RTR
    rx 601 [4] RTR
    silence
  )");
  EXPECT_EQ(bus_.node().statistics().framesIgnored, 5U);
}

TEST_F(LenientSdo, ShortRequestsAbortLikeWholeOnes) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [4] 40 99 99 00               # no such object
    tx 581 [8] 80 99 99 00 00 00 02 06
    rx 601 [7] 23 00 20 00 05 00 00      # 5: below the limit 10
    tx 581 [8] 80 00 20 00 32 00 09 06
  )");
}

TEST_F(LenientSdo, MissingBytesCountAsZeroWhateverTheFrameHolds) {
  CanFrame frame;
  frame.id = 0x601;
  frame.dlc = 7;
  const uint8_t bytes[8] = {0x23, 0x00, 0x20, 0x00, 0xA0, 0x86, 0x01, 0xFF};  // 0xFF unsent
  copyBytes(frame.data, bytes, 8);
  bus_.send(frame);
  EXPECT_TRANSCRIPT("tx 581 [8] 60 00 20 00 00 00 00 00");
  EXPECT_EQ(value(0x2000, 0), 100000U);
}

TEST_F(LenientSdo, SegmentedTransfersTakeShortFramesToo) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [4] 40 08 10 00               # segmented upload of the device name
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 601 [4] 60 00 00 00               # segment request: bytes 4..7 are not needed
    tx 581 [8] 00 43 6F 73 74 61 20 65
    rx 601 [8] 80 08 10 00 00 00 00 00   # client abort
    silence
  )");
}

TEST_F(Cia301Sdo, IgnoresEveryRequestShorterThanEightBytes) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [7] 23 00 20 00 A0 86 01
    rx 601 [4] 40 00 20 00
    rx 601 [5] 2F 10 20 00 02
    silence
    rx 601 [8] 40 00 20 00 00 00 00 00   # 0x2000 kept its default
    tx 581 [8] 43 00 20 00 E8 03 00 00
  )");
  EXPECT_EQ(bus_.node().statistics().framesIgnored, 3U);
}

// --- expeditedKeepsLowBytes ------------------------------------------------------------------

TEST_F(LenientSdo, LongerExpeditedWriteKeepsTheLowBytesThenChecksTheRange) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 04 20 02 9C FF 00 00   # INTEGER8 0x2004:02 = 0x9C = -100, 4 bytes sent
    tx 581 [8] 60 04 20 02 00 00 00 00
    rx 601 [8] 40 04 20 02 00 00 00 00
    tx 581 [8] 4F 04 20 02 9C 00 00 00
    rx 601 [8] 23 05 20 01 CD AB 12 34   # UNSIGNED16 0x2005:01: the high bytes are dropped
    tx 581 [8] 60 05 20 01 00 00 00 00
    rx 601 [8] 40 05 20 01 00 00 00 00
    tx 581 [8] 4B 05 20 01 CD AB 00 00
    rx 601 [8] 27 10 20 00 02 FF FF 00   # UNSIGNED8 0x2010 = 2 from 3 bytes
    tx 581 [8] 60 10 20 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2010, 0), 2U);
}

TEST_F(LenientSdo, LowBytesOutOfRangeAbortWithTheRangeCode) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 04 20 02 65 00 00 00   # 101 > 100
    tx 581 [8] 80 04 20 02 31 00 09 06
    rx 601 [8] 23 10 20 00 03 00 00 00   # 3 > 2
    tx 581 [8] 80 10 20 00 31 00 09 06
    rx 601 [8] 2B 04 20 02 9C FF 00 00   # 2 bytes: the same rule
    tx 581 [8] 60 04 20 02 00 00 00 00
  )");
}

TEST_F(LenientSdo, ShorterExpeditedWriteStillAbortsLengthTooLow) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 20 00 10 00 00 00   # 1 byte to UNSIGNED32 0x2000
    tx 581 [8] 80 00 20 00 13 00 07 06
    rx 601 [8] 23 06 20 00 41 42 43 44   # a string is no number: written as text
    tx 581 [8] 60 06 20 00 00 00 00 00
  )");
}

TEST_F(Cia301Sdo, LongerExpeditedWriteAbortsLengthTooHigh) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 04 20 02 9C FF 00 00
    tx 581 [8] 80 04 20 02 12 00 07 06
    rx 601 [8] 23 05 20 01 CD AB 12 34
    tx 581 [8] 80 05 20 01 12 00 07 06
    rx 601 [8] 40 04 20 02 00 00 00 00   # unchanged: -5
    tx 581 [8] 4F 04 20 02 FB 00 00 00
  )");
}

// --- expeditedByCountAlone -------------------------------------------------------------------

TEST_F(LenientSdo, CountWithoutExpeditedFlagsIsAnExpeditedWrite) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2C 10 20 00 02 00 00 00   # n = 3: one byte, e = s = 0
    tx 581 [8] 60 10 20 00 00 00 00 00
    rx 601 [8] 28 05 20 02 34 12 00 00   # n = 2: two bytes
    tx 581 [8] 60 05 20 02 00 00 00 00
    rx 601 [8] 24 00 20 00 A0 86 01 00   # n = 1: three bytes, UNSIGNED32: too low
    tx 581 [8] 80 00 20 00 13 00 07 06
  )");
  EXPECT_EQ(value(0x2010, 0), 2U);
  EXPECT_EQ(value(0x2005, 2), 0x1234U);
}

TEST_F(LenientSdo, CountAloneAndLowBytesTogether) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 28 10 20 00 01 00 00 00   # two bytes to UNSIGNED8: the low one
    tx 581 [8] 60 10 20 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2010, 0), 1U);
}

TEST_F(LenientSdo, NoCountIsStillASegmentedDownload) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 20 10 20 00 00 00 00 00   # n = 0: segmented, size not indicated
    tx 581 [8] 60 10 20 00 00 00 00 00
    rx 601 [8] 0D 01 00 00 00 00 00 00   # one byte, last
    tx 581 [8] 20 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2010, 0), 1U);
}

TEST_F(Cia301Sdo, CountWithoutExpeditedFlagsStartsASegmentedDownload) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2C 10 20 00 02 00 00 00   # CiA 301: n is not valid, a segmented download
    tx 581 [8] 60 10 20 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2010, 0), 0U);  // nothing written yet: the value comes in segments
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 0D 02 00 00 00 00 00 00
    tx 581 [8] 20 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2010, 0), 2U);
}

}  // namespace
}  // namespace costa::test
