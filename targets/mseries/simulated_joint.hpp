// A simulated M-series joint motor (targets/mseries/README.md, "The simulated joint"): integer
// fixed-point physics in steps of 1 ms, so that the host and Cortex-M compute the same counts.
//
//   position  32768 counts per turn (line 29), multi-turn, INTEGER32
//   velocity  r/min; ramps with the acceleration in (r/min)/s, none from 60000 on (lines
//             195-203) or at 0
//   position  a trapezoid: up to the velocity, accelerating and braking with the ramps,
//             stopping exactly on the target
//   homing    17 negative until DIR, 18 positive until PU, 19 positive until DIR, 21 negative
//             until DIR (CiA 402's directions); the position becomes 0 there; any other method
//             fails at once. An input already active ends homing at once
//   interpolate  the target within the period, at most at the velocity given
//   stop      decelerates (0: at once) and holds; free: stops at once (a geared joint)
#pragma once

#include "joint_backend.hpp"

namespace costa::mseries {

class SimulatedJoint final : public JointBackend {
 public:
  static constexpr Microseconds kStep = 1000;
  /// Accelerations from this on (and 0) have no internal ramp (lines 195-203).
  static constexpr uint32_t kNoRampFrom = 60000;

  SimulatedJoint() noexcept { measure(); }

  void drive(const JointCommand& command) noexcept override;
  void step(Microseconds elapsed) noexcept override;
  /// What the last change left (kept, not computed at each read: the joint reads its motor for
  /// the drive and again to publish, at every step).
  JointFeedback read() const noexcept override { return reading_; }
  void setPosition(int32_t position) noexcept override;

  /// The DIR and PU inputs (simulation commands). Homing ends at once when the input it waits
  /// for becomes active: the origin is where the switch closes.
  void setInputs(bool dir, bool pu) noexcept;
  bool moving() const noexcept override;

 private:
  /// Computes reading_ from the state: after every change of it.
  void measure() noexcept;
  void stepOnce() noexcept;
  void stepPosition(int64_t target, int64_t limit) noexcept;
  void stepVelocity(int64_t target) noexcept;
  void stepHoming() noexcept;
  bool homingInputActive() const noexcept;
  /// Homing ends here when its input is active.
  bool homeIfActive() noexcept;
  /// True when homing is over (attained here, failed, or not running).
  bool homingEnded() noexcept;

  JointCommand command_{};
  int64_t position_ = 0;      ///< counts << 16
  int64_t velocity_ = 0;      ///< (counts << 16) per ms
  int64_t ipSpeed_ = 0;       ///< kInterpolate: (counts << 16) per ms
  Microseconds elapsed_ = 0;  ///< time not yet stepped (less than kStep)
  cia402::HomingState homing_ = cia402::HomingState::kIdle;
  bool dir_ = false;
  bool pu_ = false;
  JointFeedback reading_;
};

}  // namespace costa::mseries
