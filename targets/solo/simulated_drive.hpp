// A simulated motor behind a SOLO: speed ramps with the configured acceleration, position
// follows at up to the speed limit, Iq follows the torque reference, with plausible currents,
// voltages and temperature. Deterministic (no random noise), freestanding.
//
// Model (documented in targets/solo/README.md):
//   - the drive acts only in digital commanding mode, when enabled and without a fault;
//     otherwise the motor coasts down at kCoastRevPerS2;
//   - speed mode: the speed ramps to min(reference, speed limit) at 0x302A/0x302B (rev/s²), or
//     at kDefaultRampRevPerS2 when they are 0; a reference of 0 stops at kFastStopRevPerS2;
//   - position mode: moves to the reference at up to the speed limit, accelerating and braking
//     at kDefaultRampRevPerS2, and stops exactly on it;
//   - torque mode: Iq follows the reference (5 ms lag); Iq accelerates the rotor
//     (kRevPerS2PerAmp) against viscous friction;
//   - position counts: 4 × encoder lines per revolution (encoder and sensorless modes), 3 × poles
//     (hall mode, manual line 1380); counter-clockwise is positive.
#pragma once

#include "drive_backend.hpp"

namespace costa::solo {

class SimulatedDrive final : public DriveBackend {
 public:
  static constexpr double kDefaultRampRevPerS2 = 100.0;
  static constexpr double kFastStopRevPerS2 = 1000.0;
  static constexpr double kCoastRevPerS2 = 20.0;
  static constexpr double kRevPerS2PerAmp = 50.0;
  static constexpr double kBusVoltage = 24.0;
  static constexpr double kAmbientC = 25.0;
  static constexpr uint32_t kAnalogueInputs[2] = {0, 2048};

  void step(const DriveCommand& command, Microseconds elapsed) noexcept override;
  /// The last step was under `command` and left every part of the state as it was, bit for
  /// bit: from that state, every step under the same command does the same (the model is
  /// deterministic).
  bool restsUnder(const DriveCommand& command) const noexcept override;
  void read(DriveFeedback* feedback) noexcept override;
  void home() noexcept override {
    s_.position = 0;
    resting_ = false;
  }
  bool identify(double* resistance, double* inductance) noexcept override;

 private:
  void integrate(const DriveCommand& command, double dt) noexcept;
  void integrateSpeed(const DriveCommand& command, double dt) noexcept;
  /// True when the motor has arrived at the position reference (and stopped there).
  bool integratePosition(const DriveCommand& command, double dt) noexcept;
  void integrateTorque(const DriveCommand& command, double dt) noexcept;
  static double countsPerRevolution(const DriveCommand& command) noexcept;

  /// Everything a step reads and changes; no padding, so that two states compare bit for bit.
  struct State {
    double speedRpm = 0;
    double position = 0;
    double iq = 0;
    double id = 0;
    double temperature = kAmbientC;
    double electricalTurns = 0;  ///< electrical angle in turns, 0..1
    double polePairs = 4;
    uint32_t dcMotor = 0;  ///< 1 for a DC brushed motor
    uint32_t faults = 0;
  };
  static_assert(sizeof(State) == 7 * sizeof(double) + 2 * sizeof(uint32_t), "no padding");

  State s_;
  bool resting_ = false;      ///< the last step changed nothing
  DriveCommand lastCommand_;  ///< the command of the last step
};

}  // namespace costa::solo
