// The level sensor's firmware: a CANopen slave (Costa) with the dictionary of sensor.eds, on the
// project's own CAN driver and clock, in a bare loop, as docs/porting.md describes: frames from
// the receive interrupt through a lock-free ring, the controller's acceptance filters from the
// node, and the loop asleep until an interrupt.
#include "costa/features.hpp"
#include "costa/node.hpp"
#include "costa/port/can_frame_ring.hpp"
#include "sensor_od.hpp"
#include "stub_can.hpp"
#include "tick_clock.hpp"

namespace {

// CMakeLists.txt compiles Costa without the services the sensor does not need.
static_assert(!costa::features::kSdoBlockTransfer && !costa::features::kLss &&
                  !costa::features::kNodeGuarding,
              "the sensor's stack is built without SDO block transfer, LSS and node guarding");

constexpr uint32_t kCoreClockHz = 72000000U;
constexpr uint8_t kNodeId = 0x10;

using SensorNode = costa::NodeInstance<costa::gen::sensor::Values, costa::gen::sensor::Capacity>;

costa::NodeSettings settings() noexcept {
  costa::NodeSettings s;
  s.nodeId = kNodeId;
  return s;
}

// In static storage: the node's buffers are sized at compile time from the dictionary, and
// there is no heap. (kDefinition is constant-initialized: no order problem.)
// NOLINTBEGIN(cppcoreguidelines-avoid-non-const-global-variables,cppcoreguidelines-interfaces-global-init)
sensor::StubController controller{};
sensor::StubCan can(controller);
SensorNode node(costa::gen::sensor::kDefinition, can, settings());
/// Received frames, from the receive interrupt (producer) to the main loop (consumer).
costa::port::CanFrameRing<16> received;
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables,cppcoreguidelines-interfaces-global-init)

/// The level input (a stand-in for the ADC): a slow ramp.
int16_t readLevel(costa::Microseconds now) noexcept {
  return static_cast<int16_t>((now / 100000U) % 1000U);
}

/// Programs the controller's filters with what the node listens to, whenever that changed
/// (start-up, reset communication, a COB-ID written by SDO).
class AcceptanceFilters {
 public:
  void update() noexcept {
    if (programmed_ && node.receiveFiltersVersion() == version_) {
      return;
    }
    version_ = node.receiveFiltersVersion();
    programmed_ = true;
    costa::CanIdFilter filters[sensor::StubController::kFilters];
    // More than fit: the controller accepts every frame (correct, only less selective).
    const size_t count = node.receiveFilters(filters, sensor::StubController::kFilters);
    (void)can.setFilters(filters, count);
  }

 private:
  uint32_t version_ = 0;
  bool programmed_ = false;
};

void waitForInterrupt() noexcept {
  __asm volatile("wfi");  // the receive interrupt or the next millisecond tick
}

}  // namespace

// The receive interrupt: only the ring's producer side (docs/porting.md, "Contexts").
// NOLINTNEXTLINE(readability-identifier-naming): the part's name for the vector
extern "C" void CAN_RX_IRQHandler() {
  costa::CanFrame frame;
  while (can.receive(&frame)) {
    (void)received.push(frame);  // full: dropped and counted, reported by the main loop
  }
}

int main() {
  sensor::TickClock clock;
  clock.start(kCoreClockHz);
  if (!can.start(costa::bitRateOf(settings().bitTiming))) {
    for (;;) {
    }
  }
  AcceptanceFilters filters;
  node.start(static_cast<costa::Microseconds>(clock.nowMicroseconds()));
  filters.update();
  for (;;) {
    const auto now = static_cast<costa::Microseconds>(clock.nowMicroseconds());
    if (received.takeOverrun()) {
      node.onControllerEvent(costa::CanControllerEvent::kRxOverrun, now);  // EMCY 0x8110
    }
    costa::CanFrame frame;
    while (received.pop(&frame)) {
      node.onFrame(frame, now);
    }
    const int16_t level = readLevel(now);
    if (level != node.values().x2000_level) {
      node.values().x2000_level = level;
      node.markChanged(0x2000, 0);  // the event-driven TPDO 1 sends it (inhibit time 10 ms)
    }
    // The next deadline: a part with a compare timer would arm it for (next - now); this one
    // wakes every millisecond anyway (tick_clock.cpp), which is finer than any deadline needs.
    (void)node.process(now);
    filters.update();
    waitForInterrupt();
  }
}
