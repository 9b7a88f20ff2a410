#include "joint_device.hpp"

#include "device_control.hpp"
#include "mseries_profile.hpp"

namespace costa::mseries {

static_assert(features::kHeartbeatConsumer,
              "the M-series joint stops when 0x1016's heartbeat stops (W7): build with "
              "COSTA_FEATURE_HEARTBEAT_CONSUMER=ON");
static_assert(features::kParameterStorage,
              "the M-series joint saves its parameters with 0x2614 (B13): build with "
              "COSTA_FEATURE_PARAMETER_STORAGE=ON");
static_assert(features::kQuirkProfiles,
              "the M-series joint has its own heartbeat and TPDO behaviour (mseries_profile.hpp): "
              "build with COSTA_FEATURE_QUIRK_PROFILES=ON");

namespace {

constexpr uint16_t kFirstVendorObject = 0x2600;
constexpr uint16_t kLastVendorObject = 0x261D;
constexpr uint16_t kHomingMethod = 0x6098;
/// 0x2619 values with a power-on function (line 377).
constexpr uint16_t kReturnToZero = 6;
constexpr uint16_t kCanOpenControl = 9;
constexpr uint16_t kFirstAngle = 30;
/// 0x6079 counts per volt (line 369).
constexpr uint32_t kCountsPerVolt = 327;

}  // namespace

JointDevice::JointDevice(MSeriesNode& node, JointBackend& joint, uint8_t powerOnNodeId,
                         bool nodeIdGiven) noexcept
    : node_(node),
      values_(node.values()),
      joint_(joint),
      alarms_(node),
      drive_(node, *this, driveOptions()),
      powerOnNodeId_(powerOnNodeId),
      nodeIdGiven_(nodeIdGiven),
      attached_(node.attachHook(kFirstVendorObject, kLastVendorObject, *this) &&
                node.attachHook(kHomingMethod, kHomingMethod, *this) && node.addListener(*this)) {}

uint32_t JointDevice::homingSpeed() const noexcept {
  // The ones digit of the acceleration, 0..9: 100..1000 r/min (line 277, B10).
  return (values_.x6083_profile_acceleration % 10U + 1U) * 100U;
}

void JointDevice::apply() noexcept {
  JointCommand command;
  command.axis = driveCommand_;
  if (command.axis.motion == cia402::Motion::kHoming) {
    homingByCan_ = true;
    command.homingSpeed = homingSpeed();
  } else if (command.axis.motion == cia402::Motion::kFree && pulseControl_) {
    command.axis = ownMotion_;
  }
  if (values_.x2601_drive_output_enabled == 0U) {
    command.axis = cia402::AxisCommand{};  // drive output forbidden: no torque (line 351)
  }
  joint_.drive(command);
}

void JointDevice::command(const cia402::AxisCommand& command) noexcept {
  driveCommand_ = command;
  if (command.motion != cia402::Motion::kFree) {
    ownMotion_ = cia402::AxisCommand{};  // CANopen has the motor now
  }
  apply();
}

cia402::AxisState JointDevice::state() const noexcept {
  const JointFeedback feedback = joint_.read();
  cia402::AxisState state;
  state.position = feedback.position;
  state.velocity = feedback.velocity;
  state.atRest = feedback.atRest;
  state.homing = feedback.homing;
  state.fault = alarms_.fault();
  return state;
}

void JointDevice::resetFault() noexcept {
  alarms_.resetFaults(supplyVolts_ > kOverVoltage);
}

uint16_t JointDevice::statusword(uint16_t statusword, cia402::PowerState state) noexcept {
  if ((values_.x6040_controlword & cia402::control::kSwitchOn) != 0U) {
    pulseControl_ = false;  // "after setting 1, the external impulse control is invalid" (395)
  }
  if (!pulseControl_ || (state != cia402::PowerState::kSwitchOnDisabled &&
                         state != cia402::PowerState::kNotReadyToSwitchOn)) {
    return statusword;
  }
  // Under pulse control (B7): bit 2 (the pulses operate the motor), bit 4 once CANopen started
  // homing, bits 10, 12, 13 as the drive has them: 0x0404, 0x0014, 0x1414 (lines 707, 708, 718).
  constexpr uint16_t kKept =
      cia402::status::kTargetReached | cia402::status::kModeBit12 | cia402::status::kModeBit13;
  return static_cast<uint16_t>(cia402::status::kOperationEnabled | (statusword & kKept) |
                               (homingByCan_ ? cia402::status::kVoltageEnabled : 0U));
}

void JointDevice::publish(const JointFeedback& feedback) noexcept {
  gen::mseries::Values& v = values_;
  v.x6063_position_actual_internal_value = feedback.position;
  v.x6078_current_actual_value = static_cast<int16_t>(feedback.current);
  v.x2613_pwm_of_system_output = feedback.pwm;
  v.x6079_dc_link_circuit_voltage = static_cast<uint16_t>(supplyVolts_ * kCountsPerVolt);
  v.x60fd_digital_inputs =
      static_cast<uint16_t>((feedback.dir ? 0x05U : 0U) | (feedback.pu ? 0x02U : 0U));
  v.x260e_alarm_code = alarms_.code();
}

Microseconds JointDevice::process(Microseconds now) noexcept {
  if (joint_.moving()) {
    while (now - simulated_ >= kStep) {  // elapsed time, right across the wrap of the clock
      joint_.step(kStep);
      simulated_ += kStep;
    }
  } else {
    simulated_ = now;
  }
  // The drive reads none of the published objects: publishing once, after it, is enough.
  drive_.update();
  publish(joint_.read());
  return joint_.moving() ? at(simulated_, kStep) : kNever;
}

bool JointDevice::consistent(char* why, size_t whySize) const noexcept {
  using cia402::PowerState;
  const uint16_t status = values_.x6041_statusword;
  const PowerState state = drive_.state();
  if ((status & driveOptions().unusedStatusBits) != 0U) {
    return refuseControl("the status word sets bit 6, 7, 9 or 11", why, whySize);
  }
  if ((status & (cia402::status::kModeBit12 | cia402::status::kModeBit13)) != 0U &&
      drive_.mode() != cia402::kHoming) {
    return refuseControl("the status word sets bit 12 or 13 outside homing", why, whySize);
  }
  // Bits 0, 1, 2, 3 and 5 code the state (bit 4, voltage, and bit 6, unused, do not).
  constexpr uint16_t kStateBits = 0x002FU;
  const bool pulseWord = pulseControl_ && (state == PowerState::kSwitchOnDisabled ||
                                           state == PowerState::kNotReadyToSwitchOn);
  const uint16_t expected =
      pulseWord ? cia402::status::kOperationEnabled
                : static_cast<uint16_t>(cia402::stateStatusBits(state) & kStateBits);
  if ((status & kStateBits) != expected) {
    return refuseControl("the status word does not show the drive's state", why, whySize);
  }
  return true;
}

bool JointDevice::raiseAlarm(uint8_t alarm) noexcept {
  if (alarm != kAlarmBattery && alarm != kAlarmLockedRotor && alarm != kAlarmStall) {
    return false;
  }
  return alarms_.raise(alarm);
}

void JointDevice::setSupplyVolts(uint32_t volts) noexcept {
  supplyVolts_ = volts;
  if (volts > kOverVoltage) {
    alarms_.raise(kAlarmOverVoltage);
  }
}

void JointDevice::onResetApplication() noexcept {
  // 0x2615 holds its stored value (or its default); a command-line node-id overrides it.
  if (nodeIdGiven_) {
    values_.x2615_device_location = powerOnNodeId_;
  }
  const uint16_t address = values_.x2615_device_location;
  node_.setPendingNodeId(static_cast<uint8_t>(address >= 1U && address <= 127U ? address : 1U));
  zeroStarted_ = false;
  homingByCan_ = false;
  const uint16_t function = values_.x2619_mode_selection;
  pulseControl_ = function != kCanOpenControl;
  ownMotion_ = cia402::AxisCommand{};
  if (function == kReturnToZero || function >= kFirstAngle) {
    ownMotion_.motion = cia402::Motion::kPosition;
    ownMotion_.position = function == kReturnToZero ? 0 : static_cast<int32_t>(function);
    ownMotion_.velocity = static_cast<int32_t>(homingSpeed());
    ownMotion_.acceleration = values_.x6083_profile_acceleration;
    ownMotion_.deceleration = values_.x6083_profile_acceleration;
  }
  simulated_ = node_.now();
  apply();
}

void JointDevice::onResetCommunication() noexcept {
  // The consumer starts over (CiA 301: from the producer's first heartbeat): the master it had
  // found silent is no longer waited for, and the joint resumes (errata W7).
  communicationRestored();
}

void JointDevice::onHeartbeatTimeout(uint8_t nodeId) noexcept {
  (void)nodeId;
  alarms_.raise(kAlarmCommunication);  // "Motor stops" (line 131)
  drive_.hold(true);
}

void JointDevice::onHeartbeatResumed(uint8_t nodeId) noexcept {
  (void)nodeId;
  communicationRestored();  // "Resend the heartbeat packet to recover" (131, 764)
}

void JointDevice::onHeartbeatWithdrawn(uint8_t nodeId) noexcept {
  (void)nodeId;
  communicationRestored();  // the entry no longer waits for that master (errata W7)
}

void JointDevice::communicationRestored() noexcept {
  alarms_.clear(kAlarmCommunication);
  drive_.hold(false);
}

}  // namespace costa::mseries
