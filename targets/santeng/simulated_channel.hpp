// One simulated motor channel of a Santeng controller, in integer arithmetic (so that every
// build, x86-64 or Cortex-M, computes the same readings), integrated in steps of 1 ms.
//
// Model (targets/santeng/README.md, docs/errata-santeng.md B1-B3, B16):
//   - speeds are kept in 1/10000 RPM; 0x2006/0x2007 (0.1 RPM/s) change the speed by exactly
//     their value per millisecond in these units; 0 changes it at once;
//   - speed modes: the command ramps to 0x2000 per mille of max RPM, at the acceleration while
//     the speed grows in magnitude, else at the deceleration; the motor follows the ramped
//     command;
//   - count position mode: moves to 0x2001 at |0x2002| RPM (at most max RPM), accelerating at
//     0x2006 and braking at 0x2007 when the stopping distance v^2 * lines / (3 * deceleration)
//     counts reaches the distance left; it stops exactly on the count; 0x2002 = 0 stands still;
//   - 4 encoder counts per line (lines 537, 684), 24 hall counts per revolution (D23);
//   - without power (emergency stop, fault) the command is 0 and the motor coasts down at
//     1000 RPM/s; a stalled motor (simulation) does not turn while its command ramps on;
//   - motor current (A x 10): speed / 50 RPM plus the acceleration, or the stall current
//     |command| / 10 per mille; battery current: motor current x |command| / 1000.
#pragma once

#include <stdint.h>

#include "power_stage.hpp"

namespace costa::santeng {

class SimulatedChannel {
 public:
  static constexpr int64_t kUnitsPerRpm = 10000;
  /// Coasting without power, in 0.1 RPM/s (units per millisecond).
  static constexpr int64_t kCoastRate = 10000;
  static constexpr int64_t kHallCountsPerRevolution = 24;

  /// `elapsed` (whole milliseconds) under `command`, in steps of 1 ms; the time left once the
  /// channel is at rest passes without steps, and once it runs at a steady speed, in one.
  void run(const ChannelCommand& command, Microseconds elapsed) noexcept;
  /// Nothing would change in a step under `command`.
  bool atRest(const ChannelCommand& command) const noexcept;
  /// What the channel measures now (kept up to date as its state changes).
  const ChannelReading& reading() const noexcept { return reading_; }
  void loadCounter(int32_t count) noexcept {
    count_ = count;
    measure();
  }
  void setStalled(bool stalled) noexcept {
    stalled_ = stalled;
    measure();
  }
  bool stalled() const noexcept { return stalled_; }
  /// Power-on: at rest, counters 0 (the stall stays: it is the motor's).
  void reset() noexcept;

 private:
  /// The speed the command asks for now, in units.
  int64_t targetSpeed(const ChannelCommand& command) const noexcept;
  int64_t positionTarget(const ChannelCommand& command) const noexcept;
  /// One millisecond under `command`.
  void stepMillisecond(const ChannelCommand& command) noexcept;
  /// A step under `command` would only count on at a steady speed (see cruise()).
  bool cruising(const ChannelCommand& command) const noexcept;
  /// `steps` milliseconds of stepMillisecond() while cruising(): the counts in one sum.
  void cruise(const ChannelCommand& command, uint32_t steps) noexcept;
  /// Counts of this millisecond; in count position mode, arrival on the target.
  void move(const ChannelCommand& command) noexcept;
  /// Adds a travel of `unitMilliseconds` (speed x time) to the remainders and the hall count;
  /// returns the encoder counts it makes at `encoderLines`.
  int64_t travel(int64_t unitMilliseconds, uint16_t encoderLines) noexcept;
  /// reading_ from the state.
  void measure() noexcept;

  int64_t ramped_ = 0;  ///< the command after the ramps, units
  int64_t actual_ = 0;  ///< the motor's speed, units
  int64_t change_ = 0;  ///< |ramped_ change| in the last millisecond, units
  int64_t count_ = 0;
  int64_t countRemainder_ = 0;
  int64_t hallCount_ = 0;
  int64_t hallRemainder_ = 0;
  uint16_t maxRpm_ = 1000;
  ChannelMode mode_ = ChannelMode::kOpenLoopSpeed;
  bool stalled_ = false;
  ChannelReading reading_;  ///< all 0: at rest, counters 0, not stalled
};

}  // namespace costa::santeng
