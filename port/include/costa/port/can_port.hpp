// The CAN controller as the stack sees it: a non-blocking transmit function.
#pragma once

#include "costa/port/can_frame.hpp"

namespace costa {

/// Hands frames to a CAN controller (or its driver's transmit queue).
///
/// Implemented by each port. Called only from the context that runs the stack (main loop);
/// never blocks. Reception is the other direction: the port's owner passes received frames
/// to `Node::onFrame()`.
class CanTransmitter {
 public:
  CanTransmitter(const CanTransmitter&) = delete;
  CanTransmitter& operator=(const CanTransmitter&) = delete;

  /// Queues `frame` for transmission.
  /// Returns false, without side effects, when the controller has no free transmit slot right
  /// now; the stack keeps the frame in its own bounded queue and offers it again later.
  /// Cost: O(1). Must not allocate or block.
  /// The default accepts nothing. (Port interfaces have no pure virtual functions, so that a
  /// firmware image needs nothing from the C++ runtime library.)
  virtual bool tryTransmit(const CanFrame& frame) noexcept {
    (void)frame;
    return false;
  }

 protected:
  CanTransmitter() = default;
  ~CanTransmitter() = default;
};

}  // namespace costa
