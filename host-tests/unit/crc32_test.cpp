// CRC-32/ISO-HDLC against published check values, a bitwise reference, and split updates.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "costa/crc32.hpp"

namespace costa {
namespace {

constexpr uint8_t kCheckInput[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
static_assert(crc32(kCheckInput, sizeof(kCheckInput)) == 0xCBF43926U,
              "usable in constant expressions");

uint32_t crcOfText(const char* text) {
  return crc32(reinterpret_cast<const uint8_t*>(text), std::strlen(text));
}

/// Bit-at-a-time definition of the same CRC, as the reference.
uint32_t bitwiseCrc(const std::vector<uint8_t>& data) {
  uint32_t crc = 0xFFFFFFFFU;
  for (uint8_t byte : data) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 1U) != 0U ? (crc >> 1U) ^ 0xEDB88320U : crc >> 1U;
    }
  }
  return ~crc;
}

TEST(Crc32Test, PublishedCheckValues) {
  EXPECT_EQ(crcOfText("123456789"), 0xCBF43926U);
  EXPECT_EQ(crcOfText(""), 0x00000000U);
  EXPECT_EQ(crcOfText("a"), 0xE8B7BE43U);
  EXPECT_EQ(crcOfText("The quick brown fox jumps over the lazy dog"), 0x414FA339U);
  const uint8_t zeros[4] = {};
  EXPECT_EQ(crc32(zeros, sizeof(zeros)), 0x2144DF1CU);
}

TEST(Crc32Test, MatchesTheBitwiseDefinitionForEveryByteValue) {
  std::vector<uint8_t> data;
  for (unsigned i = 0; i < 256U; ++i) {
    data.push_back(static_cast<uint8_t>(i));
    const std::vector<uint8_t> single{static_cast<uint8_t>(i)};
    ASSERT_EQ(crc32(single.data(), 1), bitwiseCrc(single)) << "byte " << i;
  }
  EXPECT_EQ(crc32(data.data(), data.size()), bitwiseCrc(data));
}

TEST(Crc32Test, IncrementalUpdatesEqualOneUpdateAtEverySplit) {
  std::vector<uint8_t> data;
  for (unsigned i = 0; i < 100U; ++i) {
    data.push_back(static_cast<uint8_t>(i * 37U + 11U));
  }
  const uint32_t whole = crc32(data.data(), data.size());
  for (size_t split = 0; split <= data.size(); ++split) {
    Crc32 crc;
    crc.update(data.data(), split);
    crc.update(data.data() + split, data.size() - split);
    EXPECT_EQ(crc.value(), whole) << "split at " << split;
  }
  Crc32 byBytes;
  for (uint8_t byte : data) {
    byBytes.update(byte);
  }
  EXPECT_EQ(byBytes.value(), whole);
}

TEST(Crc32Test, ValueCanBeTakenMidwayAndUpdatesContinue) {
  Crc32 crc;
  crc.update(kCheckInput, 4);
  EXPECT_EQ(crc.value(), crc32(kCheckInput, 4));
  crc.update(kCheckInput + 4, 5);
  EXPECT_EQ(crc.value(), 0xCBF43926U);
}

}  // namespace
}  // namespace costa
