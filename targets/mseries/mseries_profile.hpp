// The M-series joint's wire behaviour as a Costa device profile, and its CiA 402 differences as
// drive options (docs/errata-m-series.md: W wire, B behaviour).
#pragma once

#include "costa/cia402/drive_options.hpp"
#include "costa/node.hpp"

namespace costa::mseries {

/// CiA 301 SDO (the printed 0x40 replies and 0x6040 indices are errata W1, W2), heartbeat only
/// (no guarding, no RTR: W9), no EMCY producer (W10), heartbeat byte 04 while an alarm is active
/// (W6) and no NMT change on a heartbeat timeout (W7), each TPDO n answering RPDO n (W8).
constexpr DeviceProfile profile() noexcept {
  DeviceProfile p{};
  // The device needs the quirk profiles (joint_device.cpp); its header compiles in any tree.
#if COSTA_QUIRK_PROFILES
  p.errorControl.nodeGuarding = false;
  p.errorControl.emcyForErrors = false;
  p.errorControl.errorBehaviourWithoutObject = 1;  // no state change
  p.errorControl.heartbeatWhileError = 0x04;
  p.emcy.sendFrames = false;
  p.pdo.tpdoAnswersRpdo = true;
#endif
  return p;
}

/// The joint's CiA 402 differences, each an addition a standard master does not need: one
/// 0x0F enables (B1), bit 4 clears itself (B2), with bit 5 a new 0x607A moves (B3), mode 6
/// starts homing (B4), halt stops at once (B5), status bits 6, 7, 9, 11 unused and 12, 13
/// only in homing (B6), interpolation from 0x607A at each SYNC on a 2 ms cycle (B8), TPDOs only
/// as RPDO answers (W8).
constexpr cia402::DriveOptions driveOptions() noexcept {
  cia402::DriveOptions o{};
  o.power.enableFromSwitchOnDisabled = true;
  o.newSetPointClears = true;
  o.targetWriteStartsMove = true;
  o.homingOnModeWrite = true;
  o.abruptHalt = true;
  o.unusedStatusBits = cia402::status::kSwitchOnDisabled | cia402::status::kWarning |
                       cia402::status::kRemote | cia402::status::kInternalLimitActive;
  o.modeStatusModes = cia402::modeBit(cia402::kHoming);
  o.ipWithoutEnableBit = true;
  o.ipSetPointIndex = 0x607A;
  o.ipSetPointSubIndex = 0;
  o.ipPeriod = 2000;
  o.statusChangesAreEvents = false;
  return o;
}

}  // namespace costa::mseries
