#include "solo_device.hpp"

#include "costa/od/little_endian.hpp"
#include "sfxt.hpp"

namespace costa::solo {
namespace {

constexpr uint16_t kFirstObject = 0x3001;
constexpr uint16_t kLastObject = 0x304C;
constexpr Microseconds kIdentificationTime = 1000000;

int32_t roundToInt32(double value) {
  if (value >= 2147483647.0) {
    return INT32_MAX;
  }
  if (value <= -2147483647.0) {
    return -INT32_MAX;
  }
  return static_cast<int32_t>(value < 0 ? value - 0.5 : value + 0.5);
}

}  // namespace

SoloDevice::SoloDevice(SoloNode& node, DriveBackend& drive, uint8_t powerOnNodeId,
                       bool nodeIdGiven) noexcept
    : node_(node),
      values_(node.values()),
      drive_(drive),
      errors_(node, values_.x3020_device_error_register),
      powerOnNodeId_(powerOnNodeId),
      nodeIdGiven_(nodeIdGiven),
      attached_(node.attachHook(kFirstObject, kLastObject, *this) && node.addListener(*this)) {}

uint32_t SoloDevice::readU32(uint16_t index) const noexcept {
  return node_.dictionary().readUnsigned32(index, 0, 0);
}

void SoloDevice::storeSfxt(uint16_t index, double value) noexcept {
  node_.dictionary().storeUnsigned(index, 0, static_cast<uint32_t>(sfxtFromDouble(value)));
}

// The drive's inputs and outputs are read and written every step: through the generated value
// block, as members, not looked up by index.
DriveCommand SoloDevice::command() const noexcept {
  const gen::solo::Values& v = values_;
  DriveCommand c;
  c.outputEnabled = v.x3008_drive_disable_enable == 1U && errors_.value() == 0U;
  c.commanding = static_cast<CommandingMode>(v.x3002_commanding_mode);
  c.control = static_cast<ControlMode>(v.x3016_control_mode_type);
  c.feedback = static_cast<FeedbackMode>(v.x3013_feedback_control_mode);
  c.motor = static_cast<MotorType>(v.x3015_motor_type);
  c.speedReferenceRpm = static_cast<double>(v.x3005_speed_reference);
  c.clockwise = v.x300c_motor_s_direction_of_rotation == 1U;
  c.accelerationRevPerS2 = sfxtToDouble(v.x302a_speed_acceleration_value);
  c.decelerationRevPerS2 = sfxtToDouble(v.x302b_speed_deceleration_value);
  c.speedLimitRpm = static_cast<double>(v.x3011_speed_limit);
  c.positionReference = v.x301b_position_reference;
  c.torqueReferenceA = sfxtToDouble(v.x3004_torque_reference_iq_im);
  c.idReferenceA = sfxtToDouble(v.x301a_magnetizing_field_weakening_current_reference_id);
  c.currentLimitA = sfxtToDouble(v.x3003_current_limit);
  c.poles = v.x300f_motor_s_number_of_poles;
  c.encoderLines = v.x3010_incremental_encoder_s_lines;
  return c;
}

void SoloDevice::publish(const DriveFeedback& feedback) noexcept {
  gen::solo::Values& v = values_;
  v.x3036_speed_feedback = roundToInt32(feedback.speedRpm);
  v.x3037_position_feedback_incremental_encoder_and_hall_sensors = feedback.position;
  v.x3034_quadrature_current_iq = sfxtFromDouble(feedback.iqA);
  v.x3035_direct_current_magnetizing_current_id = sfxtFromDouble(feedback.idA);
  v.x302f_phase_a_current = sfxtFromDouble(feedback.phaseACurrentA);
  v.x3030_phase_b_current = sfxtFromDouble(feedback.phaseBCurrentA);
  v.x302d_phase_a_voltage = sfxtFromDouble(feedback.phaseAVoltageV);
  v.x302e_phase_b_voltage = sfxtFromDouble(feedback.phaseBVoltageV);
  v.x3031_bus_voltage_input_supply_battery = sfxtFromDouble(feedback.busVoltageV);
  v.x3032_dc_motor_current_im = sfxtFromDouble(feedback.motorCurrentA);
  v.x3033_dc_motor_voltage_vm = sfxtFromDouble(feedback.motorVoltageV);
  v.x3038_motor_s_angle = sfxtFromDouble(feedback.anglePerUnit);
  v.x3039_board_temperature = sfxtFromDouble(feedback.boardTemperatureC);
  v.x3049_digital_inputs_register = feedback.digitalInputs;
  publishedFaults_ = feedback.faults;
  if ((feedback.faults & ~errors_.value()) != 0U) {
    errors_.set(feedback.faults);  // a new fault event (also after the host cleared it)
  }
}

Microseconds SoloDevice::process(Microseconds now) noexcept {
  if (now - simulated_ >= kStep) {  // elapsed time, right across the wrap of the clock
    const DriveCommand c = command();
    if (resting_) {
      // The steps since the last call changed nothing and published nothing new: they were
      // due before whatever changed since (process() follows every frame), and are skipped.
      simulated_ += (now - simulated_) / kStep * kStep;
      resting_ = stillResting(c);
    } else {
      while (now - simulated_ >= kStep) {
        drive_.step(c, kStep);
        simulated_ += kStep;
      }
      DriveFeedback feedback;
      drive_.read(&feedback);
      publish(feedback);
      resting_ = stillResting(c);
    }
  }
  if (reached(now, identifyAt_)) {
    identifyAt_ = kNever;
    double resistance = 0;
    double inductance = 0;
    if (drive_.identify(&resistance, &inductance)) {
      storeSfxt(0x300D, resistance);
      storeSfxt(0x300E, inductance);
    }
  }
  return nextDeadline();
}

bool SoloDevice::stillResting(const DriveCommand& command) const noexcept {
  // A fault the register no longer shows (the host cleared it) comes back at the next step.
  return drive_.restsUnder(command) && (publishedFaults_ & ~errors_.value()) == 0U;
}

Microseconds SoloDevice::nextDeadline() noexcept {
  if (resting_ && !stillResting(command())) {
    resting_ = false;  // changed since process(): the next step takes the change
  }
  // At rest, a step now and then all the same, so that the time since the last step never
  // wraps the 32-bit clock.
  return earliest(at(simulated_, resting_ ? kLongestRest : kStep), identifyAt_);
}

AbortCode SoloDevice::prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                  const ReadRequest& request) noexcept {
  if (ref.index() == 0x304A) {
    const uint32_t channel = loadU32(request.requestData);
    if (channel > 1U) {
      return AbortCode::kInvalidValue;  // only CH0 (S/T) and CH1 (P/F) exist
    }
    DriveFeedback feedback;
    drive_.read(&feedback);
    dictionary.storeUnsigned(ref, feedback.analogue[channel]);
  }
  return AbortCode::kNone;
}

