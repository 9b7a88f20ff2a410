#include "santeng_target.hpp"

#include "costa/od/little_endian.hpp"
#include "santeng_control.hpp"

namespace costa::santeng {

static_assert(!SantengTarget::settings().lss &&
                  (!features::kQuirkProfiles ||  // its own static_assert (santeng_device.cpp)
                   !SantengTarget::settings().profile.errorControl.nodeGuarding),
              "the Santeng has neither LSS nor node guarding (W8, W11)");

NodeSettings SantengTarget::settingsFor(const DeviceConfig& config, NvStorage* memory) noexcept {
  DeviceConfig checked = config;
  if (checked.nodeIdGiven && (checked.nodeId < 1U || checked.nodeId > kHighestNodeId)) {
    checked.nodeId = settings().nodeId;
  }
  NodeSettings s = configured(settings(), checked);
  if (s.storage == nullptr) {
    s.storage = memory;
  }
  return s;
}

SantengTarget::SantengTarget(CanTransmitter& can, const DeviceConfig& config) noexcept
    : node_(gen::santeng::kDefinition, can, settingsFor(config, &memory_)),
      device_(node_, stage_) {}

void SantengTarget::start(Microseconds now) noexcept {
  node_.start(now);
  process(now);
}

Microseconds SantengTarget::process(Microseconds now) noexcept {
  const Microseconds deviceNext = device_.process(now);
  return earliest(deviceNext, node_.process(now));
}

bool SantengTarget::writeSetting(uint16_t index, uint8_t sub, uint32_t value) noexcept {
  uint8_t data[2] = {};
  storeLittleEndian(data, value, sizeof(data));
  return node_.writeEntry(index, sub, data, sizeof(data)) == AbortCode::kNone;
}

bool SantengTarget::control(const char* command, char* why, size_t whySize) noexcept {
  SantengControl c;
  if (!parseSantengControl(command, &c, why, whySize)) {
    return false;
  }
  using Kind = SantengControl::Kind;
  switch (c.kind) {
    case Kind::kNodeId: node_.setPendingNodeId(static_cast<uint8_t>(c.number)); break;
    case Kind::kBitRate:
      node_.setPendingBitTiming(LssBitTiming{kManufacturerBitTimingTable,
                                             static_cast<uint8_t>(santengBitRateCode(c.number))});
      break;
    case Kind::kHeartbeat: (void)writeSetting(0x1017, 0, c.number); break;
    case Kind::kTpdoRate:
      for (uint16_t tpdo = 0x1800; tpdo <= 0x1803; ++tpdo) {
        (void)writeSetting(tpdo, 5, c.number);
      }
      break;
    case Kind::kAutoStart: device_.setAutomaticStart(c.on); break;
    case Kind::kMode: device_.setChannelMode(c.channel, static_cast<ChannelMode>(c.number)); break;
    case Kind::kMaxRpm: device_.setMaxRpm(c.channel, static_cast<uint16_t>(c.number)); break;
    case Kind::kEncoderLines:
      device_.setEncoderLines(c.channel, static_cast<uint16_t>(c.number));
      break;
    case Kind::kFault: stage_.setFault(static_cast<uint8_t>(c.number), c.on); break;
    case Kind::kStall: stage_.setStalled(c.channel, c.on); break;
    case Kind::kInput: stage_.setInput(c.number, c.on); break;
    case Kind::kOutput: stage_.setOutput(c.number, c.on); break;
  }
  process(node_.now());
  return true;
}

}  // namespace costa::santeng
