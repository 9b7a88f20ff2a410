// The joint's alarms (0x260E, lines 130-137, errata B9): each one an error condition of the node,
// so that the error register 0x1001 shows it and the heartbeat carries 04 (W6). The joint has
// no EMCY producer (W10): the conditions send nothing.
//
//   0x10 battery power down   not a fault, the motor goes on; cleared by the zero setting
//   0x12 locked rotor         a fault (status bit 3); cleared by fault reset or 0x2601 = 1
//   0x14 stall                a fault; cleared like 0x12
//   0x15 over-voltage         a fault while the supply is above 52 V; cleared like 0x12 once
//                             it is not
//   0x20 communication drop   the heartbeat of 0x1016's producer stopped: the motor stops and
//                             holds until it returns, reset communication or a new 0x1016:01
//                             (not a fault)
#pragma once

#include <stdint.h>

#include "costa/node.hpp"

namespace costa::mseries {

enum Alarm : uint8_t {
  kAlarmBattery = 0x10,
  kAlarmLockedRotor = 0x12,
  kAlarmStall = 0x14,
  kAlarmOverVoltage = 0x15,
  kAlarmCommunication = 0x20,
};

class JointAlarms {
 public:
  explicit JointAlarms(Node& node) noexcept : node_(node) {}

  /// Raises `alarm` (one of Alarm); false for another code.
  bool raise(uint8_t alarm) noexcept;
  void clear(uint8_t alarm) noexcept;
  bool active(uint8_t alarm) const noexcept { return (active_ & bitOf(alarm)) != 0U; }
  /// 0x260E: the highest active code, 0 when none.
  uint16_t code() const noexcept;
  /// A fault is present: locked rotor, stall or over-voltage.
  bool fault() const noexcept;
  /// Fault reset (control word bit 7, 0x2601 = 1, 0x260E = 0): clears the faults whose cause
  /// is gone (`overVoltage`: the supply is still too high).
  void resetFaults(bool overVoltage) noexcept;

 private:
  static uint8_t bitOf(uint8_t alarm) noexcept;

  Node& node_;
  uint8_t active_ = 0;  ///< bitOf() of every active alarm
};

}  // namespace costa::mseries
