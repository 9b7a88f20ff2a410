// The sensor's clock: SysTick interrupts every millisecond and its handler counts.
#pragma once

#include <stdint.h>

#include "costa/port/clock.hpp"

namespace sensor {

class TickClock final : public costa::MonotonicClock {
 public:
  /// Starts SysTick at one interrupt per millisecond of a `coreClockHz` processor clock.
  void start(uint32_t coreClockHz) noexcept;
  /// Milliseconds since start(), in microseconds, extended to 64 bits (call at least once
  /// every 49 days).
  uint64_t nowMicroseconds() noexcept override;

 private:
  uint32_t lastTicks_ = 0;
  uint64_t milliseconds_ = 0;
};

}  // namespace sensor

/// The SysTick exception (startup.cpp's vector table).
// NOLINTNEXTLINE(readability-identifier-naming): CMSIS name
extern "C" void SysTick_Handler();
