// SDO block transfers driven by a test client: whole values of 1 byte to 10 kB up and down, with
// and without CRC, lost segments and client aborts (faults at every size, CRC errors and a lost
// last segment: sdo_block_faults_test.cpp). The scratch pad (0x2008, a DOMAIN streamed by the
// example device) takes the large values.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "block_transfer_fixture.hpp"
#include "costa/od/little_endian.hpp"

namespace costa::test {
namespace {

// Sizes: 1 byte, one whole segment, a whole 127-segment sub-block, 10 kB (several sub-blocks).
class BlockTransferSizes : public BlockTransferTest,
                           public ::testing::WithParamInterface<std::tuple<size_t, bool>> {};

TEST_P(BlockTransferSizes, DownloadAndUploadTheScratchPad) {
  const auto [size, crc] = GetParam();
  const std::vector<uint8_t> data = pattern(size);
  BlockTransferOptions options;
  options.crc = crc;
  const BlockTransferResult down = client_.download(kScratchPad, 0, data, options);
  ASSERT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;
  EXPECT_EQ(scratchPad(), data);
  EXPECT_EQ(down.subBlocks, static_cast<int>((size + 7U * 127U - 1U) / (7U * 127U)));
  const BlockTransferResult up = client_.upload(kScratchPad, 0, options);
  ASSERT_TRUE(up.ok()) << up.error << " abort " << std::hex << up.abortCode;
  EXPECT_FALSE(up.switchedProtocol);
  EXPECT_EQ(up.data, data);
  EXPECT_EQ(up.subBlocks, down.subBlocks);
  EXPECT_EQ(bus_.node().txDropped(), 0U);  // sub-blocks longer than the queue wait for room
  expectSilence();
}

INSTANTIATE_TEST_SUITE_P(All, BlockTransferSizes,
                         ::testing::Combine(::testing::Values(size_t{1}, size_t{7}, size_t{127 * 7},
                                                              size_t{10240}),
                                            ::testing::Bool()),
                         [](const auto& parameters) {
                           return std::to_string(std::get<0>(parameters.param)) + "Bytes" +
                                  (std::get<1>(parameters.param) ? "WithCrc" : "WithoutCrc");
                         });

TEST_F(BlockTransferTest, DownloadWithoutSizeIndication) {
  const std::vector<uint8_t> data = pattern(10240);
  BlockTransferOptions options;
  options.sizeIndicated = false;
  const BlockTransferResult down = client_.download(kScratchPad, 0, data, options);
  ASSERT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;
  EXPECT_EQ(scratchPad(), data);
}

// Without a size, the scratch pad learns that a value is too long only when the chunk that
// overflows its 12 KiB reaches it: the server aborts there, in the middle of a sub-block, with
// the hook's code, and the streamed value is discarded.
TEST_F(BlockTransferTest, ADownloadWithoutSizeIsAbortedWhereItOverflowsTheStreamingHook) {
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(50)).ok());
  BlockTransferOptions options;
  options.sizeIndicated = false;
  const BlockTransferResult down = client_.download(
      kScratchPad, 0, pattern(example::ExampleDevice::kScratchPadCapacity + 100U), options);
  EXPECT_EQ(down.abortCode, 0x06070012U);  // length too high
  EXPECT_EQ(device().scratchPadLength(), 0U);
  // The rest of that sub-block (the client sends a sub-block whole before it reads): requests
  // out of place now, each aborted with 0x05040001. There are some: the abort came in its middle.
  CanFrame frame;
  size_t after = 0;
  while (bus_.receive(&frame, 0)) {
    ++after;
    EXPECT_EQ(frame.id, 0x581U);
    EXPECT_EQ(frame.data[0], 0x80U);
    EXPECT_EQ(loadU32(frame.data + 4), 0x05040001U);
  }
  EXPECT_GT(after, 0U);
  const std::vector<uint8_t> data = pattern(example::ExampleDevice::kScratchPadCapacity);
  ASSERT_TRUE(client_.download(kScratchPad, 0, data, options).ok());  // exactly full: taken
  EXPECT_EQ(scratchPad(), data);
}

TEST_F(BlockTransferTest, ServerBlockSizeFollowsWhatIsLeft) {
  const std::vector<uint8_t> data = pattern(1000);  // 143 segments: 127 + 16
  const BlockTransferResult down = client_.download(kScratchPad, 0, data);
  ASSERT_TRUE(down.ok()) << down.error;
  EXPECT_EQ(down.blockSizes, (std::vector<int>{127, 16}));
}

// (bytes, block sizes the server asks for, the last acknowledgement's aside) at the edges of a
// whole block: 126 segments, 127 begun and whole, a byte and a segment more, and two begun.
class ServerBlockSizes : public BlockTransferTest,
                         public ::testing::WithParamInterface<std::pair<size_t, std::vector<int>>> {
};

