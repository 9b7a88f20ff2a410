// SRDOs (EN 50325-5 / CiA 304) through wire frames. The example transmits SRDO 1 (0x1301:
// normal 0x101, inverted 0x102, SCT 100 ms, SRVT 20 ms; 0x2001 uptime and 0x2005:01, 6 bytes)
// and receives SRDO 2 (0x1302: 0x103 / 0x104, SCT 100 ms, SRVT 20 ms; 0x2005:02 and 0x2005:03,
// 4 bytes); 0x13FF holds both signatures, 0x13FE is 0 until the master validates it (0xA5).
// EMCY of a failure: code, error register 0x11, manufacturer bytes failure and SRDO number.
#include <vector>

#include "example_fixture.hpp"

namespace costa::test {
namespace {

class SafeStateLog : public NodeEvents {
 public:
  void onSafeState(uint8_t srdo, SrdoFailure failure) noexcept override {
    if (count < kCapacity) {
      srdos[count] = srdo;
      failures[count] = failure;
      ++count;
    }
  }
  static constexpr size_t kCapacity = 4;
  uint8_t srdos[kCapacity] = {};
  SrdoFailure failures[kCapacity] = {};
  size_t count = 0;
};

constexpr const char* kValidate = R"(
  rx 601 [8] 2F FE 13 00 A5 00 00 00   # configuration valid
  tx 581 [8] 60 FE 13 00 00 00 00 00
)";
constexpr const char* kStart = R"(
  rx 000 [2] 01 00
  tx 101 [6] 00 00 00 00 34 12         # SRDO 1 at once: uptime 0, 0x2005:01 = 0x1234
  tx 102 [6] FF FF FF FF CB ED         # and its bit-inverted copy
)";

/// SRDO 2 made not valid and its mapping disabled (count 0): its entries may change.
constexpr const char* kOpenSrdo2Mapping = R"(
  rx 601 [8] 2F 02 13 01 00 00 00 00   # SRDO 2 not valid
  tx 581 [8] 60 02 13 01 00 00 00 00
  rx 601 [8] 2F 82 13 00 00 00 00 00
  tx 581 [8] 60 82 13 00 00 00 00 00
)";

class SrdoTest : public ExampleNodeTest {
 protected:
  void SetUp() override {
    ExampleNodeTest::SetUp();
    ASSERT_TRUE(bus_.node().addListener(log_));
  }
  /// Validates the configuration and starts the node: SRDO 1 sends its first pair.
  void startSafety() {
    EXPECT_TRANSCRIPT(kValidate);
    EXPECT_TRANSCRIPT(kStart);
    EXPECT_TRUE(bus_.node().workingStateAllowed());
  }
  void expectSafeState(uint8_t srdo, SrdoFailure failure) {
    ASSERT_EQ(log_.count, 1U);
    EXPECT_EQ(log_.srdos[0], srdo);
    EXPECT_EQ(log_.failures[0], failure);
    EXPECT_FALSE(bus_.node().workingStateAllowed());
  }

  SafeStateLog log_;
};

TEST_F(SrdoTest, NotValidatedNoSrdoRunsAndTheWorkingStateIsNotAllowed) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 00
    wait 300
  )");
  EXPECT_FALSE(bus_.node().workingStateAllowed());
  EXPECT_EQ(log_.count, 0U);
}

TEST_F(SrdoTest, ATransmitSrdoSendsItsNormalThenItsInvertedFrameEverySct) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44
    rx 104 [4] EE DD CC BB
    wait 99
    rx 103 [4] 11 22 33 44
    rx 104 [4] EE DD CC BB
    wait 1
    tx 101 [6] 00 00 00 00 34 12
    tx 102 [6] FF FF FF FF CB ED
  )");
  EXPECT_TRUE(bus_.node().workingStateAllowed());
}

TEST_F(SrdoTest, AValidPairIsWrittenToTheMappedEntries) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44
    wait 5
    rx 104 [4] EE DD CC BB             # 5 ms later: within SRVT
    rx 601 [8] 40 05 20 02 00 00 00 00
    tx 581 [8] 4B 05 20 02 11 22 00 00
    rx 601 [8] 40 05 20 03 00 00 00 00
    tx 581 [8] 4B 05 20 03 33 44 00 00
  )");
  EXPECT_TRUE(bus_.node().workingStateAllowed());
  EXPECT_EQ(log_.count, 0U);
}

