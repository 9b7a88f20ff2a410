#include "costa/port/linux/monotonic_clock.hpp"

#include <time.h>

namespace costa::port {

uint64_t LinuxMonotonicClock::nowMicroseconds() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<uint64_t>(ts.tv_sec) * 1000000U + static_cast<uint64_t>(ts.tv_nsec) / 1000U;
}

}  // namespace costa::port
