#include "example_target.hpp"

namespace costa::example {

ExampleTarget::ExampleTarget(CanTransmitter& can, const DeviceConfig& config) noexcept
    : node_(gen::example::kDefinition, can, configured(settings(), config)), device_(node_) {}

Microseconds ExampleTarget::process(Microseconds now) noexcept {
  const Microseconds deviceNext = device_.process(now);
  return earliest(deviceNext, node_.process(now));
}

bool ExampleTarget::control(const char* command, char* why, size_t whySize) noexcept {
  (void)command;
  return refuseControl(kNoSimulationCommands, why, whySize);
}

const uint8_t* ExampleTarget::scratchPad() const noexcept {
  return device_.scratchPad();
}

size_t ExampleTarget::scratchPadLength() const noexcept {
  return device_.scratchPadLength();
}

}  // namespace costa::example