TEST_F(SrdoTest, FramesOutsideOperationalAreIgnored) {
  EXPECT_TRANSCRIPT(kValidate);
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44               # pre-operational: no SRDO runs
    rx 104 [4] EE DD CC BB
    wait 200                             # no SCT, no SRVT either
    silence
    rx 601 [8] 40 05 20 02 00 00 00 00
    tx 581 [8] 4B 05 20 02 34 12 00 00   # not written
  )");
  EXPECT_EQ(log_.count, 0U);
}

TEST_F(SrdoTest, AMissingInvertedFrameEntersTheSafeStateAtSrvt) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44
    wait 19
    wait 1
    tx 081 [8] 50 82 11 02 02 00 00 00  # SRVT passed: SRDO 2, failure 2
  )");
  expectSafeState(2, SrdoFailure::kValidationTime);
  EXPECT_EQ(value(0x2005, 2), 0x1234U);  // not written
  EXPECT_TRANSCRIPT("wait 200");         // SRDO 1 stopped too; one report
}

TEST_F(SrdoTest, ALateFrameEntersTheSafeStateAtSct) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44
    rx 104 [4] EE DD CC BB
    wait 99
    wait 1
    tx 101 [6] 00 00 00 00 34 12
    tx 102 [6] FF FF FF FF CB ED
    tx 081 [8] 50 82 11 01 02 00 00 00  # no new pair within SCT: failure 1
    rx 103 [4] 11 22 33 44             # too late
  )");
  expectSafeState(2, SrdoFailure::kCycleTime);
}

TEST_F(SrdoTest, AWrongInversionEntersTheSafeState) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44
    rx 104 [4] EE DD CC BC             # last byte not inverted
    tx 081 [8] 00 82 11 03 02 00 00 00
  )");
  expectSafeState(2, SrdoFailure::kNotInverted);
  EXPECT_EQ(value(0x2005, 2), 0x1234U);
}

TEST_F(SrdoTest, AnInvertedFrameWithoutItsNormalFrameEntersTheSafeState) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 104 [4] EE DD CC BB
    tx 081 [8] 00 82 11 04 02 00 00 00
  )");
  expectSafeState(2, SrdoFailure::kSequence);
}

TEST_F(SrdoTest, TwoNormalFramesInARowEnterTheSafeState) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44
    rx 103 [4] 11 22 33 44             # the inverted frame is missing
    tx 081 [8] 00 82 11 04 02 00 00 00
  )");
  expectSafeState(2, SrdoFailure::kSequence);
}

TEST_F(SrdoTest, AFrameOfTheWrongLengthEntersTheSafeState) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 103 [3] 11 22 33
    tx 081 [8] 10 82 11 05 02 00 00 00
  )");
  expectSafeState(2, SrdoFailure::kLength);
}

TEST_F(SrdoTest, AWrongSignatureEntersTheSafeStateOnEnteringOperational) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B FF 13 02 4C 31 00 00   # SRDO 2's signature off by one
    tx 581 [8] 60 FF 13 02 00 00 00 00
  )");
  EXPECT_TRANSCRIPT(kValidate);
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 00
    tx 081 [8] 00 63 11 06 02 00 00 00   # no SRDO is sent
    wait 200
  )");
  expectSafeState(2, SrdoFailure::kSignature);
}

