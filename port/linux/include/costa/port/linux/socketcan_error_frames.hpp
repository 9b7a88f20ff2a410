// Linux CAN error frames (linux/can/error.h) as the controller events of Node::onControllerEvent().
//
// The driver reports a change of the controller's state in an error frame: CAN_ERR_CRTL with the
// new state in data[1], CAN_ERR_BUSOFF, CAN_ERR_RESTARTED. The events follow the bxCAN driver
// (port/stm32): an overrun first, then the end of a bus-off, then a change between error active
// and error passive, then the start of a bus-off. Error warning is error active to CiA 301, so
// only the passive state counts; a bus-off implies error passive (the transmit error counter is
// above 127). A bus-off ends with CAN_ERR_RESTARTED (the kernel restarted the controller, which
// is then error active) or with any state report (a controller that recovers by itself); the
// node then clears error passive, so a controller that comes back error passive says so again.
#pragma once

#include <linux/can.h>
#include <stddef.h>

#include "costa/port/can_controller_event.hpp"

namespace costa::port {

/// The controller's error state as the error frames so far describe it.
struct SocketCanErrorState {
  bool errorPassive = false;
  bool busOff = false;
};

/// The controller events of one error frame, in the order they are to be reported.
using SocketCanEvents = CanControllerEvents<4>;

/// The events `frame` (an error frame: CAN_ERR_FLAG set) reports to a node whose controller was
/// in `*state`; updates `*state`. Classes other than CAN_ERR_CRTL, CAN_ERR_BUSOFF and
/// CAN_ERR_RESTARTED (protocol violations, missing acknowledgements, ...) report nothing, and
/// neither does a frame without CAN_ERR_FLAG.
SocketCanEvents controllerEventsOf(const can_frame& frame, SocketCanErrorState* state) noexcept;

}  // namespace costa::port
