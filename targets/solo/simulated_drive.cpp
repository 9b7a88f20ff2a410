#include "simulated_drive.hpp"

#include "costa/od/bytes.hpp"

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

/// The same command, field by field (a command has no NaN: every field comes from an integer).
bool sameCommand(const DriveCommand& a, const DriveCommand& b) {
  return a.outputEnabled == b.outputEnabled && a.commanding == b.commanding &&
         a.control == b.control && a.feedback == b.feedback && a.motor == b.motor &&
         a.speedReferenceRpm == b.speedReferenceRpm && a.clockwise == b.clockwise &&
         a.accelerationRevPerS2 == b.accelerationRevPerS2 &&
         a.decelerationRevPerS2 == b.decelerationRevPerS2 && a.speedLimitRpm == b.speedLimitRpm &&
         a.positionReference == b.positionReference && a.torqueReferenceA == b.torqueReferenceA &&
         a.idReferenceA == b.idReferenceA && a.currentLimitA == b.currentLimitA &&
         a.poles == b.poles && a.encoderLines == b.encoderLines;
}

}  // namespace

double SimulatedDrive::countsPerRevolution(const DriveCommand& command) noexcept {
  if (command.feedback == FeedbackMode::kHall) {
    return 3.0 * static_cast<double>(command.poles);
  }
  return 4.0 * static_cast<double>(command.encoderLines);
}

void SimulatedDrive::step(const DriveCommand& command, Microseconds elapsed) noexcept {
  const State before = s_;
  s_.polePairs = static_cast<double>(command.poles) / 2.0;
  s_.dcMotor = command.motor == MotorType::kDcBrushed ? 1U : 0U;
  if (command.currentLimitA <= 0.0) {
    s_.faults |= 1U;  // over-current protection trips when the limit is 0 (manual line 885)
  } else {
    s_.faults &= ~1U;
  }
  constexpr Microseconds kStep = 1000;  // integrate in 1 ms steps
  while (elapsed > 0) {
    const Microseconds slice = elapsed < kStep ? elapsed : kStep;
    integrate(command, static_cast<double>(slice) / 1e6);
    elapsed -= slice;
  }
  // Bit for bit on purpose, so that -0.0 is not taken for 0.0, nor a NaN for anything; State
  // has no padding (static_assert in the header).
  // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison,cert-exp42-c,cert-flp37-c)
  resting_ = sameBytes(&before, &s_, sizeof(State));
  lastCommand_ = command;
}

bool SimulatedDrive::restsUnder(const DriveCommand& command) const noexcept {
  return resting_ && sameCommand(command, lastCommand_);
}

void SimulatedDrive::integrate(const DriveCommand& command, double dt) noexcept {
  const bool driving =
      command.outputEnabled && s_.faults == 0U && command.commanding == CommandingMode::kDigital;
  const double before = s_.speedRpm;
  if (!driving) {
    s_.speedRpm = approach(s_.speedRpm, 0, kCoastRevPerS2 * kRpmPerS2 * dt);
    s_.id = 0;
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
    const double accelRevPerS2 = (s_.speedRpm - before) / 60.0 / dt;
    const double targetIq =
        driving ? accelRevPerS2 / kRevPerS2PerAmp + 0.01 * s_.speedRpm / 60.0 : 0;
    s_.iq = clamp(targetIq, -command.currentLimitA, command.currentLimitA);
  }
  const double revolutions = s_.speedRpm / 60.0 * dt;
  s_.position += revolutions * countsPerRevolution(command);
  s_.electricalTurns += revolutions * s_.polePairs;
  s_.electricalTurns -= static_cast<double>(static_cast<int64_t>(s_.electricalTurns));
  if (s_.electricalTurns < 0) {
    s_.electricalTurns += 1.0;
  }
  const double heating = kAmbientC + 0.2 * (s_.iq * s_.iq + s_.id * s_.id);
  s_.temperature += (heating - s_.temperature) * (dt / 30.0);
}

