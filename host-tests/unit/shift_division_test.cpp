// divide(): quotient and remainder by shift and subtract, against the C++ operators at the edges
// of the 32-bit range and for the divisors the stack uses (1000, slot alignments).
#include "costa/shift_division.hpp"

#include <gtest/gtest.h>
#include <stdint.h>

namespace costa {
namespace {

static_assert(divide(UINT32_MAX, 1000U).quotient == 4294967U);
static_assert(divide(UINT32_MAX, 1000U).remainder == 295U);

void expectDivides(uint32_t value, uint32_t divisor) {
  const Quotient result = divide(value, divisor);
  EXPECT_EQ(result.quotient, value / divisor) << value << " / " << divisor;
  EXPECT_EQ(result.remainder, value % divisor) << value << " % " << divisor;
}

TEST(ShiftDivision, MatchesTheOperatorsAtTheEdgesOfTheRange) {
  const uint32_t values[] = {0U,          1U,          2U,          3U,          999U,
                             1000U,       1001U,       0x7FFFFFFFU, 0x80000000U, 0x80000001U,
                             0xFFFFFFFEU, 0xFFFFFFFFU, 4294967000U, 4294966999U};
  const uint32_t divisors[] = {1U,          2U,          3U,          7U,
                               64U,         1000U,       4096U,       0x7FFFFFFFU,
                               0x80000000U, 0x80000001U, 0xFFFFFFFEU, 0xFFFFFFFFU};
  for (const uint32_t value : values) {
    for (const uint32_t divisor : divisors) {
      expectDivides(value, divisor);
    }
  }
}

TEST(ShiftDivision, MatchesTheOperatorsAcrossTheRange) {
  uint32_t value = 12345U;
  for (int i = 0; i < 20000; ++i) {
    value = value * 1664525U + 1013904223U;  // a linear congruential sequence
    expectDivides(value, 1000U);
    expectDivides(value, (value >> (value & 31U)) | 1U);
    expectDivides(value >> (i & 31), (value & 0xFFFFU) + 1U);
  }
}

}  // namespace
}  // namespace costa
