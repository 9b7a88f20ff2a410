// Time as the stack sees it: a monotonic microsecond count passed in by the caller.
#pragma once

#include <stdint.h>

namespace costa {

/// Microseconds of a monotonic clock chosen by the caller.
using Microseconds = uint64_t;

/// "No deadline": returned when nothing is scheduled.
inline constexpr Microseconds kNever = UINT64_MAX;

inline constexpr Microseconds millisecondsToMicroseconds(uint64_t ms) noexcept {
  return ms * 1000U;
}

/// Unit of inhibit times (0x1015, PDO sub-index 3).
inline constexpr Microseconds kHundredMicroseconds = 100;

/// The earlier of two deadlines.
inline constexpr Microseconds earliest(Microseconds a, Microseconds b) noexcept {
  return a < b ? a : b;
}

}  // namespace costa
