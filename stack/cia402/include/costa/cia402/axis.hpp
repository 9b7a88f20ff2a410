// The narrow interface between the CiA 402 drive profile (drive.hpp) and the device behind it:
// the profile says how the axis is to move, the axis says where it is. A device implements it
// with its motor control (or a simulation); units are the device's own (position in counts,
// velocity in the unit of 0x606C / 0x60FF / 0x6081, accelerations in that of 0x6083).
#pragma once

#include <stdint.h>

#include "costa/cia402/power_state_machine.hpp"

namespace costa::cia402 {

/// How the axis is to move.
enum class Motion : uint8_t {
  kFree,         ///< no torque (the power stage is off)
  kStop,         ///< decelerate with `deceleration` to rest, then hold (0: stop at once)
  kPosition,     ///< go to `position`: at most `velocity`, ramps `acceleration`/`deceleration`
  kVelocity,     ///< reach `velocity` with `acceleration`/`deceleration` (0: no ramp)
  kHoming,       ///< run homing method `homingMethod`; the axis sets its position at home
  kInterpolate,  ///< reach `position` within `period` microseconds (one interpolation cycle)
};

struct AxisCommand {
  Motion motion = Motion::kFree;
  int32_t position = 0;
  int32_t velocity = 0;
  uint32_t acceleration = 0;
  uint32_t deceleration = 0;
  uint32_t period = 0;
  int8_t homingMethod = 0;

  constexpr bool operator==(const AxisCommand& other) const noexcept {
    return motion == other.motion && position == other.position && velocity == other.velocity &&
           acceleration == other.acceleration && deceleration == other.deceleration &&
           period == other.period && homingMethod == other.homingMethod;
  }
  constexpr bool operator!=(const AxisCommand& other) const noexcept { return !(*this == other); }
};

enum class HomingState : uint8_t { kIdle, kRunning, kAttained, kError };

/// Where the axis is.
struct AxisState {
  int32_t position = 0;  ///< 0x6064
  int32_t velocity = 0;  ///< 0x606C
  bool atRest = true;    ///< not moving (and not about to: a stop or a move has ended)
  HomingState homing = HomingState::kIdle;
  bool fault = false;  ///< a fault is present (the drive goes through fault reaction to fault)
};

class Axis {
 public:
  /// The axis is to move as `command` says from now on (called when the command changes).
  virtual void command(const AxisCommand& command) noexcept { (void)command; }
  virtual AxisState state() const noexcept { return AxisState{}; }
  /// Fault reset (control word bit 7 rising in fault): clears what can be cleared; the drive
  /// leaves fault once state().fault is false.
  virtual void resetFault() noexcept {}
  /// The status word as the device shows it: `statusword` is the profile's (CiA 402 with the
  /// options' differences) in `state`; a device adds manufacturer bits or its own words.
  virtual uint16_t statusword(uint16_t statusword, PowerState state) noexcept {
    (void)state;
    return statusword;
  }

 protected:
  Axis() = default;
  ~Axis() = default;
  Axis(const Axis&) = default;
  Axis& operator=(const Axis&) = default;
  Axis(Axis&&) = default;
  Axis& operator=(Axis&&) = default;
};

}  // namespace costa::cia402
