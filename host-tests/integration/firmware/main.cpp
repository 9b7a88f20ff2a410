// The level sensor's firmware: a CANopen slave (Costa) with the dictionary of sensor.eds, on the
// project's own CAN driver and clock, in a bare loop.
#include "costa/features.hpp"
#include "costa/node.hpp"
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
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables,cppcoreguidelines-interfaces-global-init)

/// The level input (a stand-in for the ADC): a slow ramp.
int16_t readLevel(costa::Microseconds now) noexcept {
  return static_cast<int16_t>((now / 100000U) % 1000U);
}

}  // namespace

int main() {
  sensor::TickClock clock;
  clock.start(kCoreClockHz);
  if (!can.start(costa::bitRateOf(settings().bitTiming))) {
    for (;;) {
    }
  }
  node.start(static_cast<costa::Microseconds>(clock.nowMicroseconds()));
  for (;;) {
    const auto now = static_cast<costa::Microseconds>(clock.nowMicroseconds());
    costa::CanFrame frame;
    while (can.receive(&frame)) {
      node.onFrame(frame, now);
    }
    const int16_t level = readLevel(now);
    if (level != node.values().x2000_level) {
      node.values().x2000_level = level;
      node.markChanged(0x2000, 0);  // the event-driven TPDO 1 sends it (inhibit time 10 ms)
    }
    node.process(now);
  }
}
