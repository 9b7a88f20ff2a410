// Every SDO abort code the server sends, each provoked by the offending frame, and the frames
// the server must ignore.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using SdoAbort = ExampleNodeTest;

TEST_F(SdoAbort, ToggleBitNotAlternated_05030000) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 70 00 00 00 00 00 00 00   # first segment must have toggle 0
    tx 581 [8] 80 08 10 00 00 00 03 05
  )");
}

TEST_F(SdoAbort, ToggleBitNotAlternatedInADownload_05030000) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 06 20 00 0E 00 00 00
    tx 581 [8] 60 06 20 00 00 00 00 00
    rx 601 [8] 00 61 62 63 64 65 66 67
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 00 61 62 63 64 65 66 67   # toggle repeated
    tx 581 [8] 80 06 20 00 00 00 03 05
  )");
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 06 20 00 00 00 00 00   # label unchanged
    tx 581 [8] 41 06 20 00 07 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 01 75 6E 6E 61 6D 65 64
  )");
}

TEST_F(SdoAbort, Timeout_05040000) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    wait 999
    silence
    wait 1
    tx 581 [8] 80 08 10 00 00 00 04 05
    rx 601 [8] 60 00 00 00 00 00 00 00   # the transfer is gone
    tx 581 [8] 80 00 00 00 01 00 04 05
  )");
}

TEST_F(SdoAbort, TimeoutOfADownload_05040000) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 06 20 00 0E 00 00 00
    tx 581 [8] 60 06 20 00 00 00 00 00
    wait 1000
    tx 581 [8] 80 06 20 00 00 00 04 05
  )");
}

TEST_F(SdoAbort, CommandSpecifier_05040001) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] E0 00 20 00 00 00 00 00   # ccs 7 does not exist
    tx 581 [8] 80 00 20 00 01 00 04 05
    rx 601 [8] 60 00 00 00 00 00 00 00   # upload segment without a transfer
    tx 581 [8] 80 00 00 00 01 00 04 05
    rx 601 [8] 00 01 02 03 04 05 06 07   # download segment without a transfer
    tx 581 [8] 80 00 00 00 01 00 04 05
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 00 01 02 03 04 05 06 07   # download segment inside an upload
    tx 581 [8] 80 08 10 00 01 00 04 05
  )");
}

TEST_F(SdoAbort, ReadOfWriteOnly_06010001) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 02 20 00 00 00 00 00
    tx 581 [8] 80 02 20 00 01 00 01 06
  )");
}

TEST_F(SdoAbort, WriteOfReadOnlyAndConst_06010002) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 01 20 00 05 00 00 00   # ro
    tx 581 [8] 80 01 20 00 02 00 01 06
    rx 601 [8] 23 00 10 00 05 00 00 00   # const
    tx 581 [8] 80 00 10 00 02 00 01 06
    rx 601 [8] 21 08 10 00 0D 00 00 00   # const string, segmented
    tx 581 [8] 80 08 10 00 02 00 01 06
  )");
  EXPECT_EQ(value(0x2001, 0), 0U);
}

TEST_F(SdoAbort, ObjectDoesNotExist_06020000) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 00 30 00 00 00 00 00
    tx 581 [8] 80 00 30 00 00 00 02 06
    rx 601 [8] 23 FF 5F 00 01 00 00 00
    tx 581 [8] 80 FF 5F 00 00 00 02 06
  )");
}

TEST_F(SdoAbort, SubIndexDoesNotExist_06090011) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 18 10 07 00 00 00 00
    tx 581 [8] 80 18 10 07 11 00 09 06
    rx 601 [8] 40 17 10 01 00 00 00 00   # a VAR has only sub-index 0
    tx 581 [8] 80 17 10 01 11 00 09 06
    rx 601 [8] 2B 05 20 05 01 00 00 00
    tx 581 [8] 80 05 20 05 11 00 09 06
  )");
}

TEST_F(SdoAbort, LengthDoesNotMatch_06070010) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 06 20 00 0A 00 00 00   # announces 10 bytes ...
    tx 581 [8] 60 06 20 00 00 00 00 00
    rx 601 [8] 00 61 62 63 64 65 66 67
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 1D 68 00 00 00 00 00 00   # ... delivers 8
    tx 581 [8] 80 06 20 00 10 00 07 06
    rx 601 [8] 21 06 20 00 0A 00 00 00   # announces 10 bytes ...
    tx 581 [8] 60 06 20 00 00 00 00 00
    rx 601 [8] 00 61 62 63 64 65 66 67
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 10 68 69 6A 6B 6C 6D 6E   # ... delivers 14
    tx 581 [8] 80 06 20 00 10 00 07 06
  )");
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 06 20 00 00 00 00 00
    tx 581 [8] 41 06 20 00 07 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 01 75 6E 6E 61 6D 65 64
  )");
}

TEST_F(SdoAbort, LengthTooHigh_06070012) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 10 20 00 01 00 00 00   # 2 bytes to an UNSIGNED8
    tx 581 [8] 80 10 20 00 12 00 07 06
    rx 601 [8] 21 00 20 00 05 00 00 00   # 5 bytes announced for an UNSIGNED32
    tx 581 [8] 80 00 20 00 12 00 07 06
    rx 601 [8] 21 06 20 00 21 00 00 00   # 33 bytes for a 32-byte string
    tx 581 [8] 80 06 20 00 12 00 07 06
  )");
  EXPECT_EQ(value(0x2010, 0), 0U);
}

