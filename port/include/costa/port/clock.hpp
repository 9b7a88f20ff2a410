// A monotonic clock. The stack never reads it: the loop that drives the stack does, and passes
// the time in.
#pragma once

#include <stdint.h>

namespace costa {

/// Microseconds since an arbitrary epoch; never goes backwards.
class MonotonicClock {
 public:
  MonotonicClock(const MonotonicClock&) = delete;
  MonotonicClock& operator=(const MonotonicClock&) = delete;

  /// Current time in microseconds. Cost: O(1). Safe to call from the main loop.
  /// The default is a clock that stands still at 0 (no pure virtual functions in port
  /// interfaces: firmware needs nothing from the C++ runtime library).
  virtual uint64_t nowMicroseconds() noexcept { return 0; }

 protected:
  MonotonicClock() = default;
  ~MonotonicClock() = default;
};

}  // namespace costa
