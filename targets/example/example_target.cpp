#include "example_target.hpp"

namespace costa::example {

NodeSettings ExampleTarget::settings(uint8_t nodeId) noexcept {
  NodeSettings settings;
  settings.nodeId = nodeId;
  return settings;
}

ExampleTarget::ExampleTarget(CanTransmitter& can, uint8_t nodeId) noexcept
    : ExampleTarget(can, settings(nodeId)) {}

ExampleTarget::ExampleTarget(CanTransmitter& can, const NodeSettings& settings) noexcept
    : node_(gen::example::kDefinition, can, settings), device_(node_) {}

Microseconds ExampleTarget::process(Microseconds now) noexcept {
  const Microseconds deviceNext = device_.process(now);
  return earliest(deviceNext, node_.process(now));
}

}  // namespace costa::example
