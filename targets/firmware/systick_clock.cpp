#include "systick_clock.hpp"

namespace costa::firmware {
namespace {

// SysTick registers (Armv7-M / Armv6-M system control space).
constexpr uintptr_t kSysTickControl = 0xE000E010U;  // SYST_CSR
constexpr uintptr_t kSysTickReload = 0xE000E014U;   // SYST_RVR
constexpr uintptr_t kSysTickCurrent = 0xE000E018U;  // SYST_CVR
constexpr uint32_t kEnable = 1U << 0;
constexpr uint32_t kTickInterrupt = 1U << 1;
constexpr uint32_t kProcessorClock = 1U << 2;
constexpr uint32_t kMaxReload = 0x00FFFFFFU;

volatile uint32_t& reg(uintptr_t address) {
  return *reinterpret_cast<volatile uint32_t*>(address);
}

// Written by the handler only; a 32-bit aligned read is atomic on Cortex-M.
volatile uint32_t tickCount = 0;

}  // namespace

bool SysTickClock::start(uint32_t coreClockHz) noexcept {
  if (coreClockHz % 1000U != 0 || coreClockHz / 1000U == 0 ||
      coreClockHz / 1000U - 1U > kMaxReload) {
    return false;
  }
  reg(kSysTickControl) = 0;
  reg(kSysTickReload) = coreClockHz / 1000U - 1U;
  reg(kSysTickCurrent) = 0;  // any write clears the counter
  lastTicks_ = tickCount;
  milliseconds_ = 0;
  reg(kSysTickControl) = kProcessorClock | kTickInterrupt | kEnable;
  return true;
}

uint64_t SysTickClock::nowMicroseconds() noexcept {
  const uint32_t ticks = tickCount;
  milliseconds_ += ticks - lastTicks_;  // modulo 2^32: correct across a wrap
  lastTicks_ = ticks;
  return milliseconds_ * 1000U;
}

}  // namespace costa::firmware

extern "C" void costa_systick_handler() {
  costa::firmware::tickCount = costa::firmware::tickCount + 1U;
}
