#include "simulated_drive.hpp"

namespace costa::solo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRpmPerS2 = 60.0;  // rev/s² → rpm/s

double absolute(double x) {
  return x < 0 ? -x : x;
}
double clamp(double x, double low, double high) {
  return x < low ? low : (x > high ? high : x);
}

/// sin(2π·turns), accurate to about 1e-4 (parabola with a correction term).
double sineOfTurns(double turns) {
  turns -= static_cast<double>(static_cast<int64_t>(turns));
  if (turns < 0) {
    turns += 1.0;
  }
  const double x = turns < 0.5 ? turns * 2.0 * kPi : (turns - 1.0) * 2.0 * kPi;  // -π..π
  const double y = (4.0 / kPi) * x - (4.0 / (kPi * kPi)) * x * absolute(x);
  return 0.225 * (y * absolute(y) - y) + y;
}

double squareRoot(double x) {
  if (x <= 0) {
    return 0;
  }
  double r = x > 1 ? x : 1;
  for (int i = 0; i < 40; ++i) {
    r = 0.5 * (r + x / r);
  }
  return r;
}

/// Moves `value` towards `target` by at most `step`.
double approach(double value, double target, double step) {
  if (value < target) {
    return value + step > target ? target : value + step;
  }
  return value - step < target ? target : value - step;
}

}  // namespace

double SimulatedDrive::countsPerRevolution(const DriveCommand& command) noexcept {
  if (command.feedback == FeedbackMode::kHall) {
    return 3.0 * static_cast<double>(command.poles);
  }
  return 4.0 * static_cast<double>(command.encoderLines);
}

void SimulatedDrive::step(const DriveCommand& command, Microseconds elapsed) noexcept {
  polePairs_ = static_cast<double>(command.poles) / 2.0;
  dcMotor_ = command.motor == MotorType::kDcBrushed;
  if (command.currentLimitA <= 0.0) {
    faults_ |= 1U;  // over-current protection trips when the limit is 0 (manual line 885)
  } else {
    faults_ &= ~1U;
  }
  constexpr Microseconds kStep = 1000;  // integrate in 1 ms steps
  while (elapsed > 0) {
    const Microseconds slice = elapsed < kStep ? elapsed : kStep;
    integrate(command, static_cast<double>(slice) / 1e6);
    elapsed -= slice;
  }
}

void SimulatedDrive::integrate(const DriveCommand& command, double dt) noexcept {
  const bool driving =
      command.outputEnabled && faults_ == 0U && command.commanding == CommandingMode::kDigital;
  const double before = speedRpm_;
  if (!driving) {
    speedRpm_ = approach(speedRpm_, 0, kCoastRevPerS2 * kRpmPerS2 * dt);
    id_ = 0;
  } else if (command.control == ControlMode::kSpeed) {
    integrateSpeed(command, dt);
  } else if (command.control == ControlMode::kPosition) {
    if (integratePosition(command, dt)) {
      return;
    }
  } else {
    integrateTorque(command, dt);
  }
  if (!driving || command.control != ControlMode::kTorque) {
    const double accelRevPerS2 = (speedRpm_ - before) / 60.0 / dt;
    const double targetIq = driving ? accelRevPerS2 / kRevPerS2PerAmp + 0.01 * speedRpm_ / 60.0 : 0;
    iq_ = clamp(targetIq, -command.currentLimitA, command.currentLimitA);
  }
  const double revolutions = speedRpm_ / 60.0 * dt;
  position_ += revolutions * countsPerRevolution(command);
  electricalTurns_ += revolutions * polePairs_;
  electricalTurns_ -= static_cast<double>(static_cast<int64_t>(electricalTurns_));
  if (electricalTurns_ < 0) {
    electricalTurns_ += 1.0;
  }
  const double heating = kAmbientC + 0.2 * (iq_ * iq_ + id_ * id_);
  temperature_ += (heating - temperature_) * (dt / 30.0);
}

