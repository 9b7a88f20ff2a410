#include "tick_clock.hpp"

namespace {

// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables): an interrupt's counter
volatile uint32_t ticks = 0;  // milliseconds, counted by SysTick_Handler

struct SysTickRegisters {
  volatile uint32_t ctrl;
  volatile uint32_t load;
  volatile uint32_t val;
  volatile uint32_t calib;
};

SysTickRegisters& sysTick() noexcept {
  // SysTick's registers at their fixed address.
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast,performance-no-int-to-ptr): MMIO
  return *reinterpret_cast<SysTickRegisters*>(0xE000E010U);
}

}  // namespace

// NOLINTNEXTLINE(readability-identifier-naming): CMSIS name
extern "C" void SysTick_Handler() {
  ticks = ticks + 1U;
}

namespace sensor {

void TickClock::start(uint32_t coreClockHz) noexcept {
  SysTickRegisters& registers = sysTick();
  registers.load = coreClockHz / 1000U - 1U;
  registers.val = 0U;
  registers.ctrl = 0x7U;  // processor clock, interrupt, enabled
}

uint64_t TickClock::nowMicroseconds() noexcept {
  const uint32_t now = ticks;
  milliseconds_ += now - lastTicks_;  // modulo 2^32: right across the counter's wrap
  lastTicks_ = now;
  return milliseconds_ * 1000U;
}

}  // namespace sensor
