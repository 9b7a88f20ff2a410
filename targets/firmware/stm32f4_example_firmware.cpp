// The example device on an STM32F4: CAN1 through the bxCAN driver, time from SysTick, the
// CiA 303-3 RUN and ERROR LEDs on two GPIOs (when the build has COSTA_FEATURE_INDICATORS).
// See port/stm32/README.md; the board assumptions are in stm32f4_board.hpp.
#include "costa/indicators.hpp"
#include "costa/port/stm32/bxcan_bit_timing.hpp"
#include "costa/port/stm32/bxcan_port.hpp"
#include "example_target.hpp"
#include "stm32f4_board.hpp"
#include "systick_clock.hpp"

namespace {

using costa::port::stm32::bxCanBitTiming;
using costa::port::stm32::BxCanBitTiming;

// The example's bit timing at power-on (CiA 305 table index 3: 250 kbit/s): CAN1 starts at it.
constexpr costa::LssBitTiming kBitTiming = costa::example::ExampleTarget::settings().bitTiming;
constexpr uint32_t kBitRate = costa::bitRateOf(kBitTiming);
constexpr BxCanBitTiming kTiming = bxCanBitTiming(costa::firmware::stm32f4::kApb1ClockHz, kBitRate);
static_assert(kTiming.valid(), "APB1 clock cannot produce the bit rate exactly");

// In static storage, not on the stack: the device (its 12 KiB scratch pad) is larger than the
// stack the linker script reserves. Neither constructor touches the hardware.
costa::port::stm32::BxCanPort can(costa::port::stm32::bxCan1());

costa::DeviceConfig config() noexcept {
  costa::DeviceConfig c;
  c.bitRateControl = &can;  // LSS activate bit timing re-times CAN1
  return c;
}

costa::example::ExampleTarget target(can, config());  // node-id 1, no storage

costa::firmware::stm32f4::BoardLeds leds;
costa::IndicatorsChoice indicators(target.node(), leds);  // after the target: it listens to it

/// Programs CAN1's filter banks with what the node listens to, when that changed (at start-up,
/// reset communication, a PDO's COB-ID written): frames for other nodes never reach the FIFO.
class AcceptanceFilters {
 public:
  void update(costa::Node& node) noexcept {
    const uint32_t version = node.receiveFiltersVersion();
    if (programmed_ && version == version_) {
      return;
    }
    const size_t count = node.receiveFilters(filters_, kCapacity);
    if (count <= kCapacity) {
      (void)can.setFilters(filters_, count);  // false: more than the banks hold, all accepted
    } else {
      can.acceptAllFrames();  // correct, only less selective
    }
    version_ = version;
    programmed_ = true;
  }

 private:
  static constexpr size_t kCapacity = 28;  // 14 banks of CAN1, two filters each
  costa::CanIdFilter filters_[kCapacity] = {};
  uint32_t version_ = 0;
  bool programmed_ = false;
};

AcceptanceFilters filters;

[[noreturn]] void halt() {
  for (;;) {
  }
}

}  // namespace

int main() {
  costa::firmware::stm32f4::connectCan1ToPb8Pb9();
  leds.connect();
  costa::firmware::SysTickClock clock;
  if (!clock.start(costa::firmware::stm32f4::kCoreClockHz)) {
    halt();
  }
  if (!can.start(kTiming.btr(), costa::firmware::stm32f4::kApb1ClockHz)) {
    halt();  // no acknowledge from the controller, or the bus never went idle
  }
  // The node takes the low 32 bits of the clock and handles their wrap (costa/time.hpp).
  target.start(static_cast<costa::Microseconds>(clock.nowMicroseconds()));
  filters.update(target.node());
  for (;;) {
    const auto now = static_cast<costa::Microseconds>(clock.nowMicroseconds());
    for (const costa::CanControllerEvent event : can.poll()) {
      target.node().onControllerEvent(event, now);
    }
    costa::CanFrame frame;
    while (can.receive(&frame)) {
      target.onFrame(frame, now);
    }
    target.process(now);            // timers, and frames that waited for a free mailbox
    (void)indicators.process(now);  // the next edge: this loop polls, it needs no wake-up
    filters.update(target.node());
  }
}
