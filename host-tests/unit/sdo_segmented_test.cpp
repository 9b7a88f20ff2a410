// Segmented SDO transfers (CiA 301 7.2.4.3.4/5, 7.2.4.3.7/8): toggling, size indication,
// the last segment's unused-byte count.
#include <cstring>

#include "example_fixture.hpp"

namespace costa::test {
namespace {

using SdoSegmented = ExampleNodeTest;

TEST_F(SdoSegmented, UploadsTheDeviceName) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00   # 13 bytes follow
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65   # "Costa e"
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 13 78 61 6D 70 6C 65 00   # "xample", 1 byte unused, last
  )");
}

TEST_F(SdoSegmented, UploadsSixtyFourBitValues) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 04 20 05 00 00 00 00   # INTEGER64 -1
    tx 581 [8] 41 04 20 05 08 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 FF FF FF FF FF FF FF
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 1D FF 00 00 00 00 00 00
    rx 601 [8] 40 04 20 06 00 00 00 00   # UNSIGNED64 0x0102030405060708
    tx 581 [8] 41 04 20 06 08 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 08 07 06 05 04 03 02
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 1D 01 00 00 00 00 00 00
    rx 601 [8] 40 04 20 07 00 00 00 00   # REAL64 0.25
    tx 581 [8] 41 04 20 07 08 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 00 00 00 00 00 00 D0
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 1D 3F 00 00 00 00 00 00
  )");
}

TEST_F(SdoSegmented, UploadsAnOctetStringOfExactlySevenBytesPerSegment) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 07 20 00 00 00 00 00
    tx 581 [8] 41 07 20 00 08 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 00 11 22 33 44 55 66
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 1D 77 00 00 00 00 00 00
  )");
}

TEST_F(SdoSegmented, EmptyStringUploadsAsZeroBytes) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 06 20 00 00 00 00 00   # expedited "" (one NUL byte)
    tx 581 [8] 60 06 20 00 00 00 00 00
    rx 601 [8] 40 06 20 00 00 00 00 00
    tx 581 [8] 41 06 20 00 00 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 0F 00 00 00 00 00 00 00   # no data, 7 unused, last
  )");
}

TEST_F(SdoSegmented, DownloadsAStringWithSizeIndicated) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 06 20 00 0C 00 00 00   # 12 bytes: "Hello Costa!"
    tx 581 [8] 60 06 20 00 00 00 00 00
    rx 601 [8] 00 48 65 6C 6C 6F 20 43
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 15 6F 73 74 61 21 00 00   # toggle 1, 2 unused, last
    tx 581 [8] 30 00 00 00 00 00 00 00
  )");
  const auto& dictionary = bus_.node().dictionary();
  const od::EntryRef label = dictionary.find(0x2006, 0);
  ASSERT_TRUE(label.valid());
  uint8_t text[40] = {};
  ASSERT_EQ(dictionary.read(label, 0, text, sizeof(text)), 12U);
  EXPECT_EQ(std::memcmp(text, "Hello Costa!", 12), 0);
}

TEST_F(SdoSegmented, DownloadsWithoutSizeIndicated) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 20 06 20 00 00 00 00 00
    tx 581 [8] 60 06 20 00 00 00 00 00
    rx 601 [8] 00 61 62 63 64 65 66 67
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 10 68 69 6A 6B 6C 6D 6E
    tx 581 [8] 30 00 00 00 00 00 00 00
    rx 601 [8] 0B 6F 70 00 00 00 00 00   # toggle 0, 5 unused, last
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 40 06 20 00 00 00 00 00
    tx 581 [8] 41 06 20 00 10 00 00 00
  )");
}

TEST_F(SdoSegmented, DownloadsANumericValueSegmented) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 04 20 06 08 00 00 00
    tx 581 [8] 60 04 20 06 00 00 00 00
    rx 601 [8] 00 11 22 33 44 55 66 77
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 1D 88 00 00 00 00 00 00
    tx 581 [8] 30 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2004, 6), 0x8877665544332211ULL);
}

TEST_F(SdoSegmented, ANewTransferMayFollowACompletedOne) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 0A 10 00 00 00 00 00   # "0.1.0", 5 bytes: segmented
    tx 581 [8] 41 0A 10 00 05 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 05 30 2E 31 2E 30 00 00
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 E8 03 00 00
  )");
}

TEST_F(SdoSegmented, ClientAbortEndsTheTransferSilently) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 80 08 10 00 00 00 04 05
    silence
    rx 601 [8] 60 00 00 00 00 00 00 00   # no transfer any more
    tx 581 [8] 80 00 00 00 01 00 04 05
  )");
}

TEST_F(SdoSegmented, TimeoutRestartsWithEverySegment) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    wait 900
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65
    wait 900
    silence
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 13 78 61 6D 70 6C 65 00
  )");
}

TEST_F(SdoSegmented, TheTimeoutCountsFromTheLatestSegment) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    wait 900
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65
    wait 999                             # 1899 ms after the initiate
    silence
    wait 1                               # 1000 ms after the segment
    tx 581 [8] 80 08 10 00 00 00 04 05
  )");
}

}  // namespace
}  // namespace costa::test
