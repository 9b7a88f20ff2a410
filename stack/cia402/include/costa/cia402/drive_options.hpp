// The choices of a CiA 402 drive that depart from the profile (drive.hpp). Every default is
// CiA 402's, so `DriveOptions{}` is a conformant drive; a device sets the fields its manual
// documents, each an addition: a master that follows the standard still drives it.
#pragma once

#include <stdint.h>

#include "costa/cia402/power_state_machine.hpp"

namespace costa::cia402 {

/// Modes of operation (0x6060 / 0x6061) the profile runs, and their bits in 0x6502.
enum Mode : int8_t {
  kNoMode = 0,
  kProfilePosition = 1,
  kProfileVelocity = 3,
  kHoming = 6,
  kInterpolatedPosition = 7,
};

/// The bit of 0x6502 (supported drive modes) of `mode` (1..8), 0 for another value.
constexpr uint32_t modeBit(int8_t mode) noexcept {
  return mode >= 1 && mode <= 8 ? 1U << static_cast<unsigned>(mode - 1) : 0U;
}

struct DriveOptions {
  PowerOptions power{};
  /// The drive clears control word bit 4 once it has taken a new set-point, so writing the
  /// same control word again (0x5F) is a new set-point. CiA 402: the master clears it.
  bool newSetPointClears = false;
  /// In profile position mode with bit 5 (change set immediately) set, every write of 0x607A
  /// is a new set-point, without bit 4. CiA 402: only bit 4's rising edge is.
  bool targetWriteStartsMove = false;
  /// Writing 6 (homing) to 0x6060 starts homing at once, in any state but fault; CiA 402:
  /// bit 4's rising edge in operation enabled does.
  bool homingOnModeWrite = false;
  /// Halt (bit 8) stops at once and holds; CiA 402 decelerates (halt option code 1).
  bool abruptHalt = false;
  /// Status word bits the drive never sets (warning, remote, ...).
  uint16_t unusedStatusBits = 0;
  /// Modes (0x6502 bits, modeBit()) in which status bits 12 and 13 carry their CiA 402
  /// meaning; in the others they stay 0.
  uint32_t modeStatusModes = 0xFFFFFFFFU;
  /// Interpolated position runs without control word bit 4 (enable ip mode).
  bool ipWithoutEnableBit = false;
  /// Where each SYNC's interpolation set-point is read: CiA 402's 0x60C1:01, or another object.
  uint16_t ipSetPointIndex = 0x60C1;
  uint8_t ipSetPointSubIndex = 1;
  /// The interpolation cycle in microseconds; 0: from 0x60C2 (CiA 402).
  uint32_t ipPeriod = 0;
  /// Changes of the status word and of the mode display are application events for TPDOs
  /// mapping 0x6041 or 0x6061 (Node::markChanged): event-driven TPDOs follow them. False: a
  /// device whose TPDOs go out otherwise.
  bool statusChangesAreEvents = true;
};

}  // namespace costa::cia402
