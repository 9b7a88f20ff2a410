// The CiA 402 drive profile on a node: the control word (0x6040) through the power state
// machine, the modes of operation (0x6060, shown in 0x6061, those of 0x6502) with their
// set-points, the status word (0x6041) and the actual values (0x6064, 0x606C), in front of an
// axis (axis.hpp) that moves. Usable by any drive: it listens to its node (RPDOs, SYNC, reset
// application) and attaches hooks to 0x6040, 0x6060 and 0x607A; a device's own objects and its
// manual's differences (drive_options.hpp) stay with the device.
//
// Control word and set-points take effect when written by SDO, when a whole RPDO has been
// written (an RPDO with control word and target is taken as one), and at a SYNC for
// interpolated position. Modes (CiA 402-2):
//   1 profile position      bit 4 rising: new set-point 0x607A (bit 6 relative to the previous
//                           set-point, bit 5 at once, else after the move in progress), 0x6081
//                           velocity, 0x6083 acceleration, 0x6084 deceleration (else 0x6083);
//                           status 10 target reached, 12 set-point acknowledge
//   3 profile velocity      0x60FF with 0x6083 / 0x6084; status 10 velocity reached, 12 speed 0
//   6 homing                bit 4 rising: method 0x6098; status 10, 12 attained, 13 error
//   7 interpolated position at each SYNC with bit 4 (enable ip mode): the set-point 0x60C1:01,
//                           reached within the cycle 0x60C2; status 12 ip mode active
// Halt (bit 8) stops with the profile deceleration; quick stop with 0x6085 (else 0x6084, 0x6083).
//
// Context: the one that runs the node. No allocation; every call is O(1) dictionary lookups (the
// objects of every evaluation are located once, when the drive is made).
#pragma once

#include <stdint.h>

#include "costa/cia402/axis.hpp"
#include "costa/cia402/drive_options.hpp"
#include "costa/cia402/power_state_machine.hpp"
#include "costa/node.hpp"

namespace costa::cia402 {

namespace object {
inline constexpr uint16_t kControlword = 0x6040;
inline constexpr uint16_t kStatusword = 0x6041;
inline constexpr uint16_t kModes = 0x6060;
inline constexpr uint16_t kModesDisplay = 0x6061;
inline constexpr uint16_t kPositionActual = 0x6064;
inline constexpr uint16_t kVelocityActual = 0x606C;
inline constexpr uint16_t kTargetPosition = 0x607A;
inline constexpr uint16_t kProfileVelocity = 0x6081;
inline constexpr uint16_t kProfileAcceleration = 0x6083;
inline constexpr uint16_t kProfileDeceleration = 0x6084;
inline constexpr uint16_t kQuickStopDeceleration = 0x6085;
inline constexpr uint16_t kHomingMethod = 0x6098;
inline constexpr uint16_t kInterpolationPeriod = 0x60C2;
inline constexpr uint16_t kTargetVelocity = 0x60FF;
inline constexpr uint16_t kSupportedModes = 0x6502;
}  // namespace object

class Drive : public ObjectHook, public NodeEvents {
 public:
  /// Attaches the hooks and the listener to `node`; `axis` and `node` outlive the drive.
  Drive(Node& node, Axis& axis, const DriveOptions& options) noexcept;

  /// The hooks and the listener found room in the node.
  bool attached() const noexcept { return attached_; }

  /// Brings the drive up to date with its axis (call after the axis moved): ends stops, moves
  /// and homing, runs the state machine, writes 0x6041, 0x6061, 0x6064 and 0x606C.
  void update() noexcept { evaluate(); }
  /// A stop of the device's own (a communication alarm, say): while on, operation enabled
  /// stops the axis at once and holds it; the mode's motion resumes when it goes off.
  void hold(bool on) noexcept;

  PowerState state() const noexcept { return state_; }
  int8_t mode() const noexcept { return mode_; }
  uint16_t statusword() const noexcept { return statusword_; }
  /// The command the axis was given last.
  const AxisCommand& axisCommand() const noexcept { return commanded_; }

