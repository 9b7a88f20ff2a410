// The byte-order helpers every value passes through: little-endian loads and stores of 1 to 8
// bytes, native loads and stores, sign extension from each width, and the node-id added to a
// number.
#include <gtest/gtest.h>

#include <cstring>

#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

TEST(LittleEndian, StoresAndLoadsEachWidthLeastSignificantByteFirst) {
  for (size_t length = 1; length <= 8; ++length) {
    uint8_t bytes[8] = {};
    storeLittleEndian(bytes, 0x8877665544332211ULL, length);
    for (size_t i = 0; i < 8; ++i) {
      EXPECT_EQ(bytes[i], i < length ? 0x11U * (i + 1U) : 0U) << length << " " << i;
    }
    const uint64_t expected =
        length == 8 ? 0x8877665544332211ULL : 0x8877665544332211ULL & ((1ULL << (8 * length)) - 1U);
    EXPECT_EQ(loadLittleEndianBytes(bytes, length), expected) << length;
    EXPECT_EQ(loadLittleEndian(bytes, length), expected) << length;
  }
}

TEST(LittleEndian, NativeLoadsAndStoresTakeOneTwoFourOrEightBytes) {
  alignas(8) uint8_t block[8] = {};
  for (const size_t size : {size_t{1}, size_t{2}, size_t{4}, size_t{8}}) {
    std::memset(block, 0xEE, sizeof(block));
    storeNative(block, 0x0102030405060708ULL, size);
    const uint64_t expected =
        size == 8 ? 0x0102030405060708ULL : 0x0102030405060708ULL & ((1ULL << (8 * size)) - 1U);
    EXPECT_EQ(loadNative(block, size), expected) << size;
    if (size < 8U) {
      EXPECT_EQ(block[size], 0xEEU) << size;  // nothing past the value
    }
  }
  std::memset(block, 0xEE, sizeof(block));
  storeNative(block, 0, 3);  // no native integer of 3 bytes: nothing stored, 0 loaded
  EXPECT_EQ(block[0], 0xEEU);
  EXPECT_EQ(loadNative(block, 3), 0U);
}

TEST(LittleEndian, SignExtendsFromEveryWidth) {
  EXPECT_EQ(signExtend(0xFFFFFFFFFFFFFFFFULL, 0), 0);
  for (size_t length = 1; length < 8; ++length) {
    const unsigned bits = 8U * static_cast<unsigned>(length);
    const uint64_t top = 1ULL << (bits - 1U);  // the sign bit
    // Bits above the width are ignored, whatever they are.
    const uint64_t garbage = ~((1ULL << bits) - 1U);
    EXPECT_EQ(signExtend(top - 1U, length), static_cast<int64_t>(top - 1U)) << length;
    EXPECT_EQ(signExtend((top - 1U) | garbage, length), static_cast<int64_t>(top - 1U)) << length;
    EXPECT_EQ(signExtend(top, length), -static_cast<int64_t>(top)) << length;
    EXPECT_EQ(signExtend(top | garbage, length), -static_cast<int64_t>(top)) << length;
    EXPECT_EQ(signExtend((1ULL << bits) - 1U, length), -1) << length;
    EXPECT_EQ(signExtend(0, length), 0) << length;
    EXPECT_EQ(signExtend(garbage, length), 0) << length;
  }
  EXPECT_EQ(signExtend(0x8000000000000000ULL, 8), INT64_MIN);
  EXPECT_EQ(signExtend(0x7FFFFFFFFFFFFFFFULL, 8), INT64_MAX);
  EXPECT_EQ(signExtend(0xFFFFFFFFFFFFFFFEULL, 9), -2);
}

TEST(LittleEndian, AddsANodeIdWithCarryWithinTheNumbersWidth) {
  for (size_t length = 1; length <= 8; ++length) {
    // Each byte 0xFF but the top one, 0x12: adding 1 carries through every byte below the top.
    uint8_t bytes[9];
    std::memset(bytes, 0xFF, sizeof(bytes));
    bytes[length - 1U] = 0x12;
    addLittleEndian(bytes, length, 1);
    for (size_t i = 0; i + 1U < length; ++i) {
      EXPECT_EQ(bytes[i], 0x00U) << length << " " << i;
    }
    EXPECT_EQ(bytes[length - 1U], 0x13U) << length;
    EXPECT_EQ(bytes[length], 0xFFU) << length;  // nothing past the number
    // All ones: the carry out of the top byte is dropped (the number's own width).
    std::memset(bytes, 0xFF, sizeof(bytes));
    addLittleEndian(bytes, length, 0x7F);
    EXPECT_EQ(bytes[0], 0x7EU) << length;
    for (size_t i = 1; i < length; ++i) {
      EXPECT_EQ(bytes[i], 0x00U) << length << " " << i;
    }
    EXPECT_EQ(bytes[length], 0xFFU) << length;
  }
  uint8_t cobId[4] = {0x80, 0x05, 0x00, 0x00};  // 0x580 + node-id 0x7F
  addLittleEndian(cobId, sizeof(cobId), 0x7F);
  EXPECT_EQ(loadLittleEndianBytes(cobId, sizeof(cobId)), 0x5FFU);
  addLittleEndian(cobId, sizeof(cobId), 0x01);
  EXPECT_EQ(loadLittleEndianBytes(cobId, sizeof(cobId)), 0x600U);
  addLittleEndian(cobId, sizeof(cobId), 0);
  EXPECT_EQ(loadLittleEndianBytes(cobId, sizeof(cobId)), 0x600U);
}

}  // namespace
}  // namespace costa
