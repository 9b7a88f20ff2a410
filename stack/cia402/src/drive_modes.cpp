// The modes of operation of the CiA 402 drive (drive.hpp): their set-points, the axis motion
// each state and mode asks for, and the status word bits they set.
#include "costa/cia402/drive.hpp"

namespace costa::cia402 {
namespace {

/// Powers of ten up to 10^6, for the interpolation period (0x60C2).
constexpr uint32_t kPowersOfTen[] = {1, 10, 100, 1000, 10000, 100000, 1000000};

constexpr bool risen(uint16_t now, uint16_t before, uint16_t bit) noexcept {
  return (now & bit) != 0U && (before & bit) == 0U;
}

}  // namespace

uint32_t Drive::deceleration(Located first) const noexcept {
  for (unsigned object = first; object >= kProfileAccelerationAt; --object) {
    const int64_t found = value(static_cast<Located>(object), -1);
    if (found >= 0) {
      return static_cast<uint32_t>(found);
    }
  }
  return 0;
}

uint32_t Drive::interpolationPeriod() const noexcept {
  if (options_.ipPeriod != 0U) {
    return options_.ipPeriod;
  }
  // 0x60C2: sub-index 1 units of 10^(sub-index 2) s; microseconds for exponents -6..0.
  const auto units = static_cast<uint32_t>(read(object::kInterpolationPeriod, 1, 0));
  const int64_t exponent = read(object::kInterpolationPeriod, 2, -3) + 6;
  return exponent >= 0 && exponent <= 6 ? units * kPowersOfTen[exponent] : 0U;
}

void Drive::complete(const AxisState& axis) noexcept {
  if (moving_ && axis.atRest && axis.position == setPoint_) {
    moving_ = pending_;
    setPoint_ = pending_ ? pendingSetPoint_ : setPoint_;
    pending_ = false;
  }
  if (homingRunning_ && !homingRestart_ &&
      (axis.homing == HomingState::kAttained || axis.homing == HomingState::kError)) {
    homingRunning_ = false;
    homingResult_ = axis.homing;
  }
}

void Drive::startHoming() noexcept {
  homingRunning_ = true;
  homingRestart_ = true;
  homingResult_ = HomingState::kRunning;
}

void Drive::takeSetPoint(uint16_t controlword, const AxisState& axis) noexcept {
  int64_t target = read(object::kTargetPosition, 0, 0);
  if ((controlword & control::kRelative) != 0U) {
    target += setPointTaken_ ? setPoint_ : axis.position;
  }
  // A position counter wraps (CiA 402 positions are 32-bit modulo).
  const auto position = static_cast<int32_t>(static_cast<uint32_t>(target));
  if ((controlword & control::kChangeSetImmediately) != 0U || !moving_) {
    setPoint_ = position;
    moving_ = true;
    pending_ = false;
  } else {
    pendingSetPoint_ = position;
    pending_ = true;
  }
  setPointTaken_ = true;
  acknowledged_ = true;
}

uint16_t Drive::takeEvents(uint16_t controlword, const AxisState& axis) noexcept {
  const bool enabled = state_ == PowerState::kOperationEnabled;
  const bool halted = (controlword & control::kHalt) != 0U || hold_;
  const bool edge = risen(controlword, lastControlword_, control::kNewSetPoint);
  if (mode_ == kProfilePosition && enabled && !halted) {
    const bool targetTrigger = options_.targetWriteStartsMove && targetWritten_ &&
                               (controlword & control::kChangeSetImmediately) != 0U;
    if (edge || targetTrigger) {
      takeSetPoint(controlword, axis);
      if (edge && options_.newSetPointClears) {
        controlword = static_cast<uint16_t>(controlword & ~control::kNewSetPoint);
        store(kControlwordAt, controlword);
      }
    }
  }
  if ((controlword & control::kNewSetPoint) == 0U) {
    acknowledged_ = false;
  }
  if (mode_ == kHoming) {
    const bool byModeWrite = options_.homingOnModeWrite && modeWritten_ &&
                             state_ != PowerState::kFaultReactionActive &&
                             state_ != PowerState::kFault;
    if ((enabled && edge && !halted) || byModeWrite) {
      startHoming();
    } else if (enabled && halted && homingRunning_) {
      homingRunning_ = false;  // homing interrupted
      homingResult_ = HomingState::kIdle;
    }
  }
  targetWritten_ = false;
  modeWritten_ = false;
  return controlword;
}

AxisCommand Drive::modeMotion() const noexcept {
  AxisCommand command;
  command.motion = Motion::kStop;
  command.deceleration = deceleration(kProfileDecelerationAt);
  switch (mode_) {
    case kProfilePosition:
      if (setPointTaken_) {
        command.motion = Motion::kPosition;
        command.position = setPoint_;
        command.velocity = static_cast<int32_t>(value(kProfileVelocityAt, 0));
        command.acceleration = static_cast<uint32_t>(value(kProfileAccelerationAt, 0));
      }
      break;
    case kProfileVelocity:
      command.motion = Motion::kVelocity;
      command.velocity = static_cast<int32_t>(value(kTargetVelocityAt, 0));
      command.acceleration = static_cast<uint32_t>(value(kProfileAccelerationAt, 0));
      break;
    case kHoming:
      if (homingRunning_) {
        command = AxisCommand{};
        command.motion = Motion::kHoming;
        command.homingMethod = static_cast<int8_t>(read(object::kHomingMethod, 0, 0));
      }
      break;
    case kInterpolatedPosition:
      if (ipTaken_) {
        command.motion = Motion::kInterpolate;
        command.position = ipTarget_;
        command.velocity = static_cast<int32_t>(value(kProfileVelocityAt, 0));
        command.period = interpolationPeriod();
      }
      break;
    default: break;
  }
  return command;
}

AxisCommand Drive::motion(uint16_t controlword) const noexcept {
  AxisCommand command;
  switch (state_) {
    case PowerState::kOperationEnabled:
      if (hold_ || (controlword & control::kHalt) != 0U) {
        command.motion = Motion::kStop;
        command.deceleration =
            hold_ || options_.abruptHalt ? 0U : deceleration(kProfileDecelerationAt);
        return command;
      }
      return modeMotion();
    case PowerState::kQuickStopActive:
    case PowerState::kFaultReactionActive:
      command.motion = Motion::kStop;
      command.deceleration = deceleration(kQuickStopDecelerationAt);
      return command;
    default:
      if (homingRunning_) {  // started by a mode write (DriveOptions::homingOnModeWrite)
        command.motion = Motion::kHoming;
        command.homingMethod = static_cast<int8_t>(read(object::kHomingMethod, 0, 0));
      }
      return command;
  }
}

uint16_t Drive::modeStatus(uint16_t controlword, const AxisState& axis) const noexcept {
  const bool enabled = state_ == PowerState::kOperationEnabled;
  const bool halted = enabled && (hold_ || (controlword & control::kHalt) != 0U);
  // Bit 10: at rest, unless the mode has a target of its own that is not reached yet.
  bool reached = axis.atRest;
  uint16_t bits = 0;
  switch (mode_) {
    case kProfilePosition:
      reached = reached && (halted || !moving_);
      bits = acknowledged_ ? status::kModeBit12 : 0U;  // set-point acknowledge
      break;
    case kProfileVelocity:
      if (enabled && !halted) {
        reached = axis.velocity == static_cast<int32_t>(value(kTargetVelocityAt, 0));
      }
      bits = axis.velocity == 0 ? status::kModeBit12 : 0U;  // speed 0
      break;
    case kHoming:
      reached = reached && !homingRunning_;
      bits = homingStatus();
      break;
    case kInterpolatedPosition:
      reached = reached && (halted || !ipTaken_ || axis.position == ipTarget_);
      bits = enabled && (options_.ipWithoutEnableBit || (controlword & control::kNewSetPoint) != 0U)
                 ? status::kModeBit12  // ip mode active
                 : 0U;
      break;
    default: break;
  }
  if ((options_.modeStatusModes & modeBit(mode_)) == 0U) {
    bits = 0;
  }
  return static_cast<uint16_t>((reached ? status::kTargetReached : 0U) | bits);
}

uint16_t Drive::homingStatus() const noexcept {
  switch (homingResult_) {
    case HomingState::kAttained: return status::kModeBit12;
    case HomingState::kError: return status::kModeBit13;
    default: return 0;
  }
}

uint16_t Drive::statusOf(uint16_t controlword, const AxisState& axis) const noexcept {
  const auto standard =
      static_cast<uint16_t>(stateStatusBits(state_) | modeStatus(controlword, axis));
  return axis_.statusword(static_cast<uint16_t>(standard & ~options_.unusedStatusBits), state_);
}

}  // namespace costa::cia402
