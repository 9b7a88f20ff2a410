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

}  // namespace
}  // namespace costa
