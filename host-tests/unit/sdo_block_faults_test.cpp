// SDO block transfer faults at every size of the block transfer tests (1 byte, one segment, one
// whole sub-block of 127 segments, 10 kB), with and without CRC: lost segments in both
// directions, a corrupted CRC, and a lost last segment of a download, which only the SDO
// timeout ends (CiA 301 7.2.4.3.9: the server cannot tell that the transfer is over).
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "block_transfer_fixture.hpp"
#include "costa/crc16.hpp"

namespace costa::test {
namespace {

constexpr Microseconds kSdoTimeout = 1000000;  // the example's NodeSettings::sdoTimeout

int segmentsOf(size_t size) {
  return static_cast<int>((size + 6U) / 7U);
}
int subBlocksOf(size_t size) {
  return static_cast<int>((size + 7U * 127U - 1U) / (7U * 127U));
}

using SizeAndCrc = std::tuple<size_t, bool>;

std::string nameOf(const ::testing::TestParamInfo<SizeAndCrc>& parameters) {
  return std::to_string(std::get<0>(parameters.param)) + "Bytes" +
         (std::get<1>(parameters.param) ? "WithCrc" : "WithoutCrc");
}

class BlockFaults : public BlockTransferTest, public ::testing::WithParamInterface<SizeAndCrc> {
 protected:
  size_t size() const { return std::get<0>(GetParam()); }
  BlockTransferOptions options() const {
    BlockTransferOptions options;
    options.crc = std::get<1>(GetParam());
    return options;
  }
};

// Download, a segment before the last one lost: the server acknowledges what it received in
// order at the end of the sub-block and the client repeats from there (sizes with at least
// two segments).
class LostDownloadSegmentAtEverySize : public BlockFaults {};

TEST_P(LostDownloadSegmentAtEverySize, IsRepeatedFromTheLastAcknowledgedOne) {
  const std::vector<uint8_t> data = pattern(size());
  const int segments = segmentsOf(size());
  ASSERT_GE(segments, 2);
  for (const int lost : {0, segments / 2, segments - 2}) {
    SCOPED_TRACE("segment " + std::to_string(lost) + " lost");
    ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(3)).ok());
    BlockTransferOptions options = this->options();
    options.loseSegment = lost;
    const BlockTransferResult down = client_.download(kScratchPad, 0, data, options);
    ASSERT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;
    EXPECT_EQ(scratchPad(), data);
    // The full sub-blocks before the gap, the one with the gap, then from the lost segment on
    // again: the server asks for what is left, at most 127.
    const int before = lost / 127;
    const int left = segments - lost;
    EXPECT_EQ(down.subBlocks, before + 1 + (left + 126) / 127);
    ASSERT_GT(down.blockSizes.size(), static_cast<size_t>(before + 1));
    EXPECT_EQ(down.blockSizes[static_cast<size_t>(before) + 1U], left < 127 ? left : 127);
    expectSilence();
  }
}

INSTANTIATE_TEST_SUITE_P(All, LostDownloadSegmentAtEverySize,
                         ::testing::Combine(::testing::Values(size_t{127 * 7}, size_t{10240}),
                                            ::testing::Bool()),
                         nameOf);

// Upload, the first or the last segment lost: the client acknowledges the segments before it,
// the server sends the rest again.
class LostUploadSegmentAtEverySize : public BlockFaults {};

TEST_P(LostUploadSegmentAtEverySize, IsSentAgain) {
  const std::vector<uint8_t> data = pattern(size());
  ASSERT_TRUE(client_.download(kScratchPad, 0, data).ok());
  for (const int lost : {0, segmentsOf(size()) - 1}) {
    SCOPED_TRACE("segment " + std::to_string(lost) + " lost");
    BlockTransferOptions options = this->options();
    options.loseSegment = lost;
    const BlockTransferResult up = client_.upload(kScratchPad, 0, options);
    ASSERT_TRUE(up.ok()) << up.error << " abort " << std::hex << up.abortCode;
    EXPECT_EQ(up.data, data);
    EXPECT_EQ(up.subBlocks, subBlocksOf(size()) + 1);
    expectSilence();
  }
}

// A CRC that does not match: with CRC agreed, abort 0x05040004 and the streamed scratch pad
// discarded (the example overwrites it in place, so nothing valid is left); without CRC the
// end frame's CRC field is not looked at and the value is taken.
class CorruptedCrcAtEverySize : public BlockFaults {};

TEST_P(CorruptedCrcAtEverySize, AbortsWhenTheCrcIsAgreedAndIsIgnoredOtherwise) {
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(50)).ok());
  BlockTransferOptions options = this->options();
  options.corruptCrc = true;
  const std::vector<uint8_t> data = pattern(size());
  const BlockTransferResult down = client_.download(kScratchPad, 0, data, options);
  if (options.crc) {
    EXPECT_EQ(down.abortCode, kCrcError);
    EXPECT_EQ(device().scratchPadLength(), 0U);
  } else {
    ASSERT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;
    EXPECT_EQ(scratchPad(), data);
  }
  expectSilence();
}

