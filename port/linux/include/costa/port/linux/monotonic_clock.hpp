// CLOCK_MONOTONIC as a costa::MonotonicClock.
#pragma once

#include "costa/port/clock.hpp"

namespace costa::port {

class LinuxMonotonicClock final : public MonotonicClock {
 public:
  uint64_t nowMicroseconds() noexcept override;
};

}  // namespace costa::port
