#include "device_registry.hpp"

#include "costa/port/linux/file_storage.hpp"
#include "example_od.hpp"
#include "example_target.hpp"
#include "solo_od.hpp"
#include "solo_target.hpp"

namespace costa::host {
namespace {

/// Size of the file behind --storage.
constexpr size_t kStorageBytes = 16384;

/// Opens --storage when given. False (with `error`) when the file cannot be used.
bool openStorage(const TargetOptions& options, std::unique_ptr<port::FileStorage>* storage,
                 std::string* error) {
  if (options.storagePath.empty()) {
    return true;
  }
  auto file = std::make_unique<port::FileStorage>();
  if (!file->open(options.storagePath, kStorageBytes, error)) {
    return false;
  }
  *storage = std::move(file);
  return true;
}

std::unique_ptr<DeviceTarget> createExample(CanTransmitter& can, const TargetOptions& options,
                                            std::string* error) {
  std::unique_ptr<port::FileStorage> storage;
  if (!openStorage(options, &storage, error)) {
    return nullptr;
  }
  const auto nodeId = static_cast<uint8_t>(options.nodeId < 0 ? 1 : options.nodeId);
  NodeSettings settings = example::ExampleTarget::settings(nodeId, storage.get());
  settings.storedNodeIdWins = options.nodeId < 0;  // an explicit --node-id wins
  return std::make_unique<HostedTarget<example::ExampleTarget>>(&gen::example::kNames,
                                                                std::move(storage), can, settings);
}

std::unique_ptr<DeviceTarget> createSolo(CanTransmitter& can, const TargetOptions& options,
                                         std::string* error) {
  std::unique_ptr<port::FileStorage> storage;
  if (!openStorage(options, &storage, error)) {
    return nullptr;
  }
  const auto nodeId = static_cast<uint8_t>(options.nodeId < 0 ? 1 : options.nodeId);
  NvStorage* raw = storage.get();
  const bool explicitNodeId = options.nodeId >= 0;
  return std::make_unique<HostedTarget<solo::SoloTarget>>(&gen::solo::kNames, std::move(storage),
                                                          can, nodeId, raw, explicitNodeId);
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
