// The joint's vendor objects (joint_device.hpp): what a remote write of 0x2601, 0x260A, 0x260E,
// 0x2614, 0x2615 and 0x6098 does beyond storing the value.
#include "costa/od/little_endian.hpp"
#include "joint_device.hpp"

namespace costa::mseries {
namespace {

constexpr uint16_t kOutputEnabled = 0x2601;
constexpr uint16_t kGearNumerator = 0x260A;
constexpr uint16_t kAlarmCode = 0x260E;
constexpr uint16_t kSaveFlag = 0x2614;
constexpr uint16_t kDeviceLocation = 0x2615;
constexpr uint16_t kHomingMethod = 0x6098;
/// The two writes of 0x260A that set the multi-turn zero (lines 254-257).
constexpr uint32_t kZeroFirst = 60006;
constexpr uint32_t kZeroSecond = 60016;
/// 0x2614: 1 saves, 2 reads back once saved (line 273).
constexpr uint32_t kSave = 1;
constexpr uint16_t kSaved = 2;
/// Homing methods 17..21 of 0x6098's range without 20: no figure documents it (D9).
constexpr int8_t kUndocumentedMethod = 20;

/// A value the hook refuses beyond the dictionary's checks (so that check() and write() agree).
AbortCode refusal(uint16_t index, uint32_t value) noexcept {
  switch (index) {
    case kAlarmCode: return value == 0U ? AbortCode::kNone : AbortCode::kInvalidValue;
    case kSaveFlag: return value <= kSave ? AbortCode::kNone : AbortCode::kInvalidValue;
    case kHomingMethod:
      return static_cast<int8_t>(value) == kUndocumentedMethod ? AbortCode::kInvalidValue
                                                               : AbortCode::kNone;
    default: return AbortCode::kNone;
  }
}

}  // namespace

AbortCode JointDevice::check(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                             const uint8_t* data, size_t length) noexcept {
  const AbortCode checked = dictionary.check(ref, data, length);
  if (checked != AbortCode::kNone) {
    return checked;
  }
  return refusal(ref.index(), static_cast<uint32_t>(loadLittleEndian(data, length)));
}

AbortCode JointDevice::save() noexcept {
  // Every parameter: the communication and the application groups (A5).
  const StoreResult saved =
      node_.saveGroups(groupBit(od::kGroupCommunication) | groupBit(od::kGroupApplication));
  if (saved != StoreResult::kOk) {
    return AbortCode::kCannotStore;
  }
  values_.x2614_data_save_flag = kSaved;
  return AbortCode::kNone;
}

AbortCode JointDevice::writeGearNumerator(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                          const uint8_t* data, size_t length) noexcept {
  const auto value = static_cast<uint32_t>(loadLittleEndian(data, length));
  if (value == kZeroSecond && zeroStarted_) {
    // The zero is set: the position becomes 0, the numerator returns to what it was, the
    // battery alarm is restored (lines 257, 132).
    zeroStarted_ = false;
    joint_.setPosition(0);
    alarms_.clear(kAlarmBattery);
    values_.x260a_electronic_gear_numerator = gearBeforeZero_;
    return AbortCode::kNone;
  }
  if (value == kZeroFirst && !zeroStarted_) {
    gearBeforeZero_ = values_.x260a_electronic_gear_numerator;
  }
  zeroStarted_ = value == kZeroFirst;
  return dictionary.write(ref, data, length);
}

AbortCode JointDevice::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                             const uint8_t* data, size_t length) noexcept {
  const AbortCode checked = check(dictionary, ref, data, length);
  if (checked != AbortCode::kNone) {
    return checked;
  }
  const auto value = static_cast<uint32_t>(loadLittleEndian(data, length));
  AbortCode result = AbortCode::kNone;
  switch (ref.index()) {
    case kGearNumerator: result = writeGearNumerator(dictionary, ref, data, length); break;
    case kAlarmCode: resetFault(); break;  // acknowledged; 0x260E shows what is left
    case kSaveFlag:
      if (value == kSave) {
        return save();
      }
      result = dictionary.write(ref, data, length);
      break;
    case kDeviceLocation:
      nodeIdGiven_ = false;  // from now on 0x2615 decides, at the next power-on (W11)
      result = dictionary.write(ref, data, length);
      break;
    case kOutputEnabled:
      result = dictionary.write(ref, data, length);
      if (value == 1U) {
        resetFault();  // "EN enable 1 ... can be recovered" (lines 133-134)
      }
      apply();
      break;
    default: result = dictionary.write(ref, data, length); break;
  }
  drive_.update();
  publish(joint_.read());
  return result;
}

}  // namespace costa::mseries