AbortCode SoloDevice::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                            const uint8_t* data, size_t length) noexcept {
  if (ref.index() == 0x3009) {
    // Written in kHz (8..80), held and read in Hz.
    if (length != 4U) {
      return length > 4U ? AbortCode::kLengthTooHigh : AbortCode::kLengthTooLow;
    }
    const uint32_t kilohertz = loadU32(data);
    if (kilohertz < 8U || kilohertz > 80U) {
      return AbortCode::kInvalidValue;
    }
    dictionary.storeUnsigned(ref, uint64_t{kilohertz} * 1000U);
    return AbortCode::kNone;
  }
  const AbortCode checked = dictionary.check(ref, data, length);
  if (checked != AbortCode::kNone) {
    return checked;
  }
  const uint32_t value = loadU32(data);
  switch (ref.index()) {
    case 0x3001:
      nodeIdGiven_ = false;  // the new address is kept (M) and used from the next reset on
      node_.setPendingNodeId(static_cast<uint8_t>(value));
      break;
    case 0x3007:
      if (value == 1U) {
        identifyAt_ = at(node_.now(), kIdentificationTime);
      }
      break;
    case 0x3014:
      if (value == 1U && factoryReset_ != nullptr && !factoryReset_(factoryResetContext_)) {
        return AbortCode::kCannotStore;
      }
      break;
    case 0x301F:
      if (value == 1U) {
        drive_.home();
        dictionary.storeUnsigned(0x3037, 0, 0);
      }
      break;
    case 0x3020: errors_.assign(value); return AbortCode::kNone;
    default: break;
  }
  return dictionary.write(ref, data, length);
}

void SoloDevice::onResetApplication() noexcept {
  // 0x3001 now holds its stored value (or its default); a command-line address overrides it.
  if (nodeIdGiven_) {
    node_.dictionary().storeUnsigned(0x3001, 0, powerOnNodeId_);
  }
  const uint32_t address = readU32(0x3001);
  node_.setPendingNodeId(static_cast<uint8_t>(address == 0U ? 1U : address));
  errors_.assign(0);
  simulated_ = node_.now();
  resting_ = false;  // the defaults just restored are published at the next step
  identifyAt_ = kNever;
}

void SoloDevice::onLifeGuardingExpired() noexcept {
  errors_.set(SoloErrorRegister::kCommunicationLost);
}

}  // namespace costa::solo
