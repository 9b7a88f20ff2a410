// The simulation commands of an M-series joint (costa-slave --control, transcript `sim`),
// parsed without the C++ library so that firmware replaying transcripts understands them too:
//
//   position N        the encoder's multi-turn position, counts (-2147483648..2147483647)
//   dir on|off        the DIR input (negative limit and home switch of homing)
//   pu on|off         the PU input (positive limit)
//   alarm CODE        a latched alarm: 0x10 (battery), 0x12 (locked rotor), 0x14 (stall)
//   voltage V         the supply voltage, 0..100 V; above 52 V alarm 0x15 (line 135)
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa::mseries {

struct JointControl {
  enum class Kind : uint8_t { kNone, kPosition, kDir, kPu, kAlarm, kVoltage };
  Kind kind = Kind::kNone;
  int64_t value = 0;  ///< the position, alarm code, voltage, or 1 / 0 for on / off
  /// Why the command was refused (kind kNone), a constant string.
  const char* error = "";
};

/// Parses one command (NUL-terminated).
JointControl parseJointControl(const char* text) noexcept;

}  // namespace costa::mseries
