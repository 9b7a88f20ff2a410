// The sensor's CAN driver, a stub in the shape of a real one: its controller is a block of RAM
// (a debugger or an emulator plays the bus), so it runs anywhere and touches no hardware.
#pragma once

#include <stdint.h>

#include "costa/port/can_bit_rate.hpp"
#include "costa/port/can_port.hpp"

namespace sensor {

/// The controller's registers: one receive and one transmit mailbox.
struct StubController {
  volatile uint32_t rxFull = 0;  ///< Set by the bus when `rx` holds a frame; cleared on reading.
  costa::CanFrame rx;
  volatile uint32_t txFull = 0;  ///< Set here when `tx` holds a frame; cleared once sent.
  costa::CanFrame tx;
  volatile uint32_t bitRate = 0;  ///< Bit/s; 0: the controller is off.
};

/// Costa's two CAN port interfaces: it transmits the node's frames and re-times the controller
/// (LSS, a stored bit timing). Reception is polled by the main loop: receive().
class StubCan final : public costa::CanTransmitter, public costa::CanBitRateControl {
 public:
  explicit StubCan(StubController& controller) noexcept : controller_(controller) {}

  /// Switches the controller on at `bitsPerSecond`.
  bool start(uint32_t bitsPerSecond) noexcept { return setBitRate(bitsPerSecond); }

  /// Takes the transmit mailbox when it is free; false (the node retries) when it is not.
  bool tryTransmit(const costa::CanFrame& frame) noexcept override;
  /// Accepts the rates of the CiA 305 table (10 kbit/s to 1 Mbit/s).
  bool setBitRate(uint32_t bitsPerSecond) noexcept override;
  /// The frame in the receive mailbox, if there is one.
  bool receive(costa::CanFrame* frame) noexcept;

 private:
  StubController& controller_;
};

}  // namespace sensor