TEST_P(ServerBlockSizes, FollowWhatIsLeftAndUploadTheSameBytes) {
  const auto& [size, blockSizes] = GetParam();
  const std::vector<uint8_t> data = pattern(size);
  const BlockTransferResult down = client_.download(kScratchPad, 0, data);
  ASSERT_TRUE(down.ok()) << down.error;
  EXPECT_EQ(down.blockSizes, blockSizes);
  const BlockTransferResult up = client_.upload(kScratchPad, 0);
  ASSERT_TRUE(up.ok()) << up.error;
  EXPECT_EQ(up.data, data);  // the end frame's unused bytes cut the last segment
}

INSTANTIATE_TEST_SUITE_P(All, ServerBlockSizes,
                         ::testing::Values(std::pair{size_t{882}, std::vector<int>{126}},
                                           std::pair{size_t{883}, std::vector<int>{127}},
                                           std::pair{size_t{889}, std::vector<int>{127}},
                                           std::pair{size_t{890}, std::vector<int>{127, 1}},
                                           std::pair{size_t{895}, std::vector<int>{127, 1}},
                                           std::pair{size_t{896}, std::vector<int>{127, 1}},
                                           std::pair{size_t{897}, std::vector<int>{127, 2}}),
                         [](const auto& parameters) {
                           return std::to_string(parameters.param.first) + "Bytes";
                         });

TEST_F(BlockTransferTest, LostDownloadSegmentIsRepeated) {
  const std::vector<uint8_t> data = pattern(10240);
  BlockTransferOptions options;
  options.loseSegment = 127 + 40;  // the 41st of the second sub-block
  const BlockTransferResult down = client_.download(kScratchPad, 0, data, options);
  ASSERT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;
  EXPECT_EQ(scratchPad(), data);
  EXPECT_EQ(down.subBlocks, 13);  // one more than without the loss
}

// (segment lost, sub-blocks needed): the first, one in the middle, the very last; 12 sub-blocks
// without a loss.
class LostUploadSegment : public BlockTransferTest,
                          public ::testing::WithParamInterface<std::pair<int, int>> {};

TEST_P(LostUploadSegment, IsRepeated) {
  const auto [lost, subBlocks] = GetParam();
  const std::vector<uint8_t> data = pattern(10240);
  ASSERT_TRUE(client_.download(kScratchPad, 0, data).ok());
  BlockTransferOptions options;
  options.loseSegment = lost;
  const BlockTransferResult up = client_.upload(kScratchPad, 0, options);
  ASSERT_TRUE(up.ok()) << up.error << " abort " << std::hex << up.abortCode;
  EXPECT_EQ(up.data, data);
  EXPECT_EQ(up.subBlocks, subBlocks);
  expectSilence();
}

INSTANTIATE_TEST_SUITE_P(All, LostUploadSegment,
                         ::testing::Values(std::pair{0, 13}, std::pair{200, 12},
                                           std::pair{1462, 13}),
                         [](const auto& parameters) {
                           return "Segment" + std::to_string(parameters.param.first);
                         });

TEST_F(BlockTransferTest, UploadSubBlockWaitsWhileTheControllerRefuses) {
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(10240)).ok());
  ASSERT_EQ(playText(R"(
    rx 601 [8] A4 08 20 00 7F 00 00 00
    tx 581 [8] C6 08 20 00 00 28 00 00
  )",
                     bus_),
            "");
  bus_.can().setAccepting(false);
  ASSERT_EQ(playText("rx 601 [8] A3 00 00 00 00 00 00 00", bus_), "");
  bus_.advance(500000);  // no busy loop (the bus would fail the test), no timeout either
  EXPECT_EQ(bus_.unread(), 0U);
  bus_.can().setAccepting(true);
  bus_.node().flushTx();
  bus_.advance(1);
  CanFrame frame;
  for (int sequence = 1; sequence <= 127; ++sequence) {
    ASSERT_TRUE(bus_.receive(&frame, 0)) << "segment " << sequence;
    EXPECT_EQ(frame.data[0], sequence);
  }
  EXPECT_EQ(bus_.unread(), 0U);
  EXPECT_EQ(bus_.node().txDropped(), 0U);
  EXPECT_EQ(playText("rx 601 [8] 80 08 20 00 00 00 00 08", bus_), "");
}

TEST_F(BlockTransferTest, SmallUploadBlockSizes) {
  const std::vector<uint8_t> data = pattern(100);
  ASSERT_TRUE(client_.download(kScratchPad, 0, data).ok());
  for (const uint8_t blockSize : {uint8_t{1}, uint8_t{2}, uint8_t{14}, uint8_t{15}}) {
    BlockTransferOptions options;
    options.blockSize = blockSize;
    const BlockTransferResult up = client_.upload(kScratchPad, 0, options);
    ASSERT_TRUE(up.ok()) << up.error;
    EXPECT_EQ(up.data, data);
    EXPECT_EQ(up.subBlocks, (15 + blockSize - 1) / blockSize);
  }
}

