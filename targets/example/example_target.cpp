#include "example_target.hpp"

namespace costa::example {

NodeSettings ExampleTarget::settings(uint8_t nodeId) noexcept {
  NodeSettings settings;
  settings.nodeId = nodeId;
  return settings;
}

ExampleTarget::ExampleTarget(CanTransmitter& can, uint8_t nodeId) noexcept
    : node_(gen::example::kDefinition, can, settings(nodeId)), device_(node_) {}

Microseconds ExampleTarget::process(Microseconds now) noexcept {
  const Microseconds deviceNext = device_.process(now);
  return earliest(deviceNext, node_.process(now));
}

const uint8_t* ExampleTarget::scratchPad() const noexcept {
  return device_.scratchPad();
}

size_t ExampleTarget::scratchPadLength() const noexcept {
  return device_.scratchPadLength();
}

}  // namespace costa::example
