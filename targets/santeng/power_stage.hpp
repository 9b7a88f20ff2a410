// Where Santeng firmware would meet its power stage: what the dictionary asks of each channel
// goes out, what the controller measures comes back. The Linux slave, the replayer and the tests
// use SimulatedPowerStage; real firmware would implement these functions with the motor-control
// loops of its hardware (as the SOLO's DriveBackend).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/time.hpp"

namespace costa::santeng {

/// The controller's motor channels.
inline constexpr size_t kChannels = 2;

/// A channel's operating mode, numbered as the RS232 utility's (errata B14).
enum class ChannelMode : uint8_t {
  kOpenLoopSpeed = 0,    ///< 0x2000 is power in per mille of max RPM
  kClosedLoopSpeed = 1,  ///< 0x2000 is speed in per mille of max RPM
  kCountPosition = 3,    ///< 0x2001 is the count to go to at 0x2002 RPM
};

/// What the dictionary asks of one channel.
struct ChannelCommand {
  ChannelMode mode = ChannelMode::kOpenLoopSpeed;  ///< configuration (0x5000:02/03)
  bool powered = true;           ///< no emergency stop (0x200C) and no fault: else it coasts
  bool stopping = false;         ///< stop in all modes (0x200E) until the next motion command
  int16_t motorCommand = 0;      ///< 0x2000, -1000..1000 (per mille of max RPM)
  int32_t targetCount = 0;       ///< 0x2001, encoder counts
  int16_t positionSpeed = 0;     ///< 0x2002, RPM (its magnitude; 0 stands still)
  int32_t acceleration = 10000;  ///< 0x2006, 0.1 RPM/s (0: at once)
  int32_t deceleration = 10000;  ///< 0x2007, 0.1 RPM/s (0: at once)
  uint16_t maxRpm = 1000;        ///< configuration (0x5000:04/05)
  uint16_t encoderLines = 1000;  ///< configuration (0x5000:06/07): 4 counts per line
};

/// Motor status flags of a channel (0x2121, "FM", errata B7).
inline constexpr uint8_t kAmpsLimit = 0x01;
inline constexpr uint8_t kMotorStalled = 0x02;  ///< "Motor stops": commanded but not turning
inline constexpr uint8_t kLoopError = 0x04;     ///< a closed-loop mode cannot follow its command
inline constexpr uint8_t kSafeStop = 0x08;
inline constexpr uint8_t kForwardLimit = 0x10;
inline constexpr uint8_t kReverseLimit = 0x20;
inline constexpr uint8_t kAmpsTrigger = 0x40;

/// Fault flags of the controller (0x2112, "FF", errata B7, B8).
inline constexpr uint8_t kOverheat = 0x01;
inline constexpr uint8_t kOvervoltage = 0x02;  ///< "Overpressure" (line 760), B8
inline constexpr uint8_t kUndervoltage = 0x04;
inline constexpr uint8_t kShortCircuit = 0x08;
inline constexpr uint8_t kEmergencyStop = 0x10;
inline constexpr uint8_t kSensorFault = 0x20;
inline constexpr uint8_t kMosfetFailure = 0x40;
inline constexpr uint8_t kDefaultConfiguration = 0x80;  ///< defaults loaded at start-up (B10)

/// What the power stage measures on one channel.
struct ChannelReading {
  int32_t speedRpm = 0;            ///< 0x2103 (encoder), 0x210A (hall sensors)
  int16_t appliedPermille = 0;     ///< 0x2101: the command after the ramps
  int16_t speedPermille = 0;       ///< 0x2107: speed in per mille of max RPM
  int32_t encoderCount = 0;        ///< 0x2104
  int32_t hallCount = 0;           ///< 0x2105
  int16_t motorAmpsTimes10 = 0;    ///< 0x2100
  int16_t batteryAmpsTimes10 = 0;  ///< 0x210C
  uint8_t motorFlags = 0;          ///< motor status flags the channel detects
};

/// What the controller measures besides its channels.
struct ControllerReading {
  uint16_t voltages[3] = {};    ///< 0x210D: internal V x 10, battery V x 10, 5 V output mV
  int8_t temperatures[3] = {};  ///< 0x210F: MCU, channel 1 side, channel 2 side, degrees C
  uint32_t digitalInputs = 0;   ///< 0x210E: input n in bit n - 1
  uint8_t digitalOutputs = 0;   ///< 0x2113: output n in bit n - 1
  uint8_t faults = 0;           ///< fault flags the hardware detects (not 0x10, 0x80)
};

class PowerStage {
 public:
  /// Drives the channels as `commands` say for `elapsed` (a simulation integrates; hardware
  /// ignores the time).
  virtual void step(const ChannelCommand (&commands)[kChannels], Microseconds elapsed) noexcept {
    (void)commands;
    (void)elapsed;
  }
  /// True when nothing would change in a step with these commands (all channels at rest where
  /// they are asked to be): the caller may skip the time.
  virtual bool atRest(const ChannelCommand (&commands)[kChannels]) const noexcept {
    (void)commands;
    return true;
  }
  virtual void read(size_t channel, ChannelReading* reading) const noexcept {
    (void)channel;
    (void)reading;
  }
  virtual void read(ControllerReading* reading) const noexcept { (void)reading; }
  /// 0x2003: the channel's encoder counter becomes `count`.
  virtual void loadCounter(size_t channel, int32_t count) noexcept {
    (void)channel;
    (void)count;
  }
  /// Power-on: counters 0, motors at rest.
  virtual void reset() noexcept {}

 protected:
  PowerStage() = default;
  ~PowerStage() = default;
  PowerStage(const PowerStage&) = default;
  PowerStage& operator=(const PowerStage&) = default;
  PowerStage(PowerStage&&) = default;
  PowerStage& operator=(PowerStage&&) = default;
};

}  // namespace costa::santeng
