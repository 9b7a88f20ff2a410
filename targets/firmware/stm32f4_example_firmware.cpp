// The example device on an STM32F4: CAN1 through the bxCAN driver, time from SysTick.
// See port/stm32/README.md; the board assumptions are in stm32f4_board.hpp.
#include "costa/port/stm32/bxcan_bit_timing.hpp"
#include "costa/port/stm32/bxcan_port.hpp"
#include "example_target.hpp"
#include "stm32f4_board.hpp"
#include "systick_clock.hpp"

namespace {

using costa::port::stm32::bxCanBitTiming;
using costa::port::stm32::BxCanBitTiming;

constexpr costa::LssBitTiming kBitTiming{0, 3};  // CiA 305 table: 250 kbit/s
constexpr uint32_t kBitRate = costa::bitRateOf(kBitTiming);
constexpr BxCanBitTiming kTiming = bxCanBitTiming(costa::firmware::stm32f4::kApb1ClockHz, kBitRate);
static_assert(kTiming.valid(), "APB1 clock cannot produce the bit rate exactly");
constexpr uint8_t kNodeId = 1;

// In static storage, not on the stack: the device (its 12 KiB scratch pad) is larger than the
// stack the linker script reserves. Neither constructor touches the hardware.
costa::port::stm32::BxCanPort can(costa::port::stm32::bxCan1());

costa::NodeSettings settings() noexcept {
  costa::NodeSettings s = costa::example::ExampleTarget::settings(kNodeId, nullptr);
  s.bitTiming = kBitTiming;  // the rate can.start() sets
  s.bitRateControl = &can;   // LSS activate bit timing re-times CAN1
  return s;
}

costa::example::ExampleTarget target(can, settings());

[[noreturn]] void halt() {
  for (;;) {
  }
}

}  // namespace

int main() {
  costa::firmware::stm32f4::connectCan1ToPb8Pb9();
  costa::firmware::SysTickClock clock;
  if (!clock.start(costa::firmware::stm32f4::kCoreClockHz)) {
    halt();
  }
  if (!can.start(kTiming.btr(), costa::firmware::stm32f4::kApb1ClockHz)) {
    halt();  // no acknowledge from the controller, or the bus never went idle
  }
  target.start(clock.nowMicroseconds());
  for (;;) {
    const costa::Microseconds now = clock.nowMicroseconds();
    for (const costa::CanControllerEvent event : can.poll()) {
      target.node().onControllerEvent(event, now);
    }
    costa::CanFrame frame;
    while (can.receive(&frame)) {
      target.onFrame(frame, now);
    }
    target.process(now);  // timers, and frames that waited for a free mailbox
  }
}