void SimulatedDrive::integrateSpeed(const DriveCommand& command, double dt) noexcept {
  double target = command.speedReferenceRpm < command.speedLimitRpm ? command.speedReferenceRpm
                                                                    : command.speedLimitRpm;
  if (command.clockwise) {
    target = -target;
  }
  const bool speedingUp = absolute(target) > absolute(s_.speedRpm) && target * s_.speedRpm >= 0;
  double ramp = speedingUp ? command.accelerationRevPerS2 : command.decelerationRevPerS2;
  if (ramp <= 0) {
    ramp = kDefaultRampRevPerS2;
  }
  if (command.speedReferenceRpm == 0.0) {
    ramp = kFastStopRevPerS2;  // manual lines 1276-1281: 0 bypasses the deceleration
  }
  s_.speedRpm = approach(s_.speedRpm, target, ramp * kRpmPerS2 * dt);
  s_.id = command.idReferenceA;
}

bool SimulatedDrive::integratePosition(const DriveCommand& command, double dt) noexcept {
  const double cpr = countsPerRevolution(command);
  const double error = static_cast<double>(command.positionReference) - s_.position;
  const double accel = kDefaultRampRevPerS2 * cpr;  // counts/s²
  const double vmax = command.speedLimitRpm / 60.0 * cpr;
  double vwanted = squareRoot(2.0 * accel * absolute(error));
  vwanted = vwanted < vmax ? vwanted : vmax;
  vwanted = error < 0 ? -vwanted : vwanted;
  const double v = approach(s_.speedRpm / 60.0 * cpr, vwanted, accel * dt);
  s_.speedRpm = v / cpr * 60.0;
  s_.id = command.idReferenceA;
  if (absolute(error) <= absolute(v * dt) || absolute(error) < 0.5) {
    s_.position = static_cast<double>(command.positionReference);  // arrived: stop on the spot
    s_.speedRpm = 0;
    s_.iq = 0;
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
  s_.iq += (reference - s_.iq) * (dt / 0.005 > 1 ? 1 : dt / 0.005);
  const double accel = s_.iq * kRevPerS2PerAmp - 0.5 * s_.speedRpm / 60.0;
  s_.speedRpm = clamp(s_.speedRpm + accel * kRpmPerS2 * dt, -30000, 30000);
  s_.id = command.idReferenceA;
}

void SimulatedDrive::read(DriveFeedback* feedback) noexcept {
  DriveFeedback out;
  out.speedRpm = s_.speedRpm;
  out.position = static_cast<int32_t>(clamp(s_.position, -2147483647.0, 2147483647.0));
  out.iqA = s_.iq;
  out.idA = s_.id;
  out.phaseACurrentA = s_.iq * sineOfTurns(s_.electricalTurns);
  out.phaseBCurrentA = s_.iq * sineOfTurns(s_.electricalTurns - 1.0 / 3.0);
  const double emf = kBusVoltage * s_.speedRpm / 30000.0;
  out.phaseAVoltageV = emf * sineOfTurns(s_.electricalTurns + 0.25);
  out.phaseBVoltageV = emf * sineOfTurns(s_.electricalTurns + 0.25 - 1.0 / 3.0);
  out.busVoltageV = kBusVoltage - 0.01 * absolute(s_.iq);
  out.motorCurrentA = s_.dcMotor != 0U ? s_.iq : 0;
  out.motorVoltageV = s_.dcMotor != 0U ? emf : 0;
  out.anglePerUnit =
      s_.electricalTurns < 0.5 ? s_.electricalTurns * 2.0 : s_.electricalTurns * 2.0 - 2.0;
  out.boardTemperatureC = s_.temperature;
  out.analogue[0] = kAnalogueInputs[0];
  out.analogue[1] = kAnalogueInputs[1];
  out.faults = s_.faults;
  *feedback = out;
}

bool SimulatedDrive::identify(double* resistance, double* inductance) noexcept {
  *resistance = 0.35;
  *inductance = 0.0002;
  return true;
}

}  // namespace costa::solo
