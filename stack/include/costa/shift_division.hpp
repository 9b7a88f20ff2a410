// 32-bit division by shift and subtract, for cores without a divide instruction (Cortex-M0 and
// M0+): a division the compiler cannot turn into shifts or a multiplication goes through here
// instead of linking the C library's division routine.
#pragma once

#include <stdint.h>

namespace costa {

struct Quotient {
  uint32_t quotient;
  uint32_t remainder;
};

/// `value` / `divisor` and `value` % `divisor`, exact for every `value` and every `divisor`
/// but 0 (which it must not be). One step per bit of the quotient: at most 32.
constexpr Quotient divide(uint32_t value, uint32_t divisor) noexcept {
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

}  // namespace costa
