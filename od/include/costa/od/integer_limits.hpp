// The verdict of an integer entry's limits on a candidate value, shared by the out-of-line check
// a Definition names (checkIntegerLimits(), checkLimits()) and the dictionary's inline check of
// a build for speed.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/abort_code.hpp"
#include "costa/od/data_type.hpp"
#include "costa/od/definition.hpp"
#include "costa/od/little_endian.hpp"

namespace costa::od {

/// kValueTooHigh, kValueTooLow or kNone for the raw wire bits (`size` bytes) of an integer of
/// `type`: signed types compare as int64_t, the others as uint64_t.
inline AbortCode integerLimitsVerdict(DataType type, size_t size, uint64_t raw,
                                      const Limits& limits) noexcept {
  if (isSigned(type)) {
    const int64_t value = signExtend(raw, size);
    if (value > static_cast<int64_t>(limits.high)) {
      return AbortCode::kValueTooHigh;
    }
    return value < static_cast<int64_t>(limits.low) ? AbortCode::kValueTooLow : AbortCode::kNone;
  }
  if (raw > limits.high) {
    return AbortCode::kValueTooHigh;
  }
  return raw < limits.low ? AbortCode::kValueTooLow : AbortCode::kNone;
}

}  // namespace costa::od