// The same for a value collected in the SDO buffer (the 32-byte label 0x2006): with CRC agreed,
// the old value stays.
class CorruptedCrcOfABufferedValue : public BlockFaults {};

TEST_P(CorruptedCrcOfABufferedValue, AbortsWhenTheCrcIsAgreedAndIsIgnoredOtherwise) {
  BlockTransferOptions options = this->options();
  options.corruptCrc = true;
  const std::vector<uint8_t> data(size(), 'k');
  const BlockTransferResult down = client_.download(0x2006, 0, data, options);
  const BlockTransferResult up = client_.upload(0x2006, 0);
  ASSERT_TRUE(up.ok()) << up.error;
  if (options.crc) {
    EXPECT_EQ(down.abortCode, kCrcError);
    EXPECT_EQ(std::string(up.data.begin(), up.data.end()), "unnamed");
  } else {
    ASSERT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;
    EXPECT_EQ(up.data, data);
  }
  expectSilence();
}

INSTANTIATE_TEST_SUITE_P(All, CorruptedCrcOfABufferedValue,
                         ::testing::Combine(::testing::Values(size_t{1}, size_t{7}, size_t{32}),
                                            ::testing::Bool()),
                         nameOf);

// Download, the last segment (c = 1) lost: the server still waits for the rest of the
// sub-block, answers nothing, and aborts 0x05040000 one SDO timeout after the last segment it
// received; the streamed value is discarded and the next transfer works.
class LostLastDownloadSegment : public BlockFaults {};

TEST_P(LostLastDownloadSegment, EndsInTheSdoTimeout) {
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(50)).ok());
  BlockTransferOptions options = this->options();
  options.loseSegment = segmentsOf(size()) - 1;
  const BlockTransferResult down = client_.download(kScratchPad, 0, pattern(size()), options);
  EXPECT_EQ(down.error, "the server sent nothing");
  EXPECT_EQ(down.abortCode, 0U);
  bus_.advance(kSdoTimeout - 1);
  expectSilence();
  bus_.advance(1);
  EXPECT_EQ(playText("tx 581 [8] 80 08 20 00 00 00 04 05\nsilence", bus_), "");
  EXPECT_EQ(device().scratchPadLength(), 0U);
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(size()), this->options()).ok());
  EXPECT_EQ(scratchPad(), pattern(size()));
}

const auto kEverySize = ::testing::Combine(
    ::testing::Values(size_t{1}, size_t{7}, size_t{127 * 7}, size_t{10240}), ::testing::Bool());
INSTANTIATE_TEST_SUITE_P(All, LostUploadSegmentAtEverySize, kEverySize, nameOf);
INSTANTIATE_TEST_SUITE_P(All, CorruptedCrcAtEverySize, kEverySize, nameOf);
INSTANTIATE_TEST_SUITE_P(All, LostLastDownloadSegment, kEverySize, nameOf);

// The same frame by frame: two segments announced, the second (last) one lost.
TEST_F(BlockTransferTest, LostLastDownloadSegmentFrameByFrame) {
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(50)).ok());
  EXPECT_EQ(playText(R"(
    rx 601 [8] C6 08 20 00 0A 00 00 00   # block download 0x2008, CRC, 10 bytes
    tx 581 [8] A4 08 20 00 02 00 00 00   # blksize 2
    rx 601 [8] 01 00 07 0E 15 1C 23 2A   # 1: bytes 0..6
    silence                              # segment 2 (c = 1) never arrives
    wait 999
    silence
    wait 1
    tx 581 [8] 80 08 20 00 00 00 04 05   # SDO protocol timed out
    rx 601 [8] 82 31 38 00 00 00 00 00   # segment 2 too late: an idle server takes 0x82 for
    silence                              # an abort request (ccs 4) and stays silent
  )",
                     bus_),
            "");
  EXPECT_EQ(device().scratchPadLength(), 0U);
}

/// The `rx` line of download segment `sequence` of a sub-block that starts at segment
/// `firstOfSubBlock` of `data` (0x80 when it is the last one of all).
std::string segmentLine(const std::vector<uint8_t>& data, int sequence, bool lastOfAll,
                        int firstOfSubBlock = 0) {
  uint8_t frame[8] = {static_cast<uint8_t>(sequence | (lastOfAll ? 0x80 : 0))};
  const size_t from = static_cast<size_t>(firstOfSubBlock + sequence - 1) * 7U;
  for (size_t i = 0; i < 7U && from + i < data.size(); ++i) {
    frame[1U + i] = data[from + i];
  }
  return "rx 601 [8] " + hexBytes(frame, 8) + "\n";
}

