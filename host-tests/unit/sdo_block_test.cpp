// SDO block transfer (CiA 301 7.2.4.3.9 - 7.2.4.3.16), frame by frame: initiate, sub-blocks,
// acknowledgements, end with unused bytes and CRC, block sizes, sequence errors, the protocol
// switch threshold, CRC errors, timeouts and aborts.
#include <string>

#include "example_fixture.hpp"

namespace costa::test {
namespace {

class SdoBlock : public ExampleNodeTest {
 protected:
  /// The device label (0x2006) as stored.
  std::string label() {
    const od::ObjectDictionary& dictionary = bus_.node().dictionary();
    const od::EntryRef ref = dictionary.find(0x2006, 0);
    uint8_t text[64] = {};
    const size_t length = dictionary.read(ref, 0, text, sizeof(text));
    return std::string(reinterpret_cast<const char*>(text), length);
  }
};

TEST_F(SdoBlock, DownloadsAStringWithSizeAndCrc) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 0C 00 00 00   # block download 0x2006, CRC, 12 bytes
    tx 581 [8] A4 06 20 00 02 00 00 00   # CRC too; blksize 2: all the value needs
    rx 601 [8] 01 48 65 6C 6C 6F 20 43   # 1: "Hello C"
    silence
    rx 601 [8] 82 6F 73 74 61 21 00 00   # 2, last: "osta!" and 2 unused bytes
    tx 581 [8] A2 02 01 00 00 00 00 00   # ackseq 2, blksize 1
    rx 601 [8] C9 75 73 00 00 00 00 00   # end: 2 unused, CRC 0x7375
    tx 581 [8] A1 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(label(), "Hello Costa!");
}

TEST_F(SdoBlock, DownloadsWithoutSizeOrCrc) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C0 06 20 00 00 00 00 00
    tx 581 [8] A4 06 20 00 05 00 00 00   # blksize 5: 32 bytes of SDO buffer
    rx 601 [8] 81 61 62 63 00 00 00 00   # 1, last: "abc"
    tx 581 [8] A2 01 05 00 00 00 00 00
    rx 601 [8] D1 00 00 00 00 00 00 00   # end: 4 unused, no CRC
    tx 581 [8] A1 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(label(), "abc");
}

TEST_F(SdoBlock, DownloadsASmallNumericValue) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C2 17 10 00 02 00 00 00   # 0x1017, 2 bytes, no CRC
    tx 581 [8] A4 17 10 00 01 00 00 00
    rx 601 [8] 81 E8 03 00 00 00 00 00
    tx 581 [8] A2 01 01 00 00 00 00 00
    rx 601 [8] D5 00 00 00 00 00 00 00   # 5 unused
    tx 581 [8] A1 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x1017, 0), 1000U);
}

TEST_F(SdoBlock, OutOfSequenceSegmentsAreDroppedAndRepeated) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 1C 00 00 00   # 28 bytes "0123456789ABCDEFGHIJKLMNOPQR"
    tx 581 [8] A4 06 20 00 04 00 00 00
    rx 601 [8] 01 30 31 32 33 34 35 36   # 1
    rx 601 [8] 03 45 46 47 48 49 4A 4B   # 3: 2 was lost; dropped
    rx 601 [8] 84 4C 4D 4E 4F 50 51 52   # 4, last: dropped too; the sub-block ends
    tx 581 [8] A2 01 03 00 00 00 00 00   # good up to 1; 21 bytes left: blksize 3
    rx 601 [8] 84 4C 4D 4E 4F 50 51 52   # 4 received twice: ignored, although above blksize
    silence
    rx 601 [8] 01 37 38 39 41 42 43 44   # repeated from the old segment 2
    rx 601 [8] 02 45 46 47 48 49 4A 4B
    rx 601 [8] 83 4C 4D 4E 4F 50 51 52
    tx 581 [8] A2 03 01 00 00 00 00 00
    rx 601 [8] C1 A6 28 00 00 00 00 00   # CRC 0x28A6
    tx 581 [8] A1 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(label(), "0123456789ABCDEFGHIJKLMNOPQR");
}

