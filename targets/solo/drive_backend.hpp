// Where SOLO firmware would meet its power stage: the drive's commands go out, measurements come
// back. The Linux slave and the tests use SimulatedDrive; real firmware would implement these
// functions with the motor-control loop of its hardware.
#pragma once

#include <stdint.h>

#include "costa/time.hpp"

namespace costa::solo {

enum class CommandingMode : uint32_t { kAnalogue = 0, kDigital = 1, kAnalogueDigitalGains = 2 };
enum class ControlMode : uint32_t { kSpeed = 0, kTorque = 1, kPosition = 2 };
enum class FeedbackMode : uint32_t { kSensorless = 0, kEncoder = 1, kHall = 2, kZsft = 3 };
enum class MotorType : uint32_t {
  kDcBrushed = 0,
  kBldcPmsm = 1,
  kAcim = 2,
  kBldcPmsmUltrafast = 3
};

/// What the dictionary asks of the drive (physical units).
struct DriveCommand {
  bool outputEnabled = true;                              ///< 0x3008, and no fault (0x3020 = 0)
  CommandingMode commanding = CommandingMode::kAnalogue;  ///< 0x3002
  ControlMode control = ControlMode::kSpeed;              ///< 0x3016
  FeedbackMode feedback = FeedbackMode::kSensorless;      ///< 0x3013
  MotorType motor = MotorType::kDcBrushed;                ///< 0x3015
  double speedReferenceRpm = 0;                           ///< 0x3005
  bool clockwise = false;                                 ///< 0x300C
  double accelerationRevPerS2 = 0;                        ///< 0x302A (0: the motor's own limit)
  double decelerationRevPerS2 = 0;                        ///< 0x302B (0: the motor's own limit)
  double speedLimitRpm = 0;                               ///< 0x3011
  int32_t positionReference = 0;                          ///< 0x301B, quadrature pulses
  double torqueReferenceA = 0;                            ///< 0x3004
  double idReferenceA = 0;                                ///< 0x301A
  double currentLimitA = 0;                               ///< 0x3003
  uint32_t poles = 8;                                     ///< 0x300F
  uint32_t encoderLines = 1000;                           ///< 0x3010
};

/// What the drive measures.
struct DriveFeedback {
  double speedRpm = 0;           ///< 0x3036
  int32_t position = 0;          ///< 0x3037
  double iqA = 0;                ///< 0x3034
  double idA = 0;                ///< 0x3035
  double phaseACurrentA = 0;     ///< 0x302F
  double phaseBCurrentA = 0;     ///< 0x3030
  double phaseAVoltageV = 0;     ///< 0x302D
  double phaseBVoltageV = 0;     ///< 0x302E
  double busVoltageV = 0;        ///< 0x3031
  double motorCurrentA = 0;      ///< 0x3032 (DC brushed)
  double motorVoltageV = 0;      ///< 0x3033 (DC brushed)
  double anglePerUnit = 0;       ///< 0x3038
  double boardTemperatureC = 0;  ///< 0x3039
  uint32_t analogue[2] = {};     ///< 0x304A channels 0 (S/T) and 1 (P/F), 0..4095
  uint32_t digitalInputs = 0;    ///< 0x3049
  uint32_t faults = 0;           ///< 0x3020 bits the hardware detects (bit 0 over-current, ...)
};

class DriveBackend {
 public:
  /// Applies `command` and lets `elapsed` pass (a simulation integrates; hardware ignores it).
  virtual void step(const DriveCommand& command, Microseconds elapsed) noexcept {
    (void)command;
    (void)elapsed;
  }
  /// True when a step under `command` would change nothing, nor would any further one: the
  /// device then stops stepping until that changes. A simulation can tell; hardware cannot (its
  /// motor turns on its own), and is stepped always.
  virtual bool restsUnder(const DriveCommand& command) const noexcept {
    (void)command;
    return false;
  }
  virtual void read(DriveFeedback* feedback) noexcept { (void)feedback; }
  /// 0x301F: the position counter becomes 0.
  virtual void home() noexcept {}
  /// 0x3007: identify the motor; true when done, with resistance (Ω) and inductance (H).
  virtual bool identify(double* resistance, double* inductance) noexcept {
    (void)resistance;
    (void)inductance;
    return false;
  }

 protected:
  DriveBackend() = default;
  ~DriveBackend() = default;
  DriveBackend(const DriveBackend&) = default;
  DriveBackend& operator=(const DriveBackend&) = default;
  DriveBackend(DriveBackend&&) = default;
  DriveBackend& operator=(DriveBackend&&) = default;
};

}  // namespace costa::solo
