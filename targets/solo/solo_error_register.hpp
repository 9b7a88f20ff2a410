// The SOLO device error register 0x3020 (manual lines 1151-1169), mirrored into the CANopen
// error register 0x1001 and reported by EMCY: one EMCY per error event, none when errors are
// cleared (docs/errata-solo.md S6).
//
// Bit mapping to 0x1001 (CiA 301 error register bits):
//   0 over-current      -> current (bit 1)        EMCY code 0x2310
//   1 over-voltage      -> voltage (bit 2)        0x3210
//   2 over-temperature  -> temperature (bit 3)    0x4210
//   3 encoder calibration timeout -> manufacturer (bit 7)  0xFF03
//   4 hall calibration timeout    -> manufacturer (bit 7)  0xFF04
//   5 CAN communication lost (life time expired) -> communication (bit 4)  0x8130
//   6 stall time-out    -> manufacturer (bit 7)   0xFF06
// plus bit 0 (generic) whenever any bit is set.
#pragma once

#include <stdint.h>

#include "costa/node.hpp"

namespace costa::solo {

class SoloErrorRegister {
 public:
  static constexpr uint16_t kIndex = 0x3020;
  static constexpr uint32_t kOverCurrent = 1U << 0;
  static constexpr uint32_t kCommunicationLost = 1U << 5;

  /// `value` is 0x3020's value in the node's dictionary.
  SoloErrorRegister(Node& node, uint32_t& value) noexcept : node_(node), value_(value) {}

  /// Makes 0x3020 equal to `bits`: newly set bits raise their EMCY condition (one EMCY each),
  /// cleared bits clear it; 0x1001 follows.
  void assign(uint32_t bits) noexcept;
  /// Sets more bits (devices faults).
  void set(uint32_t bits) noexcept { assign(value() | bits); }
  uint32_t value() const noexcept { return value_; }

 private:
  Node& node_;
  uint32_t& value_;
  uint32_t reported_ = 0;  ///< bits whose EMCY condition is raised
};

}  // namespace costa::solo
