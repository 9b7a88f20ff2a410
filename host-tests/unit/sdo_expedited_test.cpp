// Expedited SDO transfers of every numeric type and short strings (CiA 301 7.2.4.3.3/6).
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using SdoExpedited = ExampleNodeTest;

TEST_F(SdoExpedited, UploadsEachSizeWithItsSizeIndicatedCommand) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 10 20 00 00 00 00 00   # UNSIGNED8 operating mode
    tx 581 [8] 4F 10 20 00 00 00 00 00
    rx 601 [8] 40 17 10 00 00 00 00 00   # UNSIGNED16 heartbeat time
    tx 581 [8] 4B 17 10 00 00 00 00 00
    rx 601 [8] 40 00 20 00 00 00 00 00   # UNSIGNED32 setpoint 1000
    tx 581 [8] 43 00 20 00 E8 03 00 00
    rx 601 [8] 40 09 10 00 00 00 00 00   # VISIBLE_STRING "1.0", 3 bytes
    tx 581 [8] 47 09 10 00 31 2E 30 00
  )");
}

TEST_F(SdoExpedited, UploadsSignedRealBooleanAndArrayValues) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 04 20 02 00 00 00 00   # INTEGER8 -5
    tx 581 [8] 4F 04 20 02 FB 00 00 00
    rx 601 [8] 40 04 20 03 00 00 00 00   # INTEGER32 -100000
    tx 581 [8] 43 04 20 03 60 79 FE FF
    rx 601 [8] 40 04 20 04 00 00 00 00   # REAL32 1.5
    tx 581 [8] 43 04 20 04 00 00 C0 3F
    rx 601 [8] 40 04 20 01 00 00 00 00   # BOOLEAN false
    tx 581 [8] 4F 04 20 01 00 00 00 00
    rx 601 [8] 40 05 20 00 00 00 00 00   # ARRAY sub 0 (CompactSubObj=4)
    tx 581 [8] 4F 05 20 00 04 00 00 00
    rx 601 [8] 40 05 20 04 00 00 00 00   # ARRAY sub 4
    tx 581 [8] 4B 05 20 04 34 12 00 00
    rx 601 [8] 40 11 20 00 00 00 00 00   # INTEGER16 215
    tx 581 [8] 4B 11 20 00 D7 00 00 00
  )");
}

TEST_F(SdoExpedited, UploadsConstantsIncludingNodeIdRelativeOnes) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 00 10 00 00 00 00 00
    tx 581 [8] 43 00 10 00 00 00 00 00
    rx 601 [8] 40 18 10 01 00 00 00 00
    tx 581 [8] 43 18 10 01 05 0C 00 00
    rx 601 [8] 40 00 12 01 00 00 00 00   # $NODEID+0x600
    tx 581 [8] 43 00 12 01 01 06 00 00
    rx 601 [8] 40 00 12 02 00 00 00 00   # $NODEID+0x580
    tx 581 [8] 43 00 12 02 81 05 00 00
  )");
}

TEST_F(SdoExpedited, DownloadsWithSizeIndicatedAndStoresTheValue) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 10 20 00 02 00 00 00
    tx 581 [8] 60 10 20 00 00 00 00 00
    rx 601 [8] 2B 17 10 00 E8 03 00 00
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 601 [8] 23 00 20 00 A0 86 01 00
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 601 [8] 2F 04 20 02 9C 00 00 00
    tx 581 [8] 60 04 20 02 00 00 00 00
  )");
  EXPECT_EQ(value(0x2010, 0), 2U);
  EXPECT_EQ(value(0x1017, 0), 1000U);
  EXPECT_EQ(value(0x2000, 0), 100000U);
  EXPECT_EQ(static_cast<int64_t>(value(0x2004, 2)), -100);
}

TEST_F(SdoExpedited, DownloadWithoutSizeTakesTheObjectsSize) {
  // 0x22: expedited, size not indicated; the value's own size applies.
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 10 20 00 01 00 00 00
    tx 581 [8] 60 10 20 00 00 00 00 00
    rx 601 [8] 22 00 20 00 0A 00 00 00
    tx 581 [8] 60 00 20 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2010, 0), 1U);
  EXPECT_EQ(value(0x2000, 0), 10U);
}

TEST_F(SdoExpedited, DownloadsAShortStringAndPadsIt) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 06 20 00 4F 4B 00 00   # "OK"
    tx 581 [8] 60 06 20 00 00 00 00 00
    rx 601 [8] 40 06 20 00 00 00 00 00
    tx 581 [8] 4B 06 20 00 4F 4B 00 00
  )");
}

TEST_F(SdoExpedited, WritesARealWithinItsLimits) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 04 20 04 00 00 20 41   # 10.0f is the high limit
    tx 581 [8] 60 04 20 04 00 00 00 00
    rx 601 [8] 40 04 20 04 00 00 00 00
    tx 581 [8] 43 04 20 04 00 00 20 41
  )");
}

TEST_F(SdoExpedited, WriteOnlyObjectAcceptsWrites) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 02 20 00 02 00 00 00
    tx 581 [8] 60 02 20 00 00 00 00 00
  )");
}

}  // namespace
}  // namespace costa::test