// The signature a configuration tool computes, worked outside Costa: CRC-16/XMODEM (polynomial
// 0x1021, initial value 0, most significant bit first, no final XOR) over direction (1 byte), SCT
// (2, little-endian), SRVT (1), COB-ID 1 (4, little-endian), COB-ID 2 (4), mapping count (1),
// then per entry its sub-index (1) and value (4, little-endian). SRDO 2 with SCT 50 ms and
// COB-IDs 0x111 / 0x112 (the example mapping kept):
//   02 | 32 00 | 14 | 11 01 00 00 | 12 01 00 00 | 04 | 01 10 02 05 20 | 02 10 02 05 20
//      | 03 10 03 05 20 | 04 10 03 05 20                                     -> 0x8973
// by: c = 0; for each byte b: c ^= b << 8; 8 times: c = ((c << 1) ^ 0x1021 if c & 0x8000
// else c << 1) & 0xFFFF. The same steps give 0x4370 for the SRDO of SICK's scanGrid2 CANopen
// operating instructions (8025990/2021-03-03, 4.5.3 "Checksum calculation"), crc16_test.cpp.
// The same values big-endian would give 0xB6DA.
TEST_F(SrdoTest, ASignatureComputedByAToolFromTheParametersIsAccepted) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 02 13 02 32 00 00 00   # SCT 50 ms
    tx 581 [8] 60 02 13 02 00 00 00 00
    rx 601 [8] 23 02 13 05 11 01 00 00   # COB-ID 1 0x111
    tx 581 [8] 60 02 13 05 00 00 00 00
    rx 601 [8] 23 02 13 06 12 01 00 00   # COB-ID 2 0x112
    tx 581 [8] 60 02 13 06 00 00 00 00
    rx 601 [8] 2B FF 13 02 73 89 00 00   # signature 0x8973
    tx 581 [8] 60 FF 13 02 00 00 00 00
  )");
  EXPECT_TRANSCRIPT(kValidate);
  EXPECT_TRANSCRIPT(kStart);  // no EMCY: the signature matches
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44             # the old COB-ID: not SRDO 2's any more
    rx 111 [4] 11 22 33 44
    rx 112 [4] EE DD CC BB
    rx 601 [8] 40 05 20 02 00 00 00 00
    tx 581 [8] 4B 05 20 02 11 22 00 00
  )");
  EXPECT_TRUE(bus_.node().workingStateAllowed());
  EXPECT_EQ(log_.count, 0U);
}

TEST_F(SrdoTest, AConfigurationChangedWhileOperationalEntersTheSafeState) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 01 13 02 32 00 00 00   # SCT: refused while operational
    tx 581 [8] 80 01 13 02 22 00 00 08
    rx 103 [4] 11 22 33 44
    rx 104 [4] EE DD CC BB
  )");
  EXPECT_TRUE(bus_.node().dictionary().storeUnsigned(0x1301, 2, 50));  // behind the SDO's back
  EXPECT_TRANSCRIPT(R"(
    wait 100
    tx 081 [8] 00 63 11 07 01 00 00 00
  )");
  expectSafeState(1, SrdoFailure::kConfigurationChanged);
}

TEST_F(SrdoTest, AReceiveSrdoWhoseConfigurationChangedDeliversNothing) {
  startSafety();
  EXPECT_TRUE(bus_.node().dictionary().storeUnsigned(0x1302, 3, 25));  // SRVT, behind its back
  EXPECT_TRANSCRIPT(R"(
    rx 103 [4] 11 22 33 44
    rx 104 [4] EE DD CC BB               # a valid pair, of another configuration
    tx 081 [8] 00 63 11 07 02 00 00 00   # 0x6300, failure 7, SRDO 2
    rx 601 [8] 40 05 20 02 00 00 00 00
    tx 581 [8] 4B 05 20 02 34 12 00 00   # not written
  )");
  expectSafeState(2, SrdoFailure::kConfigurationChanged);
}

TEST_F(SrdoTest, LeavingOperationalEndsTheSafeStateAndEnteringItStartsAgain) {
  startSafety();
  EXPECT_TRANSCRIPT(R"(
    rx 104 [4] EE DD CC BB
    tx 081 [8] 00 82 11 04 02 00 00 00
    rx 000 [2] 80 00
  )");
  EXPECT_FALSE(bus_.node().workingStateAllowed());
  EXPECT_TRANSCRIPT(kStart);
  EXPECT_TRUE(bus_.node().workingStateAllowed());
}

TEST_F(SrdoTest, AGfcInOperationalEntersTheSafeState) {
  startSafety();
  EXPECT_TRANSCRIPT("rx 001 [0]");
  expectSafeState(0, SrdoFailure::kGlobalFailSafe);
  EXPECT_TRANSCRIPT("wait 200");  // no SRDO any more, no EMCY
}

