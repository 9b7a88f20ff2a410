#include "device_registry.hpp"

#include "costa/cob_ids.hpp"
#include "devices.hpp"

namespace costa::host {
namespace {

/// A composition's kAlias, or null when it declares none: the first overload when it does.
struct NoAlias {};
struct WithAlias : NoAlias {};
template <typename Composition, typename = decltype(Composition::kAlias)>
constexpr const char* aliasOf(WithAlias /*unused*/) {
  return Composition::kAlias;
}
template <typename Composition>
constexpr const char* aliasOf(NoAlias /*unused*/) {
  return nullptr;
}

template <typename Composition>
std::unique_ptr<DeviceTarget> build(CanTransmitter& can, const DeviceConfig& config,
                                    std::unique_ptr<port::FileStorage> storage) {
  return std::make_unique<HostedTarget<Composition>>(std::move(storage), can, config);
}

std::vector<DeviceEntry> listedDevices() {
  std::vector<DeviceEntry> table;
  devices::forEachDevice([&table](auto device) {
    using Composition = typename decltype(device)::Composition;
    table.push_back(DeviceEntry{
        device.name, Composition::kSummary, aliasOf<Composition>(WithAlias{}),
        Composition::settings().lss, Composition::settings().nodeId,
        devices::highestNodeId<Composition>(), Composition::kStorageBytes, &build<Composition>});
  });
  return table;
}

}  // namespace

const std::vector<DeviceEntry>& devices() {
  static const std::vector<DeviceEntry> table = listedDevices();
  return table;
}

const DeviceEntry* findDevice(const std::string& name) {
  for (const DeviceEntry& entry : devices()) {
    if (name == entry.name || (entry.alias != nullptr && name == entry.alias)) {
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

std::unique_ptr<DeviceTarget> createDevice(const DeviceEntry& device, CanTransmitter& can,
                                           const TargetOptions& options, std::string* error) {
  std::unique_ptr<port::FileStorage> storage;
  if (!options.storagePath.empty()) {
    storage = std::make_unique<port::FileStorage>();
    if (!storage->open(options.storagePath, device.storageBytes, error)) {
      return nullptr;
    }
  }
  if (options.nodeId == cob::kLssUnconfigured && !device.lss) {
    *error = std::string(device.name) + " has no LSS: it needs a node-id (--node-id 1..127)";
    return nullptr;
  }
  DeviceConfig config;
  config.nodeIdGiven = options.nodeId >= 0;
  config.nodeId = static_cast<uint8_t>(config.nodeIdGiven ? options.nodeId : 0);
  config.storage = storage.get();
  config.bitRateControl = options.bitRate;
  config.sdoTimeout = options.sdoTimeout;
  std::unique_ptr<DeviceTarget> target = device.build(can, config, std::move(storage));
  if (options.serialNumber != 0U && !target->overrideSerialNumber(options.serialNumber)) {
    *error = std::string(device.name) + ": no room for a listener setting its serial number";
    return nullptr;
  }
  return target;
}

}  // namespace costa::host
