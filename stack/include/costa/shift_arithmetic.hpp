// 32-bit division and 64-bit multiplication by shift and subtract or add, for cores without a
// divide instruction or a 32 x 32 -> 64 multiplication (Cortex-M0 and M0+, Thumb-1 only): there a
// division the compiler cannot turn into shifts, or a 64-bit product, would link the C library's
// routine, which takes more bytes. divide() and multiply() choose: the shift form on such a core,
// the C++ operator everywhere else (where it is an instruction or a short inline sequence).
#pragma once

#include <stdint.h>

namespace costa {

/// True on a Thumb-1 core (Cortex-M0, M0+): no divide instruction, no 32 x 32 -> 64 multiply.
#if defined(__ARM_ARCH_ISA_THUMB) && __ARM_ARCH_ISA_THUMB == 1
inline constexpr bool kShiftArithmetic = true;
#else
inline constexpr bool kShiftArithmetic = false;
#endif

struct Quotient {
  uint32_t quotient;
  uint32_t remainder;
};

/// `value` / `divisor` and `value` % `divisor`, exact for every `value` and every `divisor`
/// but 0 (which it must not be). One step per bit of the quotient: at most 32.
constexpr Quotient shiftDivide(uint32_t value, uint32_t divisor) noexcept {
  // The largest divisor x 2^k not above `value` (at least the divisor itself): doubling stops
  // before it could exceed `value`, so it never overflows, and k halvings give the divisor back.
  uint32_t shifted = divisor;
  while (shifted <= (value >> 1U)) {
    shifted <<= 1U;
  }
  uint32_t quotient = 0;
  for (;;) {
    quotient <<= 1U;
    if (value >= shifted) {
      value -= shifted;
      quotient |= 1U;
    }
    if (shifted == divisor) {
      return Quotient{quotient, value};
    }
    shifted >>= 1U;
  }
}

/// `value` x `factor` modulo 2^64 (what the `*` of uint64_t gives): one step per bit of `factor`.
constexpr uint64_t shiftMultiply(uint64_t value, uint32_t factor) noexcept {
  uint64_t product = 0;
  for (; factor != 0U; factor >>= 1U, value <<= 1U) {
    if ((factor & 1U) != 0U) {
      product += value;
    }
  }
  return product;
}

/// `value` / `divisor` and `value` % `divisor` (`divisor` not 0).
constexpr Quotient divide(uint32_t value, uint32_t divisor) noexcept {
  if constexpr (kShiftArithmetic) {
    return shiftDivide(value, divisor);
  } else {
    return Quotient{value / divisor, value % divisor};
  }
}

/// `value` x `factor` modulo 2^64.
constexpr uint64_t multiply(uint64_t value, uint32_t factor) noexcept {
  if constexpr (kShiftArithmetic) {
    return shiftMultiply(value, factor);
  } else {
    return value * factor;
  }
}

}  // namespace costa
