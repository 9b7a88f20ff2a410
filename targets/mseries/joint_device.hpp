// The behaviour behind an M-series joint's objects (docs/errata-m-series.md): the CiA 402 drive
// (stack/cia402) in front of the motor (JointBackend), the joint's own status words under pulse
// control (B7), its alarms (joint_alarms.hpp) and the vendor objects 0x2600..0x261D:
//
//   0x2601  drive output enabled: 0 no torque; writing 1 also clears faults (B15)
//   0x260A  60006 then 60016: the multi-turn zero (B11)
//   0x260E  the alarm code; writing 0 acknowledges (D18)
//   0x2614  1 saves the parameters, then reads 2 (B13)
//   0x2615  the node-id, effective after a save and the next power-on (W11)
//   0x2619  power-on functions 6 (back to the multi-turn zero), 9 (CANopen control), 30..32768
//           (to that position) (B12)
//   0x6098  homing method: 20 refused (D9)
//   heartbeat of 0x1016's producer lost / back (or no longer waited for: reset communication,
//   a new 0x1016:01): alarm 0x20, the drive holds / resumes (W7)
#pragma once

#include "costa/cia402/drive.hpp"
#include "costa/node.hpp"
#include "joint_alarms.hpp"
#include "joint_backend.hpp"
#include "mseries_od.hpp"

namespace costa::mseries {

/// The node of a joint: its generated dictionary, sized by it.
using MSeriesNode = NodeInstance<gen::mseries::Values, gen::mseries::Capacity>;

/// Supply voltage above which the joint raises alarm 0x15 (line 135).
inline constexpr uint32_t kOverVoltage = 52;

class JointDevice : public ObjectHook, public NodeEvents, public cia402::Axis {
 public:
  /// The joint's objects are refreshed in steps of this length while the motor moves.
  static constexpr Microseconds kStep = 1000;

  /// Attaches the drive and itself to `node`. `powerOnNodeId` is the node-id when
  /// `nodeIdGiven` (costa-slave --node-id), over 0x2615.
  JointDevice(MSeriesNode& node, JointBackend& joint, uint8_t powerOnNodeId,
              bool nodeIdGiven) noexcept;

  /// Lets the motor run up to `now`, refreshes the objects and the drive; returns the next step
  /// while the motor moves, else kNever.
  Microseconds process(Microseconds now) noexcept;

  /// Simulation: a latched alarm (0x10, 0x12, 0x14); false for another code.
  bool raiseAlarm(uint8_t alarm) noexcept;
  /// Simulation: the supply voltage; above kOverVoltage raises alarm 0x15.
  void setSupplyVolts(uint32_t volts) noexcept;

  /// The status word shows the drive's state (the fuzzer's invariant): bits 0..5 as the state
  /// sets them, or the joint's own word under pulse control (B7); never bits 6, 7, 9, 11; bits
  /// 12, 13 only in homing (B6). Otherwise false, with why in `why` (as snprintf writes).
  bool consistent(char* why, size_t whySize) const noexcept;

  cia402::Drive& drive() noexcept { return drive_; }
  const JointAlarms& alarms() const noexcept { return alarms_; }
  /// Every hook and listener of the joint and its drive found room in the node.
  bool attached() const noexcept { return attached_ && drive_.attached(); }

  // ObjectHook: 0x2600..0x261D, 0x6098.
  AbortCode check(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  // NodeEvents.
  void onResetApplication() noexcept override;
  void onResetCommunication() noexcept override;
  void onHeartbeatTimeout(uint8_t nodeId) noexcept override;
  void onHeartbeatResumed(uint8_t nodeId) noexcept override;
  void onHeartbeatWithdrawn(uint8_t nodeId) noexcept override;
  // cia402::Axis.
  void command(const cia402::AxisCommand& command) noexcept override;
  cia402::AxisState state() const noexcept override;
  void resetFault() noexcept override;
  uint16_t statusword(uint16_t statusword, cia402::PowerState state) noexcept override;

 private:
  /// Gives the motor the drive's command, or the joint's own motion under pulse control.
  void apply() noexcept;
  void publish(const JointFeedback& feedback) noexcept;
  uint32_t homingSpeed() const noexcept;
  AbortCode save() noexcept;
  /// The master is no longer silent (0x1016 has one entry): its heartbeat is back, the entry
  /// has a new value, or the consumer started over. The communication alarm ends and the
  /// joint resumes its mode.
  void communicationRestored() noexcept;
  AbortCode writeGearNumerator(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                               const uint8_t* data, size_t length) noexcept;

  Node& node_;
  gen::mseries::Values& values_;
  JointBackend& joint_;
  JointAlarms alarms_;
  cia402::Drive drive_;
  cia402::AxisCommand driveCommand_{};
  cia402::AxisCommand ownMotion_{};  ///< a power-on motion under pulse control (0x2619)
  uint32_t supplyVolts_ = 36;
  uint16_t gearBeforeZero_ = 0;  ///< 0x260A before 60006
  bool zeroStarted_ = false;     ///< 60006 was written: 60016 sets the zero
  bool pulseControl_ = true;     ///< before control word bit 0 (line 395, B7)
  bool homingByCan_ = false;     ///< homing was started over CANopen (status bit 4, B7)
  uint8_t powerOnNodeId_;
  bool nodeIdGiven_;
  Microseconds simulated_ = 0;  ///< the motor has run up to here
  bool attached_;               ///< last: every other member is ready when the node gets the hooks
};

}  // namespace costa::mseries
