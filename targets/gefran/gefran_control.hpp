// The simulation commands of a GRA/GRN (costa-slave --control, transcript `sim`), parsed without
// the C++ library so that firmware replaying transcripts understands them too:
//   raw A B            raw 14-bit readings of chip 1 and chip 2 (0..16383)
//   angle DEG          both chips at the shaft angle DEG (degrees, decimal, |DEG| < 1e18)
//   fault WHAT on|off  WHAT = chip1, chip2 or magnet
// Words and numbers are read as `std::istream >>` reads them (white space skipped, a number
// ends where its characters end, anything after the last argument is not looked at).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "hall_sensors.hpp"

namespace costa::gefran {

enum class ControlError : uint8_t {
  kNone,
  kRawUsage,        ///< "usage: raw A B (0..16383)"
  kAngleUsage,      ///< "usage: angle DEGREES"
  kFaultUsage,      ///< "usage: fault chip1|chip2|magnet on|off"
  kUnknownCommand,  ///< "unknown command 'VERB' (raw, angle, fault)"
};

/// What a command does to the simulated chips.
struct ControlCommand {
  enum class Kind : uint8_t { kSetRaw, kSetFault };
  Kind kind = Kind::kSetRaw;
  uint16_t chip1 = 0;     ///< kSetRaw: reading of chip 1
  uint16_t chip2 = 0;     ///< kSetRaw: reading of chip 2
  uint8_t faultBits = 0;  ///< kSetFault: SensorFault bits
  bool faultOn = false;   ///< kSetFault: raise (true) or clear
};

struct ParsedControl {
  ControlError error = ControlError::kNone;
  ControlCommand command;  ///< valid when `error` is kNone
  const char* verb = "";   ///< the command's first word, inside the parsed text
  size_t verbLength = 0;
};

/// Parses one command (NUL-terminated).
ParsedControl parseControl(const char* text) noexcept;

/// Applies a parsed command to the chips.
void applyControl(const ControlCommand& command, SimulatedHallSensors& sensors) noexcept;

/// Writes why a command was refused (nothing for kNone) like snprintf: at most `size` - 1
/// characters and a NUL into `out` (which may be null when `size` is 0). Returns the length of
/// the whole message.
size_t describeControlError(const ParsedControl& parsed, char* out, size_t size) noexcept;

}  // namespace costa::gefran
