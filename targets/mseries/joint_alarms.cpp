#include "joint_alarms.hpp"

namespace costa::mseries {
namespace {

/// Each alarm's error condition: its code (CiA 301 / CiA 402 classes) and error register bits.
struct AlarmCondition {
  uint8_t alarm;
  uint16_t code;
  uint8_t registerBits;
};

constexpr AlarmCondition kConditions[] = {
    {kAlarmBattery, 0xFF10, kErrorManufacturer},         // manufacturer-specific
    {kAlarmLockedRotor, 0x7121, kErrorDeviceProfile},    // CiA 402: motor blocked
    {kAlarmStall, 0x8611, kErrorDeviceProfile},          // CiA 402: following error
    {kAlarmOverVoltage, 0x3210, kErrorVoltage},          // CiA 402: DC link over-voltage
    {kAlarmCommunication, 0x8130, kErrorCommunication},  // CiA 301: heartbeat error
};

const AlarmCondition* conditionOf(uint8_t alarm) noexcept {
  for (const AlarmCondition& condition : kConditions) {
    if (condition.alarm == alarm) {
      return &condition;
    }
  }
  return nullptr;
}

}  // namespace

uint8_t JointAlarms::bitOf(uint8_t alarm) noexcept {
  for (size_t i = 0; i < sizeof(kConditions) / sizeof(kConditions[0]); ++i) {
    if (kConditions[i].alarm == alarm) {
      return static_cast<uint8_t>(1U << i);
    }
  }
  return 0;
}

bool JointAlarms::raise(uint8_t alarm) noexcept {
  const AlarmCondition* condition = conditionOf(alarm);
  if (condition == nullptr) {
    return false;
  }
  if (!active(alarm)) {
    active_ = static_cast<uint8_t>(active_ | bitOf(alarm));
    node_.raiseError(condition->code, condition->registerBits);
  }
  return true;
}

void JointAlarms::clear(uint8_t alarm) noexcept {
  const AlarmCondition* condition = conditionOf(alarm);
  if (condition != nullptr && active(alarm)) {
    active_ = static_cast<uint8_t>(active_ & ~bitOf(alarm));
    node_.clearError(condition->code);
  }
}

uint16_t JointAlarms::code() const noexcept {
  uint16_t code = 0;
  for (size_t i = 0; active_ != 0U && i < sizeof(kConditions) / sizeof(kConditions[0]); ++i) {
    if ((active_ & (1U << i)) != 0U && kConditions[i].alarm > code) {  // bit i: bitOf()
      code = kConditions[i].alarm;
    }
  }
  return code;
}

bool JointAlarms::fault() const noexcept {
  return active(kAlarmLockedRotor) || active(kAlarmStall) || active(kAlarmOverVoltage);
}

void JointAlarms::resetFaults(bool overVoltage) noexcept {
  clear(kAlarmLockedRotor);
  clear(kAlarmStall);
  if (!overVoltage) {
    clear(kAlarmOverVoltage);
  }
}

}  // namespace costa::mseries
