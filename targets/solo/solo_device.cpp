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

SoloDevice::SoloDevice(Node& node, DriveBackend& drive, uint8_t powerOnNodeId,
                       bool nodeIdGiven) noexcept
    : node_(node),
      drive_(drive),
      errors_(node),
      powerOnNodeId_(powerOnNodeId),
      nodeIdGiven_(nodeIdGiven),
      attached_(node.attachHook(kFirstObject, kLastObject, *this) && node.addListener(*this)) {}

uint32_t SoloDevice::readU32(uint16_t index) const noexcept {
  return static_cast<uint32_t>(node_.dictionary().readUnsigned(index, 0, 0));
}

double SoloDevice::readSfxt(uint16_t index) const noexcept {
  return sfxtToDouble(
      static_cast<int32_t>(node_.dictionary().readSigned(node_.dictionary().find(index, 0))));
}

void SoloDevice::storeSfxt(uint16_t index, double value) noexcept {
  node_.dictionary().storeUnsigned(index, 0, static_cast<uint32_t>(sfxtFromDouble(value)));
}

DriveCommand SoloDevice::command() const noexcept {
  DriveCommand c;
  c.outputEnabled = readU32(0x3008) == 1U && errors_.value() == 0U;
  c.commanding = static_cast<CommandingMode>(readU32(0x3002));
  c.control = static_cast<ControlMode>(readU32(0x3016));
  c.feedback = static_cast<FeedbackMode>(readU32(0x3013));
  c.motor = static_cast<MotorType>(readU32(0x3015));
  c.speedReferenceRpm = static_cast<double>(readU32(0x3005));
  c.clockwise = readU32(0x300C) == 1U;
  c.accelerationRevPerS2 = readSfxt(0x302A);
  c.decelerationRevPerS2 = readSfxt(0x302B);
  c.speedLimitRpm = static_cast<double>(readU32(0x3011));
  c.positionReference = static_cast<int32_t>(node_.dictionary().readUnsigned(0x301B, 0, 0));
  c.torqueReferenceA = readSfxt(0x3004);
  c.idReferenceA = readSfxt(0x301A);
  c.currentLimitA = readSfxt(0x3003);
  c.poles = readU32(0x300F);
  c.encoderLines = readU32(0x3010);
  return c;
}

void SoloDevice::publish(const DriveFeedback& feedback) noexcept {
  od::ObjectDictionary& dictionary = node_.dictionary();
  dictionary.storeUnsigned(0x3036, 0, static_cast<uint32_t>(roundToInt32(feedback.speedRpm)));
  dictionary.storeUnsigned(0x3037, 0, static_cast<uint32_t>(feedback.position));
  storeSfxt(0x3034, feedback.iqA);
  storeSfxt(0x3035, feedback.idA);
  storeSfxt(0x302F, feedback.phaseACurrentA);
  storeSfxt(0x3030, feedback.phaseBCurrentA);
  storeSfxt(0x302D, feedback.phaseAVoltageV);
  storeSfxt(0x302E, feedback.phaseBVoltageV);
  storeSfxt(0x3031, feedback.busVoltageV);
  storeSfxt(0x3032, feedback.motorCurrentA);
  storeSfxt(0x3033, feedback.motorVoltageV);
  storeSfxt(0x3038, feedback.anglePerUnit);
  storeSfxt(0x3039, feedback.boardTemperatureC);
  dictionary.storeUnsigned(0x3049, 0, feedback.digitalInputs);
  if ((feedback.faults & ~errors_.value()) != 0U) {
    errors_.set(feedback.faults);  // a new fault event (also after the host cleared it)
  }
}

Microseconds SoloDevice::process(Microseconds now) noexcept {
  if (now - simulated_ >= kStep) {  // elapsed time, right across the wrap of the clock
    const DriveCommand c = command();
    while (now - simulated_ >= kStep) {
      drive_.step(c, kStep);
      simulated_ += kStep;
    }
    DriveFeedback feedback;
    drive_.read(&feedback);
    publish(feedback);
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
  return earliest(at(simulated_, kStep), identifyAt_);
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
      if (value == 1U && factoryReset_ != nullptr) {
        factoryReset_(factoryResetContext_);
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
  identifyAt_ = kNever;
}

void SoloDevice::onLifeGuardingExpired() noexcept {
  errors_.set(SoloErrorRegister::kCommunicationLost);
}

}  // namespace costa::solo