TEST_F(SdoBlock, InvalidSequenceNumberInADownload_05040003) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 0C 00 00 00
    tx 581 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 03 48 65 6C 6C 6F 20 43   # 3 > blksize 2
    tx 581 [8] 80 06 20 00 03 00 04 05
    rx 601 [8] C6 06 20 00 0C 00 00 00
    tx 581 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 00 48 65 6C 6C 6F 20 43   # 0 is no sequence number
    tx 581 [8] 80 06 20 00 03 00 04 05
  )");
  EXPECT_EQ(label(), "unnamed");
}

TEST_F(SdoBlock, CrcMismatchAbortsAndKeepsTheValue_05040004) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 0C 00 00 00
    tx 581 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 01 48 65 6C 6C 6F 20 43
    rx 601 [8] 82 6F 73 74 61 21 00 00
    tx 581 [8] A2 02 01 00 00 00 00 00
    rx 601 [8] C9 75 74 00 00 00 00 00   # CRC 0x7475, not 0x7375
    tx 581 [8] 80 06 20 00 04 00 04 05
  )");
  EXPECT_EQ(label(), "unnamed");
}

TEST_F(SdoBlock, SizeMismatchAtTheEnd_06070010) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C2 06 20 00 0C 00 00 00   # 12 bytes announced, no CRC
    tx 581 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 81 48 65 6C 6C 6F 00 00   # only 5 sent
    tx 581 [8] A2 01 02 00 00 00 00 00
    rx 601 [8] C9 00 00 00 00 00 00 00
    tx 581 [8] 80 06 20 00 10 00 07 06
    rx 601 [8] C2 06 20 00 05 00 00 00   # 5 announced
    tx 581 [8] A4 06 20 00 01 00 00 00
    rx 601 [8] 81 48 65 6C 6C 6F 20 43   # 7 sent
    tx 581 [8] A2 01 01 00 00 00 00 00
    rx 601 [8] C1 00 00 00 00 00 00 00
    tx 581 [8] 80 06 20 00 10 00 07 06
  )");
  EXPECT_EQ(label(), "unnamed");
}

TEST_F(SdoBlock, ValueLargerThanTheEntry_06070012) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 21 00 00 00   # 33 bytes announced for 32
    tx 581 [8] 80 06 20 00 12 00 07 06
    rx 601 [8] C0 06 20 00 00 00 00 00   # no size: found out with the data
    tx 581 [8] A4 06 20 00 05 00 00 00
    rx 601 [8] 01 61 61 61 61 61 61 61
    rx 601 [8] 02 61 61 61 61 61 61 61
    rx 601 [8] 03 61 61 61 61 61 61 61
    rx 601 [8] 04 61 61 61 61 61 61 61
    rx 601 [8] 05 61 61 61 61 61 61 61   # byte 35 of 32
    tx 581 [8] 80 06 20 00 12 00 07 06
  )");
  EXPECT_EQ(label(), "unnamed");
}

TEST_F(SdoBlock, DownloadRefusals) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 01 20 00 04 00 00 00   # read-only
    tx 581 [8] 80 01 20 00 02 00 01 06
    rx 601 [8] C6 00 30 00 04 00 00 00   # no such object
    tx 581 [8] 80 00 30 00 00 00 02 06
    rx 601 [8] C1 00 00 00 00 00 00 00   # end without a transfer
    tx 581 [8] 80 00 00 00 01 00 04 05
  )");
}

TEST_F(SdoBlock, OnlyTheEndFrameMayFollowTheLastSegment_05040001) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 03 00 00 00
    tx 581 [8] A4 06 20 00 01 00 00 00
    rx 601 [8] 81 61 62 63 00 00 00 00
    tx 581 [8] A2 01 01 00 00 00 00 00
    rx 601 [8] 01 61 62 63 00 00 00 00
    tx 581 [8] 80 06 20 00 01 00 04 05
  )");
  EXPECT_EQ(label(), "unnamed");
}

