#include "costa/cia402/drive.hpp"

#include "costa/od/little_endian.hpp"

namespace costa::cia402 {
namespace {

/// The index of each Drive::Located object, in its order.
constexpr uint16_t kLocatedIndices[] = {
    object::kControlword,           object::kStatusword,          object::kModes,
    object::kModesDisplay,          object::kPositionActual,      object::kVelocityActual,
    object::kProfileVelocity,       object::kProfileAcceleration, object::kProfileDeceleration,
    object::kQuickStopDeceleration, object::kTargetVelocity};

}  // namespace

Drive::LocatedObjects::LocatedObjects(const od::ObjectDictionary& dictionary) noexcept {
  static_assert(sizeof(kLocatedIndices) / sizeof(kLocatedIndices[0]) == kLocatedCount,
                "one index for each located object");
  for (size_t i = 0; i < kLocatedCount; ++i) {
    values[i] = dictionary.scalar(dictionary.find(kLocatedIndices[i], 0));
  }
}

Drive::Drive(Node& node, Axis& axis, const DriveOptions& options) noexcept
    : node_(node),
      axis_(axis),
      options_(options),
      located_(node.dictionary()),
      attached_(node.attachHook(object::kControlword, object::kControlword, *this) &&
                node.attachHook(object::kModes, object::kModes, *this) &&
                node.attachHook(object::kTargetPosition, object::kTargetPosition, *this) &&
                node.addListener(*this)) {}

int64_t Drive::value(Located object, int64_t fallback) const noexcept {
  const od::Scalar& located = located_.values[object];
  return located.valid() ? static_cast<int64_t>(node_.dictionary().readUnsigned(located))
                         : fallback;
}

void Drive::store(Located object, uint64_t value) noexcept {
  node_.dictionary().storeUnsigned(located_.values[object], value);  // none where absent
}

int64_t Drive::read(uint16_t index, uint8_t subIndex, int64_t fallback) const noexcept {
  return static_cast<int64_t>(
      node_.dictionary().readUnsigned(index, subIndex, static_cast<uint64_t>(fallback)));
}

bool Drive::supported(int8_t mode) const noexcept {
  return (static_cast<uint32_t>(read(object::kSupportedModes, 0, 0)) & modeBit(mode)) != 0U;
}

AbortCode Drive::check(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                       const uint8_t* data, size_t length) noexcept {
  const AbortCode checked = dictionary.check(ref, data, length);
  if (checked != AbortCode::kNone || ref.index() != object::kModes) {
    return checked;
  }
  const auto mode = static_cast<int8_t>(data[0]);
  return mode == kNoMode || supported(mode) ? AbortCode::kNone : AbortCode::kInvalidValue;
}

AbortCode Drive::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                       const uint8_t* data, size_t length) noexcept {
  const AbortCode checked = check(dictionary, ref, data, length);
  if (checked != AbortCode::kNone) {
    return checked;
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written != AbortCode::kNone) {
    return written;
  }
  if (ref.index() == object::kModes) {
    modeWritten_ = true;
  } else if (ref.index() == object::kTargetPosition) {
    targetWritten_ = true;
  }
  if (!deferring_) {
    evaluate();
  }
  return AbortCode::kNone;
}

void Drive::onResetApplication() noexcept {
  state_ = PowerState::kNotReadyToSwitchOn;
  lastControlword_ = 0;
  statusword_ = 0;
  mode_ = kNoMode;
  shownMode_ = kNoMode;
  changeMode(kNoMode);
  deferring_ = false;
  targetWritten_ = false;
  modeWritten_ = false;
  hold_ = false;
  commanded_ = AxisCommand{};
  axis_.command(commanded_);  // no torque until the control word asks for it
}

void Drive::onRpdoWriting(uint16_t communicationIndex) noexcept {
  (void)communicationIndex;
  deferring_ = true;
}

