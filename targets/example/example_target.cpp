#include "example_target.hpp"

namespace costa::example {

NodeSettings ExampleTarget::settings(uint8_t nodeId, NvStorage* storage) noexcept {
  NodeSettings settings;
  settings.nodeId = nodeId;
  settings.storage = storage;
  settings.lss = true;
  // CiA 305 bit timing table indices 0..4 and 6..8 (1000 to 125, 50, 20, 10 kbit/s).
  settings.lssBitRates = 0x01DF;
  return settings;
}

ExampleTarget::ExampleTarget(CanTransmitter& can, uint8_t nodeId, NvStorage* storage) noexcept
    : ExampleTarget(can, settings(nodeId, storage)) {}

ExampleTarget::ExampleTarget(CanTransmitter& can, const NodeSettings& settings,
                             uint32_t serialNumber) noexcept
    : node_(gen::example::kDefinition, can, settings), device_(node_, serialNumber) {}

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