TEST_F(SdoBlock, UploadsTheDeviceNameWithCrc) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 08 10 00 7F 00 00 00   # CRC, blksize 127, pst 0
    tx 581 [8] C6 08 10 00 0D 00 00 00   # CRC, size 13
    rx 601 [8] A3 00 00 00 00 00 00 00   # start
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A2 02 7F 00 00 00 00 00
    tx 581 [8] C5 32 17 00 00 00 00 00   # end: 1 unused, CRC 0x1732
    rx 601 [8] A1 00 00 00 00 00 00 00
    silence
    rx 601 [8] 40 00 10 00 00 00 00 00   # the server is free again
    tx 581 [8] 43 00 10 00 00 00 00 00
  )");
}

// The initiate response sets sc, so the end frame carries the valid CRC even when the client did
// not ask for one: masters that check it whenever sc is set accept it, the others ignore it.
TEST_F(SdoBlock, UploadWithoutClientCrcStillSendsTheValidCrc) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A0 08 10 00 7F 00 00 00   # no CRC asked
    tx 581 [8] C6 08 10 00 0D 00 00 00   # sc 1: the server supports CRC
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A2 02 7F 00 00 00 00 00
    tx 581 [8] C5 32 17 00 00 00 00 00   # end: CRC 0x1732, as with a CRC request
    rx 601 [8] A1 00 00 00 00 00 00 00
  )");
}

TEST_F(SdoBlock, UploadUsesTheClientsBlockSizeAndRepeatsWhatWasNotAcknowledged) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 08 10 00 01 00 00 00   # blksize 1
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    rx 601 [8] A2 00 02 00 00 00 00 00   # nothing arrived; blksize 2 from now on
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A2 01 02 00 00 00 00 00   # the last segment is missing
    tx 581 [8] 81 78 61 6D 70 6C 65 00
    rx 601 [8] A2 01 02 00 00 00 00 00
    tx 581 [8] C5 32 17 00 00 00 00 00   # the CRC counts every byte once
    rx 601 [8] A1 00 00 00 00 00 00 00
  )");
}

TEST_F(SdoBlock, UploadsAnEmptyValueAsOneEmptySegment) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 08 20 00 7F 00 00 00   # the scratch pad, empty
    tx 581 [8] C6 08 20 00 00 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 81 00 00 00 00 00 00 00
    rx 601 [8] A2 01 7F 00 00 00 00 00
    tx 581 [8] DD 00 00 00 00 00 00 00   # 7 unused, CRC of nothing: 0
    rx 601 [8] A1 00 00 00 00 00 00 00
  )");
}

TEST_F(SdoBlock, ProtocolSwitchThreshold) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 08 10 00 7F 0D 00 00   # pst 13, value 13 bytes: segmented instead
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 13 78 61 6D 70 6C 65 00
    rx 601 [8] A4 00 10 00 7F 04 00 00   # pst 4, value 4 bytes: expedited
    tx 581 [8] 43 00 10 00 00 00 00 00
    rx 601 [8] A4 08 10 00 7F 0C 00 00   # pst 12, value 13 bytes: block
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] 80 08 10 00 00 00 00 08
  )");
}

TEST_F(SdoBlock, BlockSizeOutOfRange_05040002) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 08 10 00 00 00 00 00   # blksize 0
    tx 581 [8] 80 08 10 00 02 00 04 05
    rx 601 [8] A4 08 10 00 80 00 00 00   # blksize 128
    tx 581 [8] 80 08 10 00 02 00 04 05
    rx 601 [8] A4 08 10 00 01 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    rx 601 [8] A2 01 80 00 00 00 00 00   # new blksize 128
    tx 581 [8] 80 08 10 00 02 00 04 05
    rx 601 [8] A4 08 10 00 01 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    rx 601 [8] A2 01 00 00 00 00 00 00   # new blksize 0
    tx 581 [8] 80 08 10 00 02 00 04 05
  )");
}

TEST_F(SdoBlock, AcknowledgedSequenceBeyondTheSubBlock_05040003) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 08 10 00 7F 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A2 03 7F 00 00 00 00 00   # 3 of 2 sent
    tx 581 [8] 80 08 10 00 03 00 04 05
  )");
}

