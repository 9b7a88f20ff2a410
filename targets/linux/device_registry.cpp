#include "device_registry.hpp"

#include "example_od.hpp"
#include "example_target.hpp"
#include "solo_od.hpp"
#include "solo_target.hpp"

namespace costa::host {
namespace {

std::unique_ptr<DeviceTarget> createExample(CanTransmitter& can, const TargetOptions& options,
                                            std::string* error) {
  (void)error;
  const auto nodeId = static_cast<uint8_t>(options.nodeId < 0 ? 1 : options.nodeId);
  return std::make_unique<HostedTarget<example::ExampleTarget>>(&gen::example::kNames, can, nodeId);
}

std::unique_ptr<DeviceTarget> createSolo(CanTransmitter& can, const TargetOptions& options,
                                         std::string* error) {
  (void)error;
  const auto nodeId = static_cast<uint8_t>(options.nodeId < 0 ? 1 : options.nodeId);
  return std::make_unique<HostedTarget<solo::SoloTarget>>(&gen::solo::kNames, can, nodeId);
}

}  // namespace

const std::vector<DeviceEntry>& devices() {
  static const std::vector<DeviceEntry> table = {
      {"example", "Costa example device (every access type, several data types)", createExample},
      {"solo", "SOLO UNO / SOLO MINI motor controller with a simulated motor", createSolo},
  };
  return table;
}

const DeviceEntry* findDevice(const std::string& name) {
  for (const DeviceEntry& entry : devices()) {
    if (name == entry.name) {
      return &entry;
    }
  }
  return nullptr;
}

std::string deviceNames() {
  std::string text;
  for (const DeviceEntry& entry : devices()) {
    text += (text.empty() ? "" : ", ") + std::string(entry.name);
  }
  return text;
}

}  // namespace costa::host
