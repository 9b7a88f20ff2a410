#include "santeng_device.hpp"

namespace costa::santeng {

static_assert(features::kParameterStorage,
              "the Santeng saves its configuration with 0x2017 (errata D8): build with "
              "COSTA_FEATURE_PARAMETER_STORAGE=ON");
static_assert(features::kQuirkProfiles,
              "the Santeng serves short and long SDO requests (errata W2-W4, santeng_profile.hpp): "
              "build with COSTA_FEATURE_QUIRK_PROFILES=ON");

namespace {

constexpr uint16_t kFirstCommand = 0x2000;
constexpr uint16_t kLastQuery = 0x2121;
constexpr uint16_t kFirstConfiguration = 0x5000;
constexpr uint16_t kLastConfiguration = 0x5003;
constexpr Microseconds kMillisecond = 1000;
/// Serial (command) mode: commands come from the serial or CAN interface (FS f1, B7).
constexpr uint8_t kStatusSerialMode = 0x01;
constexpr uint8_t kStatusPowerOff = 0x08;
constexpr uint8_t kStatusStall = 0x10;

int16_t saturated16(int32_t value) {
  return static_cast<int16_t>(value > INT16_MAX ? INT16_MAX
                                                : (value < INT16_MIN ? INT16_MIN : value));
}

ChannelMode modeOf(uint8_t value) {
  switch (value) {
    case 1: return ChannelMode::kClosedLoopSpeed;
    case 3: return ChannelMode::kCountPosition;
    default: return ChannelMode::kOpenLoopSpeed;  // 2 (relative position) is not simulated
  }
}

bool configuration(uint16_t index) {
  return index >= kFirstConfiguration && index <= kLastConfiguration;
}

}  // namespace

SantengDevice::SantengDevice(SantengNode& node, PowerStage& stage) noexcept
    : node_(node),
      values_(node.values()),
      stage_(stage),
      attached_(node.attachHook(kFirstCommand, kLastQuery, *this) &&
                node.attachHook(kFirstConfiguration, kLastConfiguration, *this) &&
                node.addListener(*this)) {}

void SantengDevice::commands(ChannelCommand (&out)[kChannels]) const noexcept {
  const gen::santeng::Values& v = values_;
  ControllerReading controller;
  stage_.read(&controller);
  const bool powered = !emergencyStop_ && controller.faults == 0U;
  for (size_t ch = 0; ch < kChannels; ++ch) {
    ChannelCommand& c = out[ch];
    c.mode = modeOf(v.x5001_channel_mode.item[ch]);
    c.powered = powered;
    c.stopping = stopping_[ch];
    c.motorCommand = v.x2000_set_motor_command.item[ch];
    c.targetCount = v.x2001_set_position_command.item[ch];
    c.positionSpeed = v.x2002_set_position_speed.item[ch];
    c.acceleration = v.x2006_set_acceleration.item[ch];
    c.deceleration = v.x2007_set_deceleration.item[ch];
    c.maxRpm = v.x5002_max_rpm.item[ch];
    c.encoderLines = v.x5003_encoder_lines.item[ch];
  }
}

void SantengDevice::advance(Microseconds now) noexcept {
  const Microseconds elapsed = now - simulated_;  // right across the wrap of the clock
  const Microseconds whole = elapsed - elapsed % kMillisecond;
  if (whole != 0U) {
    ChannelCommand c[kChannels];
    commands(c);
    stage_.step(c, whole);
    simulated_ += whole;
    milliseconds_ += whole / kMillisecond;
    seconds_ += milliseconds_ / 1000U;
    milliseconds_ %= 1000U;
  }
  publish();
}

Microseconds SantengDevice::process(Microseconds now) noexcept {
  advance(now);
  return kNever;
}

void SantengDevice::publish() noexcept {
  gen::santeng::Values& v = values_;
  uint8_t motorFlags = 0;
  for (size_t ch = 0; ch < kChannels; ++ch) {
    ChannelReading r;
    stage_.read(ch, &r);
    v.x2100_read_motor_current.item[ch] = r.motorAmpsTimes10;
    v.x2101_read_current_motor_command.item[ch] = r.appliedPermille;
    v.x2103_read_encoder_motor_speed.item[ch] = saturated16(r.speedRpm);
    v.x2104_read_absolute_encoder_count.item[ch] = r.encoderCount;
    v.x2105_read_absolute_brushless_count.item[ch] = r.hallCount;
    v.x2107_read_encoder_speed_relative.item[ch] = r.speedPermille;
    v.x210a_read_brushless_motor_speed.item[ch] = saturated16(r.speedRpm);
    v.x210c_read_battery_current.item[ch] = r.batteryAmpsTimes10;
    v.x2121_read_motor_status_flags.item[ch] = r.motorFlags;
    motorFlags = static_cast<uint8_t>(motorFlags | r.motorFlags);
  }
  ControllerReading c;
  stage_.read(&c);
  for (size_t i = 0; i < 3U; ++i) {
    v.x210d_read_voltage.item[i] = c.voltages[i];
    v.x210f_read_temperature.item[i] = c.temperatures[i];
  }
  v.x210e_read_all_digital_inputs = c.digitalInputs;
  v.x2113_read_digital_outputs = c.digitalOutputs;
  v.x2119_read_time = seconds_;
  const auto faults = static_cast<uint8_t>(c.faults | (emergencyStop_ ? kEmergencyStop : 0U) |
                                           (configurationLost_ ? kDefaultConfiguration : 0U));
  v.x2112_read_fault_flags = faults;
  const bool powerOff = emergencyStop_ || c.faults != 0U;
  v.x2111_read_status_flags =
      static_cast<uint8_t>(kStatusSerialMode | (powerOff ? kStatusPowerOff : 0U) |
                           ((motorFlags & kMotorStalled) != 0U ? kStatusStall : 0U));
}

void SantengDevice::readRelative(uint16_t index, uint8_t sub) noexcept {
  if (sub < 1U || sub > kChannels) {
    return;
  }
  const size_t ch = sub - 1U;
  gen::santeng::Values& v = values_;
  if (index == 0x2108) {
    const int32_t now = v.x2104_read_absolute_encoder_count.item[ch];
    v.x2108_read_encoder_count_relative.item[ch] =
        static_cast<int32_t>(static_cast<uint32_t>(now) - static_cast<uint32_t>(encoderRead_[ch]));
    encoderRead_[ch] = now;
  } else if (index == 0x2109) {
    const int32_t now = v.x2105_read_absolute_brushless_count.item[ch];
    v.x2109_read_brushless_count_relative.item[ch] =
        static_cast<int32_t>(static_cast<uint32_t>(now) - static_cast<uint32_t>(hallRead_[ch]));
    hallRead_[ch] = now;
  }
}

AbortCode SantengDevice::prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                     const ReadRequest& request) noexcept {
  (void)dictionary;
  (void)request;
  if (configuration(ref.index())) {
    return AbortCode::kNoObject;  // the RS232 utility's, not the bus's (D13)
  }
  advance(node_.now());
  readRelative(ref.index(), ref.subIndex());
  return AbortCode::kNone;
}

