#include "solo_target.hpp"

namespace costa::solo {

static_assert(
    features::kParameterStorage,
    "the SOLO keeps its parameters in EEPROM: build with COSTA_FEATURE_PARAMETER_STORAGE=ON");
static_assert(
    features::kNodeGuarding,
    "the SOLO answers node guarding (errata A12, S5): build with COSTA_FEATURE_NODE_GUARDING=ON");
static_assert(features::kQuirkProfiles,
              "the SOLO speaks its own SDO, PDO and EMCY dialect (solo_profile.hpp): build with "
              "COSTA_FEATURE_QUIRK_PROFILES=ON");
static_assert(!SoloTarget::settings().lss && SoloTarget::settings().saveParametersOnWrite,
              "the SOLO has no LSS and keeps every M object as it is written");

NodeSettings SoloTarget::settingsFor(const DeviceConfig& config, NvStorage* eeprom) noexcept {
  NodeSettings s = configured(settings(), config);
  s.nodeId = address(s.nodeId);
  if (s.storage == nullptr) {
    s.storage = eeprom;
  }
  return s;
}

SoloTarget::SoloTarget(CanTransmitter& can, const DeviceConfig& config) noexcept
    : node_(gen::solo::kDefinition, can, settingsFor(config, &eeprom_)),
      device_(node_, drive_, address(config.nodeIdGiven ? config.nodeId : settings().nodeId),
              config.nodeIdGiven) {
  device_.onFactoryReset(&SoloTarget::discardStoredParameters, this);
}

bool SoloTarget::discardStoredParameters(void* target) noexcept {
  ParameterStore* store = static_cast<SoloTarget*>(target)->node_.parameterStore();
  if (store == nullptr) {
    return true;
  }
  // Both groups are tried, so that a failure of one does not keep the other.
  const StoreResult communication = store->invalidate(od::kGroupCommunication);
  const StoreResult application = store->invalidate(od::kGroupApplication);
  return communication == StoreResult::kOk && application == StoreResult::kOk;
}

Microseconds SoloTarget::process(Microseconds now) noexcept {
  (void)device_.process(now);  // first: the node's PDOs carry what the drive measured now
  const Microseconds nodeNext = node_.process(now);
  return earliest(device_.nextDeadline(), nodeNext);
}

bool SoloTarget::control(const char* command, char* why, size_t whySize) noexcept {
  (void)command;
  return refuseControl(kNoSimulationCommands, why, whySize);
}

}  // namespace costa::solo
