// The CiA 402 power drive system state machine ("device control", CiA 402-2 / IEC 61800-7-201):
// its states, the commands of the control word, the transitions 0..16 and the state bits of the
// status word, as pure functions. No device, no dictionary, no time: drive.hpp runs it.
#pragma once

#include <stdint.h>

namespace costa::cia402 {

enum class PowerState : uint8_t {
  kNotReadyToSwitchOn,
  kSwitchOnDisabled,
  kReadyToSwitchOn,
  kSwitchedOn,
  kOperationEnabled,
  kQuickStopActive,
  kFaultReactionActive,
  kFault,
};

/// Control word bits (0x6040). Bits 4..6 and 9 are mode-specific.
namespace control {
inline constexpr uint16_t kSwitchOn = 1U << 0;
inline constexpr uint16_t kEnableVoltage = 1U << 1;
inline constexpr uint16_t kQuickStop = 1U << 2;  ///< 0: quick stop
inline constexpr uint16_t kEnableOperation = 1U << 3;
inline constexpr uint16_t kNewSetPoint = 1U << 4;  ///< profile position; homing: start; ip: enable
inline constexpr uint16_t kChangeSetImmediately = 1U << 5;  ///< profile position
inline constexpr uint16_t kRelative = 1U << 6;              ///< profile position
inline constexpr uint16_t kFaultReset = 1U << 7;            ///< on its rising edge
inline constexpr uint16_t kHalt = 1U << 8;
}  // namespace control

/// Status word bits (0x6041). Bits 12 and 13 are mode-specific.
namespace status {
inline constexpr uint16_t kReadyToSwitchOn = 1U << 0;
inline constexpr uint16_t kSwitchedOn = 1U << 1;
inline constexpr uint16_t kOperationEnabled = 1U << 2;
inline constexpr uint16_t kFault = 1U << 3;
inline constexpr uint16_t kVoltageEnabled = 1U << 4;
inline constexpr uint16_t kQuickStop = 1U << 5;  ///< 0: quick stop active
inline constexpr uint16_t kSwitchOnDisabled = 1U << 6;
inline constexpr uint16_t kWarning = 1U << 7;
inline constexpr uint16_t kRemote = 1U << 9;
inline constexpr uint16_t kTargetReached = 1U << 10;
inline constexpr uint16_t kInternalLimitActive = 1U << 11;
inline constexpr uint16_t kModeBit12 = 1U << 12;
inline constexpr uint16_t kModeBit13 = 1U << 13;
}  // namespace status

/// The device control command a control word gives (bits 0..3, CiA 402 table "device control
/// commands"); fault reset is the rising edge of bit 7, outside this decoding.
enum class Command : uint8_t {
  kDisableVoltage,   ///< xxxx x0x: transitions 7, 9, 10, 12
  kQuickStop,        ///< xxx 0 1x: 7, 10, 11
  kShutdown,         ///< x 1 1 0: 2, 6, 8
  kSwitchOn,         ///< 0 1 1 1: 3; in operation enabled "disable operation", 5
  kEnableOperation,  ///< 1 1 1 1: 4, 16; from ready to switch on "switch on + enable", 3 + 4
};

constexpr Command decodeCommand(uint16_t controlword) noexcept {
  if ((controlword & control::kEnableVoltage) == 0U) {
    return Command::kDisableVoltage;
  }
  if ((controlword & control::kQuickStop) == 0U) {
    return Command::kQuickStop;
  }
  if ((controlword & control::kSwitchOn) == 0U) {
    return Command::kShutdown;
  }
  return (controlword & control::kEnableOperation) == 0U ? Command::kSwitchOn
                                                         : Command::kEnableOperation;
}

/// What decides a transition besides the control word.
struct PowerInputs {
  bool faultReset = false;  ///< control word bit 7 has just gone from 0 to 1
  bool fault = false;       ///< a fault is present: 13; 15 only once it is gone
  bool stopped = false;  ///< the drive is at rest: ends a quick stop (12) and a fault reaction (14)
};

/// A device's choices; each default is CiA 402's.
struct PowerOptions {
  /// Quick stop option code (0x605A): 0..4 go to switch on disabled (12) once stopped (0: at
  /// once), 5..8 stay in quick stop active, from where enable operation returns (16).
  int16_t quickStopOption = 2;
  /// Enable operation in switch on disabled takes 2, 3 and 4 at once: a drive that one control
  /// word enables. CiA 402 leaves switch on disabled only by shutdown (2).
  bool enableFromSwitchOnDisabled = false;
};

inline constexpr uint8_t kNoTransition = 0xFF;

struct PowerTransition {
  PowerState state;  ///< after the transition; the same state when none is taken
  uint8_t number;    ///< the CiA 402 number of the (last) transition taken, or kNoTransition
};

/// One step of the state machine from `state` under `controlword` and `inputs`. Transitions
/// 0 and 1 (power-on, initialised) are automatic: from not ready to switch on the machine goes
/// to switch on disabled. A fault in any state but fault reaction active and fault is 13.
PowerTransition nextPowerState(PowerState state, uint16_t controlword, const PowerInputs& inputs,
                               const PowerOptions& options) noexcept;

/// Status word bits 0..6 of `state` (CiA 402 table "state coding"), with bit 4 (voltage
/// enabled) where the power stage may be on: ready to switch on, switched on, operation
/// enabled, quick stop active, fault reaction active.
uint16_t stateStatusBits(PowerState state) noexcept;

/// The state a status word shows, by CiA 402's masks (0x4F, 0x6F); false when bits 0..6 show
/// none (the vendor words of a drive under its own control, for example).
bool stateOfStatusword(uint16_t statusword, PowerState* state) noexcept;

}  // namespace costa::cia402