AbortCode SantengDevice::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                               const uint8_t* data, size_t length) noexcept {
  if (configuration(ref.index())) {
    return AbortCode::kNoObject;  // D13
  }
  advance(node_.now());  // the command takes effect from now on
  const int32_t counter =
      ref.index() == 0x2003 && ref.subIndex() >= 1U && ref.subIndex() <= kChannels
          ? values_.x2104_read_absolute_encoder_count.item[ref.subIndex() - 1U]
          : 0;
  const AbortCode written = dictionary.write(ref, data, length);
  if (written != AbortCode::kNone) {
    return written;
  }
  if (ref.index() == 0x2003 && ref.subIndex() >= 1U && ref.subIndex() <= kChannels) {
    const size_t ch = ref.subIndex() - 1U;
    const int32_t loaded = values_.x2003_set_encoder_counter.item[ch];
    stage_.loadCounter(ch, loaded);
    // A load is no motion: the relative count goes on from the new value.
    encoderRead_[ch] =
        static_cast<int32_t>(static_cast<uint32_t>(encoderRead_[ch]) +
                             (static_cast<uint32_t>(loaded) - static_cast<uint32_t>(counter)));
  }
  const AbortCode acted = act(ref);
  publish();
  return acted;
}

AbortCode SantengDevice::act(const od::EntryRef& ref) noexcept {
  const uint8_t sub = ref.subIndex();
  const bool channel = sub >= 1U && sub <= kChannels;
  if (!channel && ref.index() != 0x2005 && (ref.index() <= 0x2003 || ref.index() == 0x200E)) {
    return AbortCode::kNone;  // sub-index 0 of a channel object: no command (a local write)
  }
  switch (ref.index()) {
    case 0x2000:
    case 0x2001:
    case 0x2002:
      stopping_[sub - 1U] = false;  // a motion command ends the stop of 0x200E
      break;
    case 0x2005: mirrorUserVariables(); break;
    case 0x200C: emergencyStop_ = true; break;
    case 0x200D: emergencyStop_ = false; break;
    case 0x200E: stopping_[sub - 1U] = true; break;
    case 0x2017: return save();
    default: break;
  }
  return AbortCode::kNone;
}

