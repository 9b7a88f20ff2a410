// Additional SDO servers (CiA 301 7.5.2.33, 0x1201..0x127F) through wire frames. The example
// has one, 0x1201, not valid by default (both COB-IDs 0x80000000, client node-id 1); the tests
// give it 0x681 (client -> server) and 0x6C1 (server -> client) through the default server.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

constexpr const char* kConfigure = R"(
  rx 601 [8] 23 01 12 01 81 06 00 00   # 0x1201:01 = 0x681, valid
  tx 581 [8] 60 01 12 01 00 00 00 00
  rx 601 [8] 23 01 12 02 C1 06 00 00   # 0x1201:02 = 0x6C1, valid
  tx 581 [8] 60 01 12 02 00 00 00 00
)";

class SdoServersTest : public ExampleNodeTest {
 protected:
  void configure() { ASSERT_EQ(play(kConfigure), ""); }
};

TEST_F(SdoServersTest, TheAdditionalServerIsNotValidByDefaultAndAnswersNothing) {
  EXPECT_TRANSCRIPT(R"(
    rx 681 [8] 40 00 10 00 00 00 00 00
    silence
    rx 601 [8] 40 01 12 00 00 00 00 00
    tx 581 [8] 4F 01 12 00 03 00 00 00
    rx 601 [8] 40 01 12 01 00 00 00 00
    tx 581 [8] 43 01 12 01 00 00 00 80
    rx 601 [8] 40 01 12 02 00 00 00 00
    tx 581 [8] 43 01 12 02 00 00 00 80
    rx 601 [8] 40 01 12 03 00 00 00 00
    tx 581 [8] 4F 01 12 03 01 00 00 00
  )");
  EXPECT_EQ(bus_.node().sdoServers().count(), 1U);
}

TEST_F(SdoServersTest, AValidServerAnswersOnItsOwnCanIds) {
  configure();
  EXPECT_TRANSCRIPT(R"(
    rx 681 [8] 40 01 12 01 00 00 00 00
    tx 6C1 [8] 43 01 12 01 81 06 00 00
    rx 681 [8] 2F 01 12 03 05 00 00 00   # client node-id 5, written through the server itself
    tx 6C1 [8] 60 01 12 03 00 00 00 00
    rx 601 [8] 40 01 12 03 00 00 00 00
    tx 581 [8] 4F 01 12 03 05 00 00 00
    rx 681 [8] 40 00 30 00 00 00 00 00   # no such object: the abort on 0x6C1 too
    tx 6C1 [8] 80 00 30 00 00 00 02 06
  )");
}

TEST_F(SdoServersTest, TwoMastersTalkToTwoServersAtOnce) {
  configure();
  // Master A uploads the device name (13 bytes) from the default server while master B
  // downloads 8 bytes to 0x2004:06 through 0x1201, their segments interleaved.
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 681 [8] 21 04 20 06 08 00 00 00
    tx 6C1 [8] 60 04 20 06 00 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65   # "Costa e"
    rx 681 [8] 00 11 22 33 44 55 66 77
    tx 6C1 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 13 78 61 6D 70 6C 65 00   # "xample", last
    rx 681 [8] 1D 88 00 00 00 00 00 00   # toggle 1, 1 byte, last
    tx 6C1 [8] 30 00 00 00 00 00 00 00
    rx 681 [8] 40 04 20 06 00 00 00 00   # B reads back through its server
    tx 6C1 [8] 41 04 20 06 08 00 00 00
    rx 601 [8] 40 08 10 00 00 00 00 00   # A starts again meanwhile
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 681 [8] 60 00 00 00 00 00 00 00
    tx 6C1 [8] 00 11 22 33 44 55 66 77
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65
    rx 681 [8] 70 00 00 00 00 00 00 00
    tx 6C1 [8] 1D 88 00 00 00 00 00 00
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 13 78 61 6D 70 6C 65 00
  )");
  EXPECT_EQ(value(0x2004, 6), 0x8877665544332211U);
  EXPECT_FALSE(bus_.node().sdo().busy());
  EXPECT_TRUE(bus_.node().sdoServers().valid());
}