  /// 0x6060: a mode 0x6502 does not list aborts 0x06090030; 0 is "no mode change".
  AbortCode check(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;
  void onResetApplication() noexcept override;
  void onRpdoWriting(uint16_t communicationIndex) noexcept override;
  void onRpdoReceived(uint16_t communicationIndex) noexcept override;
  void onSync(uint8_t counter) noexcept override;

 private:
  void evaluate() noexcept;
  void runStateMachine(uint16_t controlword, AxisState* axis) noexcept;
  void enter(PowerState state) noexcept;
  void changeMode(int8_t mode) noexcept;
  /// Ends what the axis has finished: a move to the set-point, homing.
  void complete(const AxisState& axis) noexcept;
  /// Set-points and starts the control word and the writes ask for; returns the control word
  /// as it stands afterwards (bit 4 cleared by newSetPointClears).
  uint16_t takeEvents(uint16_t controlword, const AxisState& axis) noexcept;
  void takeSetPoint(uint16_t controlword, const AxisState& axis) noexcept;
  void startHoming() noexcept;
  AxisCommand motion(uint16_t controlword) const noexcept;
  AxisCommand modeMotion() const noexcept;
  uint16_t statusOf(uint16_t controlword, const AxisState& axis) const noexcept;
  uint16_t modeStatus(uint16_t controlword, const AxisState& axis) const noexcept;
  /// Status bits 12 (attained) and 13 (error) of homing.
  uint16_t homingStatus() const noexcept;
  bool supported(int8_t mode) const noexcept;

  /// The objects an evaluation reads or writes each time, or may read in its mode (sub-index 0),
  /// in the order of kLocatedIndices (drive.cpp); 0x6083, 0x6084 and 0x6085 in a row, for
  /// deceleration().
  enum Located : uint8_t {
    kControlwordAt,
    kStatuswordAt,
    kModesAt,
    kModesDisplayAt,
    kPositionActualAt,
    kVelocityActualAt,
    kProfileVelocityAt,
    kProfileAccelerationAt,
    kProfileDecelerationAt,
    kQuickStopDecelerationAt,
    kTargetVelocityAt,
    kLocatedCount
  };
  /// The Located objects, found in the dictionary and resolved once; not valid where it lacks
  /// one.
  struct LocatedObjects {
    explicit LocatedObjects(const od::ObjectDictionary& dictionary) noexcept;
    od::Scalar values[kLocatedCount];
  };
  /// The value of a located object as a signed number; `fallback` when the dictionary lacks it.
  int64_t value(Located object, int64_t fallback) const noexcept;
  /// Stores into a located object when the dictionary has it.
  void store(Located object, uint64_t value) noexcept;
  /// The same for any other entry, looked up each time.
  int64_t read(uint16_t index, uint8_t subIndex, int64_t fallback) const noexcept;
  /// The first of `first`, 0x6084, 0x6083 (down to kProfileAccelerationAt) that the dictionary
  /// has; 0 (at once) when none.
  uint32_t deceleration(Located first) const noexcept;
  uint32_t interpolationPeriod() const noexcept;

  Node& node_;
  Axis& axis_;
  DriveOptions options_;
  PowerState state_ = PowerState::kNotReadyToSwitchOn;
  uint16_t lastControlword_ = 0;  ///< the control word evaluated last (for its edges)
  uint16_t statusword_ = 0;
  int8_t mode_ = kNoMode;
  int8_t shownMode_ = kNoMode;  ///< 0x6061 as written last
  // Profile position.
  int32_t setPoint_ = 0;
  int32_t pendingSetPoint_ = 0;
  bool setPointTaken_ = false;  ///< setPoint_ holds a set-point of this mode
  bool moving_ = false;         ///< the axis goes to setPoint_
  bool pending_ = false;        ///< pendingSetPoint_ follows once setPoint_ is reached
  bool acknowledged_ = false;   ///< status bit 12 in profile position
  // Homing.
  bool homingRunning_ = false;
  bool homingRestart_ = false;  ///< command the axis even if the command is the same as before
  HomingState homingResult_ = HomingState::kIdle;
  // Interpolated position.
  int32_t ipTarget_ = 0;
  bool ipTaken_ = false;
  // What happened since the last evaluation.
  bool deferring_ = false;  ///< an RPDO is being written: evaluate once it is complete
  bool targetWritten_ = false;
  bool modeWritten_ = false;
  bool hold_ = false;
  AxisCommand commanded_{};
  LocatedObjects located_;
  bool attached_;  ///< last: every other member is ready when the node gets the hooks
};

}  // namespace costa::cia402