void SimulatedDrive::integrateSpeed(const DriveCommand& command, double dt) noexcept {
  double target = command.speedReferenceRpm < command.speedLimitRpm ? command.speedReferenceRpm
                                                                    : command.speedLimitRpm;
  if (command.clockwise) {
    target = -target;
  }
  const bool speedingUp = absolute(target) > absolute(speedRpm_) && target * speedRpm_ >= 0;
  double ramp = speedingUp ? command.accelerationRevPerS2 : command.decelerationRevPerS2;
  if (ramp <= 0) {
    ramp = kDefaultRampRevPerS2;
  }
  if (command.speedReferenceRpm == 0.0) {
    ramp = kFastStopRevPerS2;  // manual lines 1276-1281: 0 bypasses the deceleration
  }
  speedRpm_ = approach(speedRpm_, target, ramp * kRpmPerS2 * dt);
  id_ = command.idReferenceA;
}

bool SimulatedDrive::integratePosition(const DriveCommand& command, double dt) noexcept {
  const double cpr = countsPerRevolution(command);
  const double error = static_cast<double>(command.positionReference) - position_;
  const double accel = kDefaultRampRevPerS2 * cpr;  // counts/s²
  const double vmax = command.speedLimitRpm / 60.0 * cpr;
  double vwanted = squareRoot(2.0 * accel * absolute(error));
  vwanted = vwanted < vmax ? vwanted : vmax;
  vwanted = error < 0 ? -vwanted : vwanted;
  const double v = approach(speedRpm_ / 60.0 * cpr, vwanted, accel * dt);
  speedRpm_ = v / cpr * 60.0;
  id_ = command.idReferenceA;
  if (absolute(error) <= absolute(v * dt) || absolute(error) < 0.5) {
    position_ = static_cast<double>(command.positionReference);  // arrived: stop on the spot
    speedRpm_ = 0;
    iq_ = 0;
    return true;
  }
  return false;
}

void SimulatedDrive::integrateTorque(const DriveCommand& command, double dt) noexcept {
  double reference = command.torqueReferenceA;
  reference = clamp(reference, -command.currentLimitA, command.currentLimitA);
  if (command.clockwise) {
    reference = -reference;
  }
  iq_ += (reference - iq_) * (dt / 0.005 > 1 ? 1 : dt / 0.005);
  const double accel = iq_ * kRevPerS2PerAmp - 0.5 * speedRpm_ / 60.0;
  speedRpm_ = clamp(speedRpm_ + accel * kRpmPerS2 * dt, -30000, 30000);
  id_ = command.idReferenceA;
}

void SimulatedDrive::read(DriveFeedback* feedback) noexcept {
  DriveFeedback out;
  out.speedRpm = speedRpm_;
  out.position = static_cast<int32_t>(clamp(position_, -2147483647.0, 2147483647.0));
  out.iqA = iq_;
  out.idA = id_;
  out.phaseACurrentA = iq_ * sineOfTurns(electricalTurns_);
  out.phaseBCurrentA = iq_ * sineOfTurns(electricalTurns_ - 1.0 / 3.0);
  const double emf = kBusVoltage * speedRpm_ / 30000.0;
  out.phaseAVoltageV = emf * sineOfTurns(electricalTurns_ + 0.25);
  out.phaseBVoltageV = emf * sineOfTurns(electricalTurns_ + 0.25 - 1.0 / 3.0);
  out.busVoltageV = kBusVoltage - 0.01 * absolute(iq_);
  out.motorCurrentA = dcMotor_ ? iq_ : 0;
  out.motorVoltageV = dcMotor_ ? emf : 0;
  out.anglePerUnit = electricalTurns_ < 0.5 ? electricalTurns_ * 2.0 : electricalTurns_ * 2.0 - 2.0;
  out.boardTemperatureC = temperature_;
  out.analogue[0] = kAnalogueInputs[0];
  out.analogue[1] = kAnalogueInputs[1];
  out.faults = faults_;
  *feedback = out;
}

bool SimulatedDrive::identify(double* resistance, double* inductance) noexcept {
  *resistance = 0.35;
  *inductance = 0.0002;
  return true;
}

}  // namespace costa::solo
