#include "simulated_joint.hpp"

namespace costa::mseries {
namespace {

using cia402::HomingState;
using cia402::Motion;

constexpr unsigned kFraction = 16;  ///< position and velocity carry 16 fractional bits
constexpr int64_t kOneCount = int64_t{1} << kFraction;

/// A count in the fixed point of position_ (a product: a negative count may not be shifted).
constexpr int64_t fixed(int32_t counts) noexcept {
  return int64_t{counts} * kOneCount;
}
/// (counts << 16) per ms of one r/min: 32768 * 65536 / 60000.
constexpr int64_t kRpmScale = int64_t{1} << 31;
constexpr int64_t kRpmDivisor = 60000;

constexpr int64_t fromRpm(int64_t rpm) noexcept {
  return rpm * kRpmScale / kRpmDivisor;
}
/// Per ms per ms of one (r/min)/s.
constexpr int64_t fromRpmPerSecond(int64_t rate) noexcept {
  return rate * kRpmScale / (kRpmDivisor * 1000);
}

int32_t toRpm(int64_t velocity) noexcept {
  const int64_t scaled = velocity * kRpmDivisor;
  const int64_t half = kRpmScale / 2;
  return static_cast<int32_t>(scaled >= 0 ? (scaled + half) / kRpmScale
                                          : -((-scaled + half) / kRpmScale));
}

int64_t magnitude(int64_t value) noexcept {
  return value < 0 ? -value : value;
}

/// floor(sqrt(value)).
int64_t squareRoot(int64_t value) noexcept {
  auto rest = static_cast<uint64_t>(value);
  uint64_t root = 0;
  uint64_t bit = uint64_t{1} << 62U;
  while (bit > rest) {
    bit >>= 2U;
  }
  while (bit != 0U) {
    if (rest >= root + bit) {
      rest -= root + bit;
      root = (root >> 1U) + bit;
    } else {
      root >>= 1U;
    }
    bit >>= 2U;
  }
  return static_cast<int64_t>(root);
}

/// The ramp of `rate` (r/min)/s per step; 0 means none.
int64_t rampOf(uint32_t rate) noexcept {
  return rate == 0U || rate >= SimulatedJoint::kNoRampFrom ? 0 : fromRpmPerSecond(rate);
}

}  // namespace

void SimulatedJoint::drive(const JointCommand& command) noexcept {
  command_ = command;
  if (command.axis.motion == Motion::kHoming) {
    homing_ = HomingState::kRunning;
    homingEnded();  // an active input, or a method without a search, ends it at once
  }
  if (command.axis.motion == Motion::kInterpolate) {
    const int64_t distance = magnitude(fixed(command.axis.position) - position_);
    const int64_t steps = command.axis.period / kStep == 0U ? 1 : command.axis.period / kStep;
    ipSpeed_ = (distance + steps - 1) / steps;
    const int64_t limit = fromRpm(command.axis.velocity);
    if (limit > 0 && ipSpeed_ > limit) {
      ipSpeed_ = limit;
    }
  }
  if (command.axis.motion == Motion::kFree ||
      (command.axis.motion == Motion::kStop && rampOf(command.axis.deceleration) == 0)) {
    velocity_ = 0;  // no torque, or an abrupt stop: at rest at once
  }
  measure();
}

void SimulatedJoint::setPosition(int32_t position) noexcept {
  position_ = fixed(position);
  measure();
}

void SimulatedJoint::step(Microseconds elapsed) noexcept {
  elapsed_ += elapsed;
  if (elapsed_ < kStep) {
    return;
  }
  do {
    elapsed_ -= kStep;
    stepOnce();
  } while (elapsed_ >= kStep);
  measure();
}

void SimulatedJoint::stepOnce() noexcept {
  const cia402::AxisCommand& c = command_.axis;
  switch (c.motion) {
    case Motion::kFree: velocity_ = 0; break;
    case Motion::kStop: {
      const int64_t ramp = rampOf(c.deceleration);
      if (ramp == 0 || magnitude(velocity_) <= ramp) {
        velocity_ = 0;
      } else {
        velocity_ += velocity_ > 0 ? -ramp : ramp;
      }
      position_ += velocity_;
      break;
    }
    case Motion::kPosition: stepPosition(fixed(c.position), fromRpm(c.velocity)); break;
    case Motion::kVelocity: stepVelocity(fromRpm(c.velocity)); break;
    case Motion::kHoming: stepHoming(); break;
    case Motion::kInterpolate: {
      const int64_t target = fixed(c.position);
      const int64_t distance = target - position_;
      if (magnitude(distance) <= ipSpeed_) {
        position_ = target;
        velocity_ = 0;
      } else {
        velocity_ = distance > 0 ? ipSpeed_ : -ipSpeed_;
        position_ += velocity_;
      }
      break;
    }
  }
}

void SimulatedJoint::stepPosition(int64_t target, int64_t limit) noexcept {
  const int64_t distance = target - position_;
  if (distance == 0 && velocity_ == 0) {
    return;
  }
  const int64_t direction = distance >= 0 ? 1 : -1;
  const int64_t toward = velocity_ * direction;  // speed toward the target (< 0: away)
  const int64_t ramp = rampOf(command_.axis.acceleration);
  const int64_t brake = rampOf(command_.axis.deceleration);
  int64_t speed = ramp == 0 ? limit : toward + ramp;
  if (speed > limit) {
    speed = limit;
  }
  // The speed from which braking stops on the target (none to compute when far away). Moving
  // away from it (speed < 0), the ramp slows the motion down first.
  constexpr int64_t kFar = int64_t{1} << 40;
  if (brake != 0 && magnitude(distance) < kFar) {
    const int64_t stoppable = squareRoot(2 * brake * magnitude(distance));
    if (speed > stoppable) {
      speed = toward - brake > stoppable ? toward - brake : stoppable;
    }
  }
  if (speed >= magnitude(distance)) {
    position_ = target;
    velocity_ = 0;
    return;
  }
  velocity_ = speed * direction;
  position_ += velocity_;
}

void SimulatedJoint::stepVelocity(int64_t target) noexcept {
  // Away from rest with the acceleration, toward it with the deceleration.
  const bool speedingUp =
      magnitude(target) > magnitude(velocity_) && (target >= 0) == (velocity_ >= 0);
  const int64_t ramp = rampOf(speedingUp ? command_.axis.acceleration : command_.axis.deceleration);
  if (ramp == 0 || magnitude(target - velocity_) <= ramp) {
    velocity_ = target;
  } else {
    velocity_ += target > velocity_ ? ramp : -ramp;
  }
  position_ += velocity_;
}

bool SimulatedJoint::homingInputActive() const noexcept {
  switch (command_.axis.homingMethod) {
    case 17:
    case 19:
    case 21: return dir_;
    case 18: return pu_;
    default: return false;
  }
}

void SimulatedJoint::setInputs(bool dir, bool pu) noexcept {
  dir_ = dir;
  pu_ = pu;
  if (command_.axis.motion == Motion::kHoming && homing_ == HomingState::kRunning) {
    homeIfActive();
  }
  measure();
}

bool SimulatedJoint::homeIfActive() noexcept {
  if (!homingInputActive()) {
    return false;
  }
  position_ = 0;
  velocity_ = 0;
  homing_ = HomingState::kAttained;
  return true;
}

bool SimulatedJoint::homingEnded() noexcept {
  if (homing_ != HomingState::kRunning) {
    velocity_ = 0;
    return true;
  }
  const int8_t method = command_.axis.homingMethod;
  if (method != 17 && method != 18 && method != 19 && method != 21) {
    homing_ = HomingState::kError;
    velocity_ = 0;
    return true;
  }
  return homeIfActive();
}

void SimulatedJoint::stepHoming() noexcept {
  if (homingEnded()) {
    return;
  }
  const int8_t method = command_.axis.homingMethod;
  const int64_t speed = fromRpm(command_.homingSpeed);
  velocity_ = method == 18 || method == 19 ? speed : -speed;
  position_ += velocity_;
}

bool SimulatedJoint::moving() const noexcept {
  if (velocity_ != 0) {
    return true;
  }
  const cia402::AxisCommand& c = command_.axis;
  switch (c.motion) {
    case Motion::kPosition:  // a move at velocity 0 cannot go on: at rest where it is
      return position_ != fixed(c.position) && c.velocity != 0;
    case Motion::kInterpolate: return position_ != fixed(c.position);
    case Motion::kVelocity: return c.velocity != 0;
    case Motion::kHoming: return homing_ == HomingState::kRunning;
    default: return false;
  }
}

void SimulatedJoint::measure() noexcept {
  JointFeedback& feedback = reading_;
  feedback.position =
      static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(position_ >> kFraction)));
  feedback.velocity = toRpm(velocity_);
  feedback.atRest = !moving();
  feedback.homing = homing_;
  const int64_t rpm = magnitude(feedback.velocity);
  feedback.current = static_cast<uint16_t>(100 + (rpm > 3000 ? 3000 : rpm));
  feedback.pwm = static_cast<int16_t>(int64_t{feedback.velocity} * 32767 / 3000);
  feedback.dir = dir_;
  feedback.pu = pu_;
}

}  // namespace costa::mseries
