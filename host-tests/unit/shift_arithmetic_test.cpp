// shiftDivide() and shiftMultiply(), the forms of divide() and multiply() on cores without a
// divide instruction or a long multiplication, against the C++ operators at the edges of the
// range and for the divisors and factors the stack uses (1000, slot alignments, 0x100C x 0x100D);
// divide() and multiply() themselves, whichever form this build chose.
#include "costa/shift_arithmetic.hpp"

#include <gtest/gtest.h>
#include <stdint.h>

namespace costa {
namespace {

static_assert(shiftDivide(UINT32_MAX, 1000U).quotient == 4294967U);
static_assert(shiftDivide(UINT32_MAX, 1000U).remainder == 295U);
static_assert(shiftMultiply(uint64_t{65535U} * 1000U, 255U) == 16711425000U);
static_assert(shiftMultiply(UINT64_MAX, 2U) == UINT64_MAX - 1U);  // modulo 2^64

void expectDivides(uint32_t value, uint32_t divisor) {
  for (const Quotient result : {shiftDivide(value, divisor), divide(value, divisor)}) {
    EXPECT_EQ(result.quotient, value / divisor) << value << " / " << divisor;
    EXPECT_EQ(result.remainder, value % divisor) << value << " % " << divisor;
  }
}

void expectMultiplies(uint64_t value, uint32_t factor) {
  EXPECT_EQ(shiftMultiply(value, factor), value * factor) << value << " x " << factor;
  EXPECT_EQ(multiply(value, factor), value * factor) << value << " x " << factor;
}

TEST(ShiftArithmetic, DivisionMatchesTheOperatorsAtTheEdgesOfTheRange) {
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

TEST(ShiftArithmetic, DivisionMatchesTheOperatorsAcrossTheRange) {
  uint32_t value = 12345U;
  for (int i = 0; i < 20000; ++i) {
    value = value * 1664525U + 1013904223U;  // a linear congruential sequence
    expectDivides(value, 1000U);
    expectDivides(value, (value >> (value & 31U)) | 1U);
    expectDivides(value >> (i & 31), (value & 0xFFFFU) + 1U);
  }
}

TEST(ShiftArithmetic, MultiplicationMatchesTheOperatorModulo2To64) {
  const uint64_t values[] = {0U, 1U, 1000U, 65535000U, 0xFFFFFFFFU, 0x100000000U, UINT64_MAX};
  const uint32_t factors[] = {0U, 1U, 2U, 255U, 1000U, 0x80000000U, 0xFFFFFFFFU};
  for (const uint64_t value : values) {
    for (const uint32_t factor : factors) {
      expectMultiplies(value, factor);
    }
  }
  uint64_t value = 987654321U;
  for (int i = 0; i < 5000; ++i) {
    value = value * 6364136223846793005U + 1442695040888963407U;
    expectMultiplies(value, static_cast<uint32_t>(value >> 17U));
  }
}

}  // namespace
}  // namespace costa