/// The lines of a block download of `data` to the scratch pad up to its first sub-block: the
/// initiate (with CRC or not, the size indicated), the server's blksize 127, segments 1..127.
std::string firstSubBlockLines(const std::vector<uint8_t>& data, bool crc) {
  const size_t size = data.size();
  const uint8_t initiate[8] = {
      static_cast<uint8_t>(crc ? 0xC6 : 0xC2), 0x08, 0x20, 0, static_cast<uint8_t>(size),
      static_cast<uint8_t>(size >> 8U)};
  std::string text =
      "rx 601 [8] " + hexBytes(initiate, 8) + "\n" + "tx 581 [8] A4 08 20 00 7F 00 00 00\n";
  for (int sequence = 1; sequence <= 127; ++sequence) {
    text += segmentLine(data, sequence, false);
  }
  return text;
}

// A segment that closed a sub-block, received twice (a controller may deliver a frame twice):
// the copy is ignored, before a smaller next sub-block (no 0x05040003), before one as large
// (no second acknowledgement) and after the last segment (no 0x05040001), without CRC and with.
TEST_F(BlockTransferTest, ARepeatedClosingSegmentIsIgnored) {
  for (const bool crc : {false, true}) {
    SCOPED_TRACE(crc ? "with CRC" : "without CRC");
    // 127 + 2 segments, then 127 + 127.
    for (const size_t size : {size_t{127 * 7 + 10}, size_t{2 * 127 * 7}}) {
      SCOPED_TRACE(std::to_string(size) + " bytes");
      const std::vector<uint8_t> data = pattern(size);
      const int rest = segmentsOf(size) - 127;
      std::string text = firstSubBlockLines(data, crc);
      const uint8_t firstAck[8] = {0xA2, 0x7F, static_cast<uint8_t>(rest)};
      text += "tx 581 [8] " + hexBytes(firstAck, 8) + "\n";
      text += segmentLine(data, 127, false) + "silence\n";  // the closing segment again
      for (int sequence = 1; sequence <= rest; ++sequence) {
        text += segmentLine(data, sequence, sequence == rest, 127);
      }
      const uint8_t lastAck[8] = {0xA2, static_cast<uint8_t>(rest), 0x01};
      text += "tx 581 [8] " + hexBytes(lastAck, 8) + "\n";
      text += segmentLine(data, rest, true, 127) + "silence\n";  // the last segment again
      const size_t unused = static_cast<size_t>(segmentsOf(size)) * 7U - size;
      const uint16_t value = crc16(data.data(), data.size());
      const uint8_t end[8] = {static_cast<uint8_t>(0xC1U | (unused << 2U)),
                              static_cast<uint8_t>(value), static_cast<uint8_t>(value >> 8U)};
      text += "rx 601 [8] " + hexBytes(end, 8) + "\ntx 581 [8] A1 00 00 00 00 00 00 00\n";
      EXPECT_EQ(playText(text, bus_), "");
      EXPECT_EQ(scratchPad(), data);
    }
  }
}

// The exception the header states: a last segment numbered 65 (127 + 65 whole segments) has
// the first byte of an end request (0xC1: 110, 0 unused bytes, cs 1), so its repeat is answered
// as one. Without CRC the transfer then ends with every byte received and the value written, and
// the client's own end finds no transfer; with CRC, bytes 1 and 2 of the segment are no CRC of
// the value: 0x05040004, and the streamed scratch pad is left empty (as after any CRC error).
TEST_F(BlockTransferTest, ARepeatedLastSegmentNumbered65IsTakenForTheEndRequest) {
  const size_t size = (127 + 65) * 7;
  const std::vector<uint8_t> data = pattern(size);
  for (const bool crc : {false, true}) {
    SCOPED_TRACE(crc ? "with CRC" : "without CRC");
    std::string text = firstSubBlockLines(data, crc);
    text += "tx 581 [8] A2 7F 41 00 00 00 00 00\n";
    for (int sequence = 1; sequence <= 65; ++sequence) {
      text += segmentLine(data, sequence, sequence == 65, 127);
    }
    text += "tx 581 [8] A2 41 01 00 00 00 00 00\n";
    text += segmentLine(data, 65, true, 127);  // again: C1 ...
    text += crc ? "tx 581 [8] 80 08 20 00 04 00 04 05\n" : "tx 581 [8] A1 00 00 00 00 00 00 00\n";
    const uint16_t value = crc16(data.data(), data.size());
    const uint8_t end[8] = {0xC1, static_cast<uint8_t>(value), static_cast<uint8_t>(value >> 8U)};
    text += "rx 601 [8] " + hexBytes(end, 8) + "\ntx 581 [8] 80 00 00 00 01 00 04 05\n";
    EXPECT_EQ(playText(text, bus_), "");
    EXPECT_EQ(scratchPad(), crc ? std::vector<uint8_t>{} : data);
  }
}

}  // namespace
}  // namespace costa::test
