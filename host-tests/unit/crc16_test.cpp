// CRC-16 of SDO block transfers (CiA 301: x^16 + x^12 + x^5 + 1, initial value 0).
#include "costa/crc16.hpp"

#include <gtest/gtest.h>

namespace costa {
namespace {

constexpr uint8_t kCheck[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
static_assert(crc16(kCheck, sizeof(kCheck)) == 0x31C3, "the CRC-16/XMODEM check value");

TEST(Crc16, CheckValue) {
  EXPECT_EQ(crc16(kCheck, sizeof(kCheck)), 0x31C3);
}

TEST(Crc16, NothingGivesZero) {
  EXPECT_EQ(crc16(kCheck, 0), 0x0000);
  EXPECT_EQ(Crc16().value(), 0x0000);
}

TEST(Crc16, IncrementalInAnyPiecesEqualsWhole) {
  for (size_t split = 0; split <= sizeof(kCheck); ++split) {
    Crc16 crc;
    crc.update(kCheck, split);
    crc.update(kCheck + split, sizeof(kCheck) - split);
    EXPECT_EQ(crc.value(), 0x31C3) << "split at " << split;
  }
  Crc16 bytewise;
  for (const uint8_t byte : kCheck) {
    bytewise.update(byte);
  }
  EXPECT_EQ(bytewise.value(), 0x31C3);
  bytewise.reset();
  EXPECT_EQ(bytewise.value(), 0x0000);
}

TEST(Crc16, KnownValues) {
  const uint8_t single[] = {0x01};
  EXPECT_EQ(crc16(single, 1), 0x1021);  // one bit in: the polynomial
  const uint8_t label[] = {'H', 'e', 'l', 'l', 'o', ' ', 'C', 'o', 's', 't', 'a', '!'};
  EXPECT_EQ(crc16(label, sizeof(label)), 0x7375);
}

// The worked example of an SRDO signature (0x13FF, CiA 304) in SICK's scanGrid2 CANopen
// operating instructions (8025990/2021-03-03, 4.5.3 "Checksum calculation"): an RSRDO with
// direction 2, SCT 0x0032, SRVT 0x14, COB-IDs 0x111 / 0x112 and the mapping 0x60100108,
// 0x60110108, 0x60100208, 0x60110208, each value little-endian, each entry after its sub-index;
// the document gives the checksum 0x4370.
TEST(Crc16, PublishedSrdoSignature) {
  const uint8_t configuration[] = {0x02, 0x32, 0x00, 0x14, 0x11, 0x01, 0x00, 0x00, 0x12,
                                   0x01, 0x00, 0x00, 0x04, 0x01, 0x08, 0x01, 0x10, 0x60,
                                   0x02, 0x08, 0x01, 0x11, 0x60, 0x03, 0x08, 0x02, 0x10,
                                   0x60, 0x04, 0x08, 0x02, 0x11, 0x60};
  EXPECT_EQ(crc16(configuration, sizeof(configuration)), 0x4370);
}

}  // namespace
}  // namespace costa