void Drive::onRpdoReceived(uint16_t communicationIndex) noexcept {
  (void)communicationIndex;
  deferring_ = false;
  evaluate();
}

void Drive::onSync(uint8_t counter) noexcept {
  (void)counter;
  const auto controlword = static_cast<uint16_t>(value(kControlwordAt, 0));
  if (state_ == PowerState::kOperationEnabled && mode_ == kInterpolatedPosition &&
      (options_.ipWithoutEnableBit || (controlword & control::kNewSetPoint) != 0U)) {
    ipTarget_ = static_cast<int32_t>(
        read(options_.ipSetPointIndex, options_.ipSetPointSubIndex, ipTarget_));
    ipTaken_ = true;
    evaluate();
  }
}

void Drive::hold(bool on) noexcept {
  if (hold_ != on) {
    hold_ = on;
    evaluate();
  }
}

void Drive::enter(PowerState state) noexcept {
  if (state == PowerState::kOperationEnabled) {
    setPointTaken_ = false;
    moving_ = false;
    pending_ = false;
    ipTaken_ = false;
  } else if (state == PowerState::kFaultReactionActive || state == PowerState::kFault) {
    homingRunning_ = false;
  }
  state_ = state;
}

void Drive::changeMode(int8_t mode) noexcept {
  mode_ = mode;
  setPointTaken_ = false;
  moving_ = false;
  pending_ = false;
  acknowledged_ = false;
  homingRunning_ = false;
  homingResult_ = HomingState::kIdle;
  ipTaken_ = false;
}

void Drive::runStateMachine(uint16_t controlword, AxisState* axis) noexcept {
  PowerInputs inputs;
  inputs.faultReset =
      (controlword & control::kFaultReset) != 0U && (lastControlword_ & control::kFaultReset) == 0U;
  if (inputs.faultReset && state_ == PowerState::kFault) {
    axis_.resetFault();
    *axis = axis_.state();
  }
  inputs.fault = axis->fault;
  inputs.stopped = axis->atRest;
  // Automatic transitions follow at once (1 after 0; 12 and 14 when already at rest).
  for (int step = 0; step < 4; ++step) {
    const PowerTransition next = nextPowerState(state_, controlword, inputs, options_.power);
    if (next.number == kNoTransition) {
      break;
    }
    enter(next.state);
    inputs.faultReset = false;
  }
}

void Drive::evaluate() noexcept {
  auto controlword = static_cast<uint16_t>(value(kControlwordAt, 0));
  AxisState axis = axis_.state();
  runStateMachine(controlword, &axis);
  const auto requested = static_cast<int8_t>(value(kModesAt, kNoMode));
  if (requested != mode_ && requested != kNoMode && supported(requested)) {
    changeMode(requested);  // 0: no mode change (CiA 402)
  }
  complete(axis);
  controlword = takeEvents(controlword, axis);
  const AxisCommand next = motion(controlword);
  if (next != commanded_ || homingRestart_) {
    commanded_ = next;
    homingRestart_ = false;
    axis_.command(next);
    axis = axis_.state();
  }
  complete(axis);  // a set-point already reached ends at once
  lastControlword_ = controlword;
  const uint16_t status = statusOf(controlword, axis);
  store(kModesDisplayAt, static_cast<uint64_t>(mode_));
  store(kPositionActualAt, static_cast<uint64_t>(axis.position));
  store(kVelocityActualAt, static_cast<uint64_t>(axis.velocity));
  store(kStatuswordAt, status);
  if (status != statusword_ || mode_ != shownMode_) {
    const bool modeChanged = mode_ != shownMode_;
    const bool statusChanged = status != statusword_;
    statusword_ = status;
    shownMode_ = mode_;
    if (options_.statusChangesAreEvents && statusChanged) {
      node_.markChanged(object::kStatusword, 0);
    }
    if (options_.statusChangesAreEvents && modeChanged) {
      node_.markChanged(object::kModesDisplay, 0);
    }
  }
}

}  // namespace costa::cia402