TEST_F(BlockTransferTest, ClientAbortInTheMiddleOfADownload) {
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(50)).ok());
  BlockTransferOptions options;
  options.abortAfterSubBlocks = 2;
  const BlockTransferResult down = client_.download(kScratchPad, 0, pattern(10240), options);
  EXPECT_EQ(down.abortCode, 0U);
  EXPECT_EQ(down.error, "");
  bus_.advance(5000000);
  expectSilence();  // no timeout abort: the transfer is gone
  EXPECT_EQ(device().scratchPadLength(), 0U);
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(20)).ok());
  EXPECT_EQ(scratchPad(), pattern(20));
}

TEST_F(BlockTransferTest, ClientAbortInTheMiddleOfAnUpload) {
  const std::vector<uint8_t> data = pattern(10240);
  ASSERT_TRUE(client_.download(kScratchPad, 0, data).ok());
  BlockTransferOptions options;
  options.abortAfterSubBlocks = 1;
  EXPECT_TRUE(client_.upload(kScratchPad, 0, options).ok());
  bus_.advance(5000000);
  expectSilence();
  const BlockTransferResult up = client_.upload(kScratchPad, 0);
  ASSERT_TRUE(up.ok()) << up.error;
  EXPECT_EQ(up.data, data);
}

TEST_F(BlockTransferTest, OrdinaryEntries) {
  const BlockTransferResult name = client_.upload(0x1008, 0);
  ASSERT_TRUE(name.ok()) << name.error;
  EXPECT_EQ(std::string(name.data.begin(), name.data.end()), "Costa example");
  const BlockTransferResult type = client_.upload(0x1000, 0);
  ASSERT_TRUE(type.ok()) << type.error;
  EXPECT_EQ(type.data, (std::vector<uint8_t>{0, 0, 0, 0}));
  const BlockTransferResult hours = client_.upload(0x2004, 6);
  ASSERT_TRUE(hours.ok()) << hours.error;
  EXPECT_EQ(hours.data, (std::vector<uint8_t>{8, 7, 6, 5, 4, 3, 2, 1}));
  const std::string text = "thirty-two characters, exactly!!";
  ASSERT_TRUE(client_.download(0x2006, 0, std::vector<uint8_t>(text.begin(), text.end())).ok());
  const BlockTransferResult label = client_.upload(0x2006, 0);
  ASSERT_TRUE(label.ok()) << label.error;
  EXPECT_EQ(std::string(label.data.begin(), label.data.end()), text);
  ASSERT_TRUE(client_.download(0x1017, 0, {0xE8, 0x03}).ok());
  EXPECT_EQ(bus_.node().dictionary().readUnsigned(0x1017, 0, 0), 1000U);
}

TEST_F(BlockTransferTest, ProtocolSwitchThreshold) {
  BlockTransferOptions options;
  options.protocolSwitch = 13;
  const BlockTransferResult segmented = client_.upload(0x1008, 0, options);
  ASSERT_TRUE(segmented.ok()) << segmented.error;
  EXPECT_TRUE(segmented.switchedProtocol);
  EXPECT_EQ(std::string(segmented.data.begin(), segmented.data.end()), "Costa example");
  options.protocolSwitch = 12;
  const BlockTransferResult block = client_.upload(0x1008, 0, options);
  ASSERT_TRUE(block.ok()) << block.error;
  EXPECT_FALSE(block.switchedProtocol);
  EXPECT_EQ(std::string(block.data.begin(), block.data.end()), "Costa example");
}

TEST_F(BlockTransferTest, TooLargeForTheScratchPad) {
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(50)).ok());
  const std::vector<uint8_t> tooLarge = pattern(12 * 1024 + 1);
  EXPECT_EQ(client_.download(kScratchPad, 0, tooLarge).abortCode, 0x06070012U);
  EXPECT_EQ(scratchPad(), pattern(50));  // refused before any data: content kept
  BlockTransferOptions options;
  options.sizeIndicated = false;
  EXPECT_EQ(client_.download(kScratchPad, 0, tooLarge, options).abortCode, 0x06070012U);
  EXPECT_EQ(device().scratchPadLength(), 0U);  // found out on the way: discarded
  ASSERT_TRUE(client_.download(kScratchPad, 0, pattern(12 * 1024)).ok());
  EXPECT_EQ(scratchPad(), pattern(12 * 1024));
}

}  // namespace
}  // namespace costa::test