TEST_F(SdoBlock, UploadRefusalsAndWrongSteps_05040001) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 00 30 00 7F 00 00 00   # no such object
    tx 581 [8] 80 00 30 00 00 00 02 06
    rx 601 [8] A4 02 20 00 7F 00 00 00   # write-only
    tx 581 [8] 80 02 20 00 01 00 01 06
    rx 601 [8] A3 00 00 00 00 00 00 00   # start without a transfer
    tx 581 [8] 80 00 00 00 01 00 04 05
    rx 601 [8] A4 08 10 00 7F 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A2 00 7F 00 00 00 00 00   # acknowledgement before the start
    tx 581 [8] 80 08 10 00 01 00 04 05
    rx 601 [8] A4 08 10 00 7F 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A2 02 7F 00 00 00 00 00
    tx 581 [8] C5 32 17 00 00 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00   # start instead of the end response
    tx 581 [8] 80 08 10 00 01 00 04 05
    rx 601 [8] A4 08 10 00 7F 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A1 00 00 00 00 00 00 00   # end response instead of the acknowledgement
    tx 581 [8] 80 08 10 00 01 00 04 05
  )");
}

TEST_F(SdoBlock, EveryWaitTimesOut_05040000) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 0C 00 00 00   # download: waiting for segments
    tx 581 [8] A4 06 20 00 02 00 00 00
    wait 999
    rx 601 [8] 01 48 65 6C 6C 6F 20 43   # every segment restarts the timer
    wait 999
    silence
    wait 1
    tx 581 [8] 80 06 20 00 00 00 04 05
    rx 601 [8] C6 06 20 00 0C 00 00 00   # download: waiting for the end frame
    tx 581 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 01 48 65 6C 6C 6F 20 43
    rx 601 [8] 82 6F 73 74 61 21 00 00
    tx 581 [8] A2 02 01 00 00 00 00 00
    wait 1000
    tx 581 [8] 80 06 20 00 00 00 04 05
    rx 601 [8] A4 08 10 00 7F 00 00 00   # upload: waiting for the start
    tx 581 [8] C6 08 10 00 0D 00 00 00
    wait 1000
    tx 581 [8] 80 08 10 00 00 00 04 05
    rx 601 [8] A4 08 10 00 7F 00 00 00   # upload: waiting for the acknowledgement
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    wait 1000
    tx 581 [8] 80 08 10 00 00 00 04 05
    rx 601 [8] A4 08 10 00 7F 00 00 00   # upload: waiting for the end response
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A2 02 7F 00 00 00 00 00
    tx 581 [8] C5 32 17 00 00 00 00 00
    wait 1000
    tx 581 [8] 80 08 10 00 00 00 04 05
  )");
  EXPECT_EQ(label(), "unnamed");
}

// Every segment restarts the timer, one dropped out of sequence too: at a low bit rate the rest
// of a sub-block after a lost segment may take longer than the timeout.
TEST_F(SdoBlock, ASegmentDroppedOutOfSequenceRestartsTheTimerToo) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 0C 00 00 00
    tx 581 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 01 48 65 6C 6C 6F 20 43   # segment 1
    wait 500
    rx 601 [8] 01 48 65 6C 6C 6F 20 43   # segment 1 again: out of sequence, dropped silently
    wait 999
    silence
    wait 1
    tx 581 [8] 80 06 20 00 00 00 04 05   # 1000 ms after the last segment
  )");
  EXPECT_EQ(label(), "unnamed");
}

TEST_F(SdoBlock, ClientAbortEndsTheTransferSilently) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C6 06 20 00 0C 00 00 00
    tx 581 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 01 48 65 6C 6C 6F 20 43
    rx 601 [8] 80 06 20 00 00 00 00 08   # abort in the middle of a sub-block
    silence
    rx 601 [8] 82 6F 73 74 61 21 00 00   # no transfer: an ordinary abort frame now
    silence
    rx 601 [8] A4 08 10 00 7F 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] 80 08 10 00 00 00 00 08   # abort instead of the acknowledgement
    silence
    wait 2000
    silence
  )");
  EXPECT_EQ(label(), "unnamed");
}

}  // namespace
}  // namespace costa::test
