// Where M-series firmware meets its motor: the joint asks for a motion (the CiA 402 axis
// command with the joint's homing speed), lets time pass, and reads back where the motor is.
// The Linux slave, the tests and the firmware images here use SimulatedJoint; a joint's own
// firmware implements these functions with its FOC loop, encoder and inputs.
#pragma once

#include <stdint.h>

#include "costa/cia402/axis.hpp"
#include "costa/time.hpp"

namespace costa::mseries {

/// Counts of the 15-bit encoder per turn (line 29).
inline constexpr int32_t kCountsPerTurn = 32768;

/// What the joint asks of its motor.
struct JointCommand {
  cia402::AxisCommand axis{};
  uint32_t homingSpeed = 0;  ///< r/min, for axis.motion == kHoming (0x6083's ones digit, line 277)
};

/// What the motor reports.
struct JointFeedback {
  int32_t position = 0;  ///< counts
  int32_t velocity = 0;  ///< r/min
  bool atRest = true;
  cia402::HomingState homing = cia402::HomingState::kIdle;
  uint16_t current = 0;  ///< 0x6078: 1/2000 A
  int16_t pwm = 0;       ///< 0x2613: 32767 = 100 %
  bool dir = false;      ///< the DIR input (negative limit, home switch)
  bool pu = false;       ///< the PU input (positive limit)
};

class JointBackend {
 public:
  /// The motor is to move as `command` says from now on.
  virtual void drive(const JointCommand& command) noexcept { (void)command; }
  /// Lets `elapsed` pass (a simulation integrates; hardware ignores it).
  virtual void step(Microseconds elapsed) noexcept { (void)elapsed; }
  virtual JointFeedback read() const noexcept { return JointFeedback{}; }
  /// True while the motor moves or is about to: the joint then refreshes its objects at every
  /// step (a firmware loop that runs at a fixed rate may always answer true).
  virtual bool moving() const noexcept { return false; }
  /// Sets the multi-turn position (the zero setting of 0x260A: 0).
  virtual void setPosition(int32_t position) noexcept { (void)position; }

 protected:
  JointBackend() = default;
  ~JointBackend() = default;
  JointBackend(const JointBackend&) = default;
  JointBackend& operator=(const JointBackend&) = default;
  JointBackend(JointBackend&&) = default;
  JointBackend& operator=(JointBackend&&) = default;
};

}  // namespace costa::mseries