AbortCode SantengDevice::save() noexcept {
  const StoreResult groups = node_.saveGroups(kSavedGroups);
  const LssStoreResult record =
      node_.storeLssConfiguration(node_.pendingNodeId(), node_.pendingBitTiming());
  return groups == StoreResult::kOk && record == LssStoreResult::kStored ? AbortCode::kNone
                                                                         : AbortCode::kCannotStore;
}

void SantengDevice::mirrorUserVariables() noexcept {
  for (size_t i = 0; i < 16U; ++i) {
    values_.x2106_read_user_integer_variable.item[i] =
        values_.x2005_set_user_integer_variable.item[i];
  }
}

void SantengDevice::setChannelMode(size_t channel, ChannelMode mode) noexcept {
  advance(node_.now());
  values_.x5001_channel_mode.item[channel] = static_cast<uint8_t>(mode);
  publish();
}

void SantengDevice::setMaxRpm(size_t channel, uint16_t rpm) noexcept {
  advance(node_.now());
  values_.x5002_max_rpm.item[channel] = rpm;
  publish();
}

void SantengDevice::setEncoderLines(size_t channel, uint16_t lines) noexcept {
  advance(node_.now());
  values_.x5003_encoder_lines.item[channel] = lines;
  publish();
}

void SantengDevice::setAutomaticStart(bool on) noexcept {
  values_.x5000_automatic_start = on ? 1U : 0U;
}

void SantengDevice::onResetApplication() noexcept {
  stage_.reset();
  simulated_ = node_.now();
  milliseconds_ = 0;
  seconds_ = 0;
  for (size_t ch = 0; ch < kChannels; ++ch) {
    encoderRead_[ch] = 0;
    hallRead_[ch] = 0;
    stopping_[ch] = false;
  }
  emergencyStop_ = false;
  configurationLost_ = false;
}

void SantengDevice::onResetCommunication() noexcept {
  // Automatic start after the boot-up (W7): the configuration's, loaded at reset node.
  node_.setAutomaticStart(values_.x5000_automatic_start == 1U);
}

void SantengDevice::onRpdoReceived(uint16_t communicationIndex) noexcept {
  (void)communicationIndex;
  mirrorUserVariables();  // RPDO data lands in user variables 9..16 (W14)
}

void SantengDevice::onStoredParametersInvalid(uint8_t group, StoreResult result) noexcept {
  (void)group;
  (void)result;
  configurationLost_ = true;  // "default configuration loaded at startup" (FF f8, B10)
}

}  // namespace costa::santeng
