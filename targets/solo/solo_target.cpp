#include "solo_target.hpp"

#include "solo_profile.hpp"

namespace costa::solo {

SoloTarget::SoloTarget(CanTransmitter& can, uint8_t nodeId, NvStorage* storage, bool explicitNodeId,
                       CanBitRateControl* bitRate) noexcept
    : node_(gen::solo::kDefinition, can,
            settings(address(nodeId), storage != nullptr ? storage : &eeprom_, bitRate)),
      device_(node_, drive_, address(nodeId), explicitNodeId) {
  device_.onFactoryReset(&SoloTarget::discardStoredParameters, this);
}

void SoloTarget::discardStoredParameters(void* target) noexcept {
  ParameterStore* store = static_cast<SoloTarget*>(target)->node_.parameterStore();
  if (store != nullptr) {
    store->invalidate(od::kGroupCommunication);
    store->invalidate(od::kGroupApplication);
  }
}

Microseconds SoloTarget::process(Microseconds now) noexcept {
  const Microseconds deviceNext = device_.process(now);
  return earliest(deviceNext, node_.process(now));
}

}  // namespace costa::solo