TEST_F(SrdoTest, WritesFollowTheRulesAndInvalidateTheConfiguration) {
  EXPECT_TRANSCRIPT(kValidate);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 01 13 01 03 00 00 00   # direction 3
    tx 581 [8] 80 01 13 01 30 00 09 06
    rx 601 [8] 2B 01 13 02 00 00 00 00   # SCT 0
    tx 581 [8] 80 01 13 02 30 00 09 06
    rx 601 [8] 2F 01 13 03 00 00 00 00   # SRVT 0
    tx 581 [8] 80 01 13 03 30 00 09 06
    rx 601 [8] 27 01 13 02 C8 00 00 00   # SCT in 3 bytes
    tx 581 [8] 80 01 13 02 12 00 07 06
    rx 601 [8] 2F 01 13 04 FD 00 00 00   # transmission type 253
    tx 581 [8] 80 01 13 04 30 00 09 06
    rx 601 [8] 23 01 13 05 02 01 00 00   # normal data on an even COB-ID
    tx 581 [8] 80 01 13 05 30 00 09 06
    rx 601 [8] 23 01 13 06 81 01 00 00   # beyond 0x180
    tx 581 [8] 80 01 13 06 30 00 09 06
    rx 601 [8] 2F 81 13 00 00 00 00 00   # mapping of a valid SRDO
    tx 581 [8] 80 81 13 00 00 00 01 06
    rx 601 [8] 40 FE 13 00 00 00 00 00   # refused writes changed nothing
    tx 581 [8] 4F FE 13 00 A5 00 00 00
    rx 601 [8] 2B 01 13 02 C8 00 00 00   # SCT 200 ms
    tx 581 [8] 60 01 13 02 00 00 00 00
    rx 601 [8] 40 FE 13 00 00 00 00 00   # not valid any more
    tx 581 [8] 4F FE 13 00 00 00 00 00
  )");
}

TEST_F(SrdoTest, AMappingIsPairsOfANormalAndAnInvertedEntryOfTheSameSize) {
  EXPECT_TRANSCRIPT(kOpenSrdo2Mapping);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 82 13 02 20 00 00 20   # inverted: 0x2000 (32 bits), normal 0x2005:02 (16)
    tx 581 [8] 60 82 13 02 00 00 00 00
    rx 601 [8] 2F 82 13 00 02 00 00 00
    tx 581 [8] 80 82 13 00 43 00 04 06
    rx 601 [8] 2F 82 13 00 03 00 00 00   # odd count
    tx 581 [8] 80 82 13 00 42 00 04 06
    rx 601 [8] 23 82 13 02 10 04 05 20   # inverted: 0x2005:04, an entry of its own
    tx 581 [8] 60 82 13 02 00 00 00 00
    rx 601 [8] 2F 82 13 00 02 00 00 00
    tx 581 [8] 60 82 13 00 00 00 00 00
    rx 601 [8] 23 82 13 01 10 02 05 20   # entries only while the count is 0
    tx 581 [8] 80 82 13 01 22 00 00 08
  )");
}

// Each entry of a pair is checked when the count takes it in: whole bytes and not 0
// (0x06040043), an existing entry (0x06020000), its own size (0x06040043). A refused count leaves
// the mapping disabled (0).
TEST_F(SrdoTest, EveryEntryOfAMappingIsCheckedWhenTheCountTakesItIn) {
  EXPECT_TRANSCRIPT(kOpenSrdo2Mapping);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 82 13 02 10 03 05 20   # inverted: 0x2005:03, 16 bits
    tx 581 [8] 60 82 13 02 00 00 00 00
    rx 601 [8] 23 82 13 01 11 00 00 30   # normal: 0x3000:00 (none) as 17 bits: bits first
    tx 581 [8] 60 82 13 01 00 00 00 00
    rx 601 [8] 2F 82 13 00 02 00 00 00
    tx 581 [8] 80 82 13 00 43 00 04 06
    rx 601 [8] 23 82 13 01 10 00 00 30   # 0x3000:00: no such object
    tx 581 [8] 60 82 13 01 00 00 00 00
    rx 601 [8] 2F 82 13 00 02 00 00 00
    tx 581 [8] 80 82 13 00 00 00 02 06
    rx 601 [8] 23 82 13 01 20 02 05 20   # 0x2005:02 (16 bits) as 32
    tx 581 [8] 60 82 13 01 00 00 00 00
    rx 601 [8] 2F 82 13 00 02 00 00 00
    tx 581 [8] 80 82 13 00 43 00 04 06
    rx 601 [8] 23 82 13 01 20 00 00 20   # two pairs of 0x2000, 4 bytes each: 8, the most
    tx 581 [8] 60 82 13 01 00 00 00 00
    rx 601 [8] 23 82 13 02 20 00 00 20
    tx 581 [8] 60 82 13 02 00 00 00 00
    rx 601 [8] 23 82 13 03 20 00 00 20
    tx 581 [8] 60 82 13 03 00 00 00 00
    rx 601 [8] 23 82 13 04 20 00 00 20
    tx 581 [8] 60 82 13 04 00 00 00 00
    rx 601 [8] 2F 82 13 00 04 00 00 00
    tx 581 [8] 60 82 13 00 00 00 00 00
    rx 601 [8] 2F 82 13 00 00 00 00 00
    tx 581 [8] 60 82 13 00 00 00 00 00
    rx 601 [8] 23 82 13 03 00 00 00 00   # an entry 0 in a pair
    tx 581 [8] 60 82 13 03 00 00 00 00
    rx 601 [8] 2F 82 13 00 04 00 00 00
    tx 581 [8] 80 82 13 00 43 00 04 06
    rx 601 [8] 40 82 13 00 00 00 00 00
    tx 581 [8] 4F 82 13 00 00 00 00 00
  )");
}

