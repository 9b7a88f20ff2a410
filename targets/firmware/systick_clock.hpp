// The monotonic clock of a Cortex-M firmware image: a millisecond tick from SysTick.
#pragma once

#include <stdint.h>

#include "costa/port/clock.hpp"

namespace costa::firmware {

/// SysTick interrupts every millisecond and its handler counts; nowMicroseconds() extends the
/// count to 64 bits. SysTick is one per core, so there is one such clock per image.
class SysTickClock final : public MonotonicClock {
 public:
  SysTickClock() = default;

  /// Starts SysTick from the processor clock (`coreClockHz`), interrupting every millisecond.
  /// False, leaving SysTick off, when a millisecond is not a whole number of clocks or does not
  /// fit the 24-bit reload value.
  bool start(uint32_t coreClockHz) noexcept;

  /// Time since start() with millisecond resolution. Call at least once every 49 days (the tick
  /// count is 32 bits wide).
  uint64_t nowMicroseconds() noexcept override;

 private:
  uint32_t lastTicks_ = 0;
  uint64_t milliseconds_ = 0;
};

}  // namespace costa::firmware

/// The SysTick exception handler (replaces the weak default of startup.cpp).
extern "C" void costa_systick_handler();