TEST_F(SdoAbort, LengthTooHighWithoutSizeIndication_06070012) {
  std::string text = R"(
    rx 601 [8] 20 06 20 00 00 00 00 00
    tx 581 [8] 60 06 20 00 00 00 00 00
  )";
  // 5 segments of 7 bytes = 35 bytes, more than the 32-byte capacity.
  for (int i = 0; i < 4; ++i) {
    text += i % 2 == 0 ? "rx 601 [8] 00 61 61 61 61 61 61 61\ntx 581 [8] 20 00 00 00 00 00 00 00\n"
                       : "rx 601 [8] 10 61 61 61 61 61 61 61\ntx 581 [8] 30 00 00 00 00 00 00 00\n";
  }
  text += "rx 601 [8] 01 61 61 61 61 61 61 61\ntx 581 [8] 80 06 20 00 12 00 07 06\n";
  EXPECT_EQ(play(text), "");
}

TEST_F(SdoAbort, LengthTooLow_06070013) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 20 00 64 00 00 00   # 1 byte to an UNSIGNED32
    tx 581 [8] 80 00 20 00 13 00 07 06
    rx 601 [8] 21 04 20 06 04 00 00 00   # 4 bytes announced for an UNSIGNED64
    tx 581 [8] 80 04 20 06 13 00 07 06
  )");
  EXPECT_EQ(value(0x2000, 0), 1000U);
}

TEST_F(SdoAbort, InvalidValue_06090030) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 04 20 01 02 00 00 00   # BOOLEAN takes 0 or 1
    tx 581 [8] 80 04 20 01 30 00 09 06
  )");
  EXPECT_EQ(value(0x2004, 1), 0U);
}

TEST_F(SdoAbort, ValueTooHigh_06090031) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 20 00 A1 86 01 00   # 100001 > 100000
    tx 581 [8] 80 00 20 00 31 00 09 06
    rx 601 [8] 2F 04 20 02 65 00 00 00   # INTEGER8 101 > 100
    tx 581 [8] 80 04 20 02 31 00 09 06
    rx 601 [8] 23 04 20 04 00 00 30 41   # REAL32 11.0 > 10.0
    tx 581 [8] 80 04 20 04 31 00 09 06
    rx 601 [8] 2F 02 20 00 04 00 00 00   # command 4 > 3
    tx 581 [8] 80 02 20 00 31 00 09 06
  )");
  EXPECT_EQ(value(0x2000, 0), 1000U);
}

TEST_F(SdoAbort, ValueTooLow_06090032) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 20 00 09 00 00 00   # 9 < 10
    tx 581 [8] 80 00 20 00 32 00 09 06
    rx 601 [8] 2F 04 20 02 9B 00 00 00   # INTEGER8 -101 < -100
    tx 581 [8] 80 04 20 02 32 00 09 06
    rx 601 [8] 23 04 20 03 7F 7B E1 FF   # INTEGER32 -2000001 < -2000000
    tx 581 [8] 80 04 20 03 32 00 09 06
    rx 601 [8] 23 04 20 04 00 00 80 BF   # REAL32 -1.0 < 0.0
    tx 581 [8] 80 04 20 04 32 00 09 06
  )");
}

TEST_F(SdoAbort, GeneralError_08000000) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 02 20 00 03 00 00 00   # self-test: no sensor fitted
    tx 581 [8] 80 02 20 00 00 00 00 08
  )");
}

TEST_F(SdoAbort, DeviceState_08000022) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01                     # operational
    rx 601 [8] 2F 10 20 00 01 00 00 00   # mode changes only in pre-operational
    tx 581 [8] 80 10 20 00 22 00 00 08
    rx 000 [2] 80 01
    rx 601 [8] 2F 10 20 00 01 00 00 00
    tx 581 [8] 60 10 20 00 00 00 00 00
  )");
}

TEST_F(SdoAbort, IgnoresMalformedAndForeignFrames) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [7] 40 08 10 00 00 00 00      # DLC 7
    rx 601 [0]
    rx 601 [8] RTR                       # remote frame on the SDO id
    rx 602 [8] 40 08 10 00 00 00 00 00   # another node's SDO
    rx 581 [8] 40 08 10 00 00 00 00 00   # a response id
    silence
  )");
  CanFrame extended;
  extended.id = 0x601;
  extended.extended = true;
  extended.dlc = 8;
  extended.data[0] = 0x40;
  extended.data[1] = 0x08;
  extended.data[2] = 0x10;
  bus_.send(extended);
  CanFrame tooLong = extended;
  tooLong.extended = false;
  tooLong.dlc = 9;
  bus_.send(tooLong);
  EXPECT_EQ(bus_.unread(), 0U);
  EXPECT_EQ(bus_.node().statistics().framesIgnored, 7U);
}

TEST_F(SdoAbort, NoSdoInStoppedState) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 02 00
    rx 601 [8] 40 08 10 00 00 00 00 00
    silence
    rx 000 [2] 80 00
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 E8 03 00 00
  )");
}

TEST_F(SdoAbort, StoppingAbandonsATransferInProgress) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 000 [2] 02 01
    rx 000 [2] 80 01
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 80 00 00 00 01 00 04 05
    wait 2000
    silence
  )");
}

}  // namespace
}  // namespace costa::test
