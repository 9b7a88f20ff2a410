#include "device_registry.hpp"

#include "costa/port/linux/file_storage.hpp"
#include "example_od.hpp"
#include "example_target.hpp"
#include "gefran_control.hpp"
#include "gefran_target.hpp"
#include "gra_od.hpp"
#include "grn_od.hpp"
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
  settings.bitRateControl = options.bitRate;
  return std::make_unique<HostedTarget<example::ExampleTarget>>(&gen::example::kNames,
                                                                std::move(storage), can, settings);
}

std::unique_ptr<DeviceTarget> createSolo(CanTransmitter& can, const TargetOptions& options,
                                         std::string* error) {
  std::unique_ptr<port::FileStorage> storage;
  if (!openStorage(options, &storage, error)) {
    return nullptr;
  }
  if (options.nodeId == 255) {
    *error = "solo has no LSS: it needs a node-id (--node-id 1..127)";
    return nullptr;
  }
  const auto nodeId = static_cast<uint8_t>(options.nodeId < 0 ? 1 : options.nodeId);
  NvStorage* raw = storage.get();
  const bool explicitNodeId = options.nodeId >= 0;
  return std::make_unique<HostedTarget<solo::SoloTarget>>(
      &gen::solo::kNames, std::move(storage), can, nodeId, raw, explicitNodeId, options.bitRate);
}

/// Simulation commands of a GRA/GRN (targets/gefran/gefran_control.hpp): raw A B, angle DEG,
/// fault chip1|chip2|magnet on|off.
template <typename Target>
std::string controlGefran(Target& target, const std::string& command) {
  const gefran::ParsedControl parsed = gefran::parseControl(command.c_str());
  if (parsed.error != gefran::ControlError::kNone) {
    std::string message(gefran::describeControlError(parsed, nullptr, 0) + 1U, '\0');
    message.resize(gefran::describeControlError(parsed, message.data(), message.size()));
    return message;
  }
  gefran::applyControl(parsed.command, target.sensors());
  target.process(target.node().now());
  return "";
}

template <typename Values, typename Capacity>
std::unique_ptr<DeviceTarget> createGefran(const od::Definition& definition,
                                           const od::NameTable& names, CanTransmitter& can,
                                           const TargetOptions& options, std::string* error) {
  std::unique_ptr<port::FileStorage> storage;
  if (!openStorage(options, &storage, error)) {
    return nullptr;
  }
  using Target = gefran::GefranTarget<Values, Capacity>;
  const auto nodeId =
      static_cast<uint8_t>(options.nodeId < 0 ? gefran::kFactoryNodeId : options.nodeId);
  NvStorage* raw = storage.get();
  auto target =
      std::make_unique<HostedTarget<Target>>(&names, std::move(storage), definition, can, nodeId,
                                             raw, options.nodeId >= 0, options.bitRate);
  target->setController(&controlGefran<Target>);
  return target;
}

std::unique_ptr<DeviceTarget> createGra(CanTransmitter& can, const TargetOptions& options,
                                        std::string* error) {
  return createGefran<gen::gra::Values, gen::gra::Capacity>(gen::gra::kDefinition, gen::gra::kNames,
                                                            can, options, error);
}

std::unique_ptr<DeviceTarget> createGrn(CanTransmitter& can, const TargetOptions& options,
                                        std::string* error) {
  return createGefran<gen::grn::Values, gen::grn::Capacity>(gen::grn::kDefinition, gen::grn::kNames,
                                                            can, options, error);
}

}  // namespace

const std::vector<DeviceEntry>& devices() {
  static const std::vector<DeviceEntry> table = {
      {"example", "Costa example device (every access type, several data types)", createExample},
      {"solo", "SOLO UNO / SOLO MINI motor controller with a simulated motor", createSolo},
      {"gra", "Gefran GRA contactless angle sensor (with shaft), simulated hall chips", createGra},
      {"grn", "Gefran GRN contactless angle sensor (without shaft)", createGrn},
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
