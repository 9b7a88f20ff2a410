// The sensor's CAN driver, a stub in the shape of a real one: its controller is a block of RAM
// (a debugger or an emulator plays the bus), so it runs anywhere and touches no hardware.
#pragma once

#include <stdint.h>

#include <stddef.h>

#include "costa/port/can_bit_rate.hpp"
#include "costa/port/can_id_filter.hpp"
#include "costa/port/can_port.hpp"

namespace sensor {

/// The controller's registers: one receive and one transmit mailbox, eight acceptance filters.
struct StubController {
  static constexpr size_t kFilters = 8;
  static constexpr uint32_t kAcceptAll = 0xFF;

  /// A frame reaches `rx` (and raises the receive interrupt) when its identifier agrees with
  /// filterId[i] in the bits of filterMask[i] for some i < filterCount; kAcceptAll: any frame.
  volatile uint32_t filterCount = kAcceptAll;
  uint16_t filterId[kFilters] = {};
  uint16_t filterMask[kFilters] = {};
  volatile uint32_t rxFull = 0;  ///< Set by the bus when `rx` holds a frame; cleared on reading.
  costa::CanFrame rx;
  volatile uint32_t txFull = 0;  ///< Set here when `tx` holds a frame; cleared once sent.
  costa::CanFrame tx;
  volatile uint32_t bitRate = 0;  ///< Bit/s; 0: the controller is off.
};

/// Costa's two CAN port interfaces: it transmits the node's frames and re-times the controller
/// (LSS, a stored bit timing). Reception: the receive interrupt calls receive() and hands the
/// frames to the main loop through a costa::port::CanFrameRing (main.cpp).
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
  /// Programs the node's acceptance filters (costa::Node::receiveFilters()). More than the
  /// controller holds: it accepts every frame, and the answer is false.
  bool setFilters(const costa::CanIdFilter* filters, size_t count) noexcept;

 private:
  StubController& controller_;
};

}  // namespace sensor
