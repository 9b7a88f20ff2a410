#include "costa/port/linux/socketcan_error_frames.hpp"

#include <linux/can/error.h>

namespace costa::port {
namespace {

constexpr uint8_t kOverflow = CAN_ERR_CRTL_RX_OVERFLOW | CAN_ERR_CRTL_TX_OVERFLOW;
constexpr uint8_t kPassive = CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE;
constexpr uint8_t kBelowPassive =
    CAN_ERR_CRTL_ACTIVE | CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING;

}  // namespace

SocketCanEvents controllerEventsOf(const can_frame& frame, SocketCanErrorState* state) noexcept {
  SocketCanEvents events;
  if ((frame.can_id & CAN_ERR_FLAG) == 0U) {
    return events;
  }
  const bool controller = (frame.can_id & CAN_ERR_CRTL) != 0U;
  const uint8_t status = controller ? frame.data[1] : 0U;
  // A state report (passive, warning, active) while bus-off says the controller is back, as
  // CAN_ERR_RESTARTED does: drivers that recover in hardware report only the new state.
  const bool stateReported = (status & (kPassive | kBelowPassive)) != 0U;
  const bool restarted = (frame.can_id & CAN_ERR_RESTARTED) != 0U;
  const bool busOff = (frame.can_id & CAN_ERR_BUSOFF) != 0U;

  if ((status & kOverflow) != 0U) {
    events.add(CanControllerEvent::kRxOverrun);
  }
  if (state->busOff && (restarted || stateReported)) {
    // The node clears error passive when the bus-off ends (a restarted controller is error
    // active), so a controller still error passive is reported again below.
    state->busOff = false;
    state->errorPassive = false;
    events.add(CanControllerEvent::kBusOffRecovered);
  }
  bool errorPassive = state->errorPassive;
  if ((status & kPassive) != 0U) {
    errorPassive = true;
  } else if ((status & kBelowPassive) != 0U) {
    errorPassive = false;
  }
  if (busOff && !state->busOff) {
    errorPassive = true;
  }
  if (errorPassive != state->errorPassive) {
    events.add(errorPassive ? CanControllerEvent::kErrorPassive : CanControllerEvent::kErrorActive);
    state->errorPassive = errorPassive;
  }
  if (busOff && !state->busOff) {
    state->busOff = true;
    events.add(CanControllerEvent::kBusOff);
  }
  return events;
}

}  // namespace costa::port
