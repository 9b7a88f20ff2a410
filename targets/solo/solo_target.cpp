#include "solo_target.hpp"

#include "solo_profile.hpp"

namespace costa::solo {

SoloTarget::SoloTarget(CanTransmitter& can, uint8_t nodeId) noexcept
    : node_(gen::solo::kDefinition, can, settings(address(nodeId))),
      device_(node_, drive_, address(nodeId)) {}

Microseconds SoloTarget::process(Microseconds now) noexcept {
  const Microseconds deviceNext = device_.process(now);
  return earliest(deviceNext, node_.process(now));
}

}  // namespace costa::solo