TEST_F(SdoServersTest, ACobIdWithA29BitOrReservedBitIsRefused) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 01 12 01 81 06 00 20   # bit 29: 29-bit CAN-ID
    tx 581 [8] 80 01 12 01 30 00 09 06
    rx 601 [8] 23 01 12 02 C1 0E 00 80   # bit 11, not valid
    tx 581 [8] 80 01 12 02 30 00 09 06
    rx 601 [8] 23 01 12 01 FF FF FF FF
    tx 581 [8] 80 01 12 01 30 00 09 06
  )");
  EXPECT_EQ(value(0x1201, 1), 0x80000000U);
  EXPECT_EQ(value(0x1201, 2), 0x80000000U);
}

TEST_F(SdoServersTest, AValidEntryTakesNoRestrictedCanId) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 01 12 01 01 06 00 00   # 0x601: the default server's
    tx 581 [8] 80 01 12 01 30 00 09 06
    rx 601 [8] 23 01 12 02 81 05 00 00   # 0x581
    tx 581 [8] 80 01 12 02 30 00 09 06
    rx 601 [8] 23 01 12 01 00 00 00 00   # 0x000: NMT
    tx 581 [8] 80 01 12 01 30 00 09 06
    rx 601 [8] 23 01 12 01 01 06 00 80   # 0x601 while not valid: kept
    tx 581 [8] 60 01 12 01 00 00 00 00
    rx 601 [8] 23 01 12 01 01 06 00 00   # and made valid: refused
    tx 581 [8] 80 01 12 01 30 00 09 06
  )");
  EXPECT_EQ(value(0x1201, 1), 0x80000601U);
}

TEST_F(SdoServersTest, TheCanIdChangesOnlyWhileTheEntryIsNotValid) {
  configure();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 01 12 01 82 06 00 00   # valid 0x681 -> valid 0x682
    tx 581 [8] 80 01 12 01 30 00 09 06
    rx 601 [8] 23 01 12 02 C2 06 00 00   # valid 0x6C1 -> valid 0x6C2
    tx 581 [8] 80 01 12 02 30 00 09 06
    rx 601 [8] 23 01 12 01 81 06 00 40   # bit 30 (dynamic) while valid
    tx 581 [8] 80 01 12 01 30 00 09 06
    rx 601 [8] 23 01 12 01 81 06 00 00   # the same value again
    tx 581 [8] 60 01 12 01 00 00 00 00
    rx 601 [8] 23 01 12 01 82 06 00 80   # not valid, with the new CAN-ID at once
    tx 581 [8] 60 01 12 01 00 00 00 00
    rx 681 [8] 40 00 10 00 00 00 00 00   # the old CAN-ID is served no longer
    silence
    rx 601 [8] 23 01 12 01 82 06 00 00   # valid again on 0x682
    tx 581 [8] 60 01 12 01 00 00 00 00
    rx 682 [8] 40 01 12 01 00 00 00 00
    tx 6C1 [8] 43 01 12 01 82 06 00 00
  )");
}

TEST_F(SdoServersTest, TheClientNodeIdIsOneTo127) {
  ASSERT_TRUE(bus_.node().profile().sdo.distinguishHighAndLowValues);  // the example's profile
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 01 12 03 7F 00 00 00
    tx 581 [8] 60 01 12 03 00 00 00 00
    rx 601 [8] 2F 01 12 03 00 00 00 00
    tx 581 [8] 80 01 12 03 32 00 09 06   # below: 0x06090032
    rx 601 [8] 2F 01 12 03 80 00 00 00
    tx 581 [8] 80 01 12 03 31 00 09 06   # above: 0x06090031
  )");
  EXPECT_EQ(value(0x1201, 3), 0x7FU);
}

