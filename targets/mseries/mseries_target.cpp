#include "mseries_target.hpp"

#include "joint_control.hpp"

namespace costa::mseries {

static_assert(!MSeriesTarget::settings().lss && MSeriesTarget::settings().automaticStart &&
                  (!features::kQuirkProfiles ||  // its own static_assert (joint_device.cpp)
                   !MSeriesTarget::settings().profile.errorControl.nodeGuarding),
              "the M-series joint has no LSS, starts by itself and answers no guarding");

NodeSettings MSeriesTarget::settingsFor(const DeviceConfig& config, NvStorage* eeprom) noexcept {
  NodeSettings s = configured(settings(), config);
  s.nodeId = address(s.nodeId);
  if (s.storage == nullptr) {
    s.storage = eeprom;
  }
  return s;
}

MSeriesTarget::MSeriesTarget(CanTransmitter& can, const DeviceConfig& config) noexcept
    : node_(gen::mseries::kDefinition, can, settingsFor(config, &eeprom_)),
      device_(node_, joint_, address(config.nodeIdGiven ? config.nodeId : settings().nodeId),
              config.nodeIdGiven) {}

void MSeriesTarget::start(Microseconds now) noexcept {
  node_.start(now);
  process(now);
}

bool MSeriesTarget::control(const char* command, char* why, size_t whySize) noexcept {
  const JointControl parsed = parseJointControl(command);
  const JointFeedback feedback = joint_.read();
  switch (parsed.kind) {
    case JointControl::Kind::kNone: return refuseControl(parsed.error, why, whySize);
    case JointControl::Kind::kPosition:
      joint_.setPosition(static_cast<int32_t>(parsed.value));
      break;
    case JointControl::Kind::kDir: joint_.setInputs(parsed.value != 0, feedback.pu); break;
    case JointControl::Kind::kPu: joint_.setInputs(feedback.dir, parsed.value != 0); break;
    case JointControl::Kind::kAlarm: device_.raiseAlarm(static_cast<uint8_t>(parsed.value)); break;
    case JointControl::Kind::kVoltage:
      device_.setSupplyVolts(static_cast<uint32_t>(parsed.value));
      break;
  }
  process(node_.now());
  return true;
}

}  // namespace costa::mseries
