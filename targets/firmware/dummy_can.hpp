// A stand-in CAN controller for the link check: frames go to and come from memory that a
// debugger (or an emulator) can watch. It proves the core links; it drives no hardware.
#pragma once

#include <stdint.h>

#include "costa/port/can_port.hpp"

namespace costa::firmware {

struct Mailbox {
  volatile uint32_t rxCount;  ///< Incremented by the outside world when `rx` holds a frame.
  CanFrame rx;
  volatile uint32_t txCount;  ///< Incremented here for every frame written to `tx`.
  CanFrame tx;
  volatile uint32_t ticks;  ///< Milliseconds, advanced by the outside world.
};

class DummyCan final : public CanTransmitter {
 public:
  explicit DummyCan(Mailbox& mailbox) noexcept : mailbox_(mailbox) {}
  bool tryTransmit(const CanFrame& frame) noexcept override;
  bool receive(CanFrame* frame) noexcept;

 private:
  Mailbox& mailbox_;
  uint32_t seen_ = 0;
};

}  // namespace costa::firmware