TEST_F(SdoServersTest, AChangedCobIdEndsTheTransferInProgressOnThatServer) {
  configure();
  EXPECT_TRANSCRIPT(R"(
    rx 681 [8] 40 08 10 00 00 00 00 00   # a segmented upload on 0x1201
    tx 6C1 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 23 01 12 02 C1 06 00 80   # its responses not valid: it stops serving
    tx 581 [8] 60 01 12 02 00 00 00 00
    rx 681 [8] 60 00 00 00 00 00 00 00
    silence
    rx 601 [8] 23 01 12 02 C2 06 00 00   # valid again, on 0x6C2
    tx 581 [8] 60 01 12 02 00 00 00 00
    rx 681 [8] 60 00 00 00 00 00 00 00   # the upload is gone: a segment out of place
    tx 6C2 [8] 80 00 00 00 01 00 04 05
    wait 2000
    silence
  )");
  EXPECT_TRUE(bus_.node().sdoServers().valid());
}

TEST_F(SdoServersTest, ATransferOnTheAdditionalServerTimesOutOnItsOwnChannel) {
  configure();
  EXPECT_TRANSCRIPT(R"(
    rx 681 [8] 40 08 10 00 00 00 00 00
    tx 6C1 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65
    wait 2000                            # both time out (the default server first)
    tx 581 [8] 80 08 10 00 00 00 04 05
    tx 6C1 [8] 80 08 10 00 00 00 04 05
  )");
}

TEST_F(SdoServersTest, ResetCommunicationRestoresTheDefaultsAndEndsTheTransfer) {
  configure();
  EXPECT_TRANSCRIPT(R"(
    rx 681 [8] 40 08 10 00 00 00 00 00
    tx 6C1 [8] 41 08 10 00 0D 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    rx 681 [8] 60 00 00 00 00 00 00 00
    silence
    rx 601 [8] 40 01 12 01 00 00 00 00
    tx 581 [8] 43 01 12 01 00 00 00 80
    rx 601 [8] 40 01 12 02 00 00 00 00
    tx 581 [8] 43 01 12 02 00 00 00 80
    wait 2000
    silence
  )");
  EXPECT_TRUE(bus_.node().sdoServers().valid());
}

TEST_F(SdoServersTest, AStoppedNodeServesNoAdditionalServer) {
  configure();
  EXPECT_TRANSCRIPT(R"(
    rx 681 [8] 40 08 10 00 00 00 00 00
    tx 6C1 [8] 41 08 10 00 0D 00 00 00
    rx 000 [2] 02 01
    rx 681 [8] 60 00 00 00 00 00 00 00
    silence
  )");
}

TEST_F(SdoServersTest, BlockDownloadThroughTheAdditionalServer) {
  configure();
  EXPECT_TRANSCRIPT(R"(
    rx 681 [8] C6 06 20 00 0C 00 00 00   # block download 0x2006, CRC, 12 bytes
    tx 6C1 [8] A4 06 20 00 02 00 00 00
    rx 601 [8] 40 08 10 00 00 00 00 00   # the default server meanwhile
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 681 [8] 01 48 65 6C 6C 6F 20 43   # 1: "Hello C"
    silence
    rx 681 [8] 82 6F 73 74 61 21 00 00   # 2, last: "osta!" and 2 unused bytes
    tx 6C1 [8] A2 02 01 00 00 00 00 00
    rx 681 [8] C9 75 73 00 00 00 00 00   # end: 2 unused, CRC 0x7375
    tx 6C1 [8] A1 00 00 00 00 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65
  )");
  EXPECT_TRUE(bus_.node().sdoServers().valid());
}

TEST_F(SdoServersTest, AValidServerIsInTheAcceptanceFilters) {
  auto has681 = [this] {
    CanIdFilter filters[32];
    const size_t count = bus_.node().receiveFilters(filters, 32);
    for (size_t i = 0; i < count && i < 32U; ++i) {
      if (filters[i].mask == CanIdFilter::kExact && filters[i].id == 0x681U) {
        return true;
      }
    }
    return false;
  };
  EXPECT_FALSE(has681());
  const uint32_t version = bus_.node().receiveFiltersVersion();
  configure();
  EXPECT_NE(bus_.node().receiveFiltersVersion(), version);
  EXPECT_TRUE(has681());
}

}  // namespace
}  // namespace costa::test