// CiA 304 maps the inverted data as an object of its own, which the application keeps. SRDO 1
// with the inverted data of 0x2005:01 in 0x2005:04; signature (worked as above) over
//   01 | 64 00 | 14 | 01 01 00 00 | 02 01 00 00 | 04 | 01 20 00 01 20 | 02 20 00 01 20
//      | 03 10 01 05 20 | 04 10 04 05 20                                     -> 0xFE4A
TEST_F(SrdoTest, ATransmitSrdoSendsTheApplicationsInvertedEntryAsItIs) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 01 13 01 00 00 00 00   # SRDO 1 not valid
    tx 581 [8] 60 01 13 01 00 00 00 00
    rx 601 [8] 2F 81 13 00 00 00 00 00
    tx 581 [8] 60 81 13 00 00 00 00 00
    rx 601 [8] 23 81 13 04 10 04 05 20   # the inverted data of 0x2005:01 is 0x2005:04
    tx 581 [8] 60 81 13 04 00 00 00 00
    rx 601 [8] 2F 81 13 00 04 00 00 00
    tx 581 [8] 60 81 13 00 00 00 00 00
    rx 601 [8] 2F 01 13 01 01 00 00 00   # transmit
    tx 581 [8] 60 01 13 01 00 00 00 00
    rx 601 [8] 2B FF 13 01 4A FE 00 00   # signature 0xFE4A
    tx 581 [8] 60 FF 13 01 00 00 00 00
    rx 601 [8] 2B 05 20 04 78 56 00 00   # the application's copy: not the NOT of 0x1234
    tx 581 [8] 60 05 20 04 00 00 00 00
  )");
  EXPECT_TRANSCRIPT(kValidate);
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 00
    tx 101 [6] 00 00 00 00 34 12
    tx 102 [6] FF FF FF FF 78 56         # as the application keeps it: the receivers judge it
  )");
  EXPECT_EQ(log_.count, 0U);
}

// SRDO 2 with the inverted data of 0x2005:02 in 0x2005:04; signature over
//   02 | 64 00 | 14 | 03 01 00 00 | 04 01 00 00 | 02 | 01 10 02 05 20 | 02 10 04 05 20 -> 0x0AAF
TEST_F(SrdoTest, AReceiveSrdoWritesTheInvertedDataToItsOwnEntry) {
  EXPECT_TRANSCRIPT(kOpenSrdo2Mapping);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 82 13 02 10 04 05 20   # the inverted data of 0x2005:02 is 0x2005:04
    tx 581 [8] 60 82 13 02 00 00 00 00
    rx 601 [8] 2F 82 13 00 02 00 00 00   # one pair: 2 bytes
    tx 581 [8] 60 82 13 00 00 00 00 00
    rx 601 [8] 2F 02 13 01 02 00 00 00   # receive
    tx 581 [8] 60 02 13 01 00 00 00 00
    rx 601 [8] 2B FF 13 02 AF 0A 00 00   # signature 0x0AAF
    tx 581 [8] 60 FF 13 02 00 00 00 00
  )");
  EXPECT_TRANSCRIPT(kValidate);
  EXPECT_TRANSCRIPT(kStart);
  EXPECT_TRANSCRIPT(R"(
    rx 103 [2] 11 22
    rx 104 [2] EE DD
    rx 601 [8] 40 05 20 02 00 00 00 00
    tx 581 [8] 4B 05 20 02 11 22 00 00
    rx 601 [8] 40 05 20 04 00 00 00 00
    tx 581 [8] 4B 05 20 04 EE DD 00 00   # the inverted frame's bytes
  )");
  EXPECT_TRUE(bus_.node().workingStateAllowed());
  EXPECT_EQ(log_.count, 0U);
}

}  // namespace
}  // namespace costa::test
