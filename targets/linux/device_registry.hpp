// The devices costa-slave can be: those of targets/devices.hpp, by name.
#pragma once

#include <stddef.h>

#include <memory>
#include <string>
#include <vector>

#include "costa/node_settings.hpp"
#include "device_target.hpp"

namespace costa::host {

struct DeviceEntry {
  const char* name;
  const char* summary;
  /// Another name the device answers to (its composition's optional kAlias: a name that is
  /// no C++ identifier, such as m-series), or null.
  const char* alias;
  bool lss;               ///< it has LSS: it may start without a node-id (--node-id 255)
  uint8_t defaultNodeId;  ///< its own node-id (without --node-id)
  uint8_t highestNodeId;  ///< it takes node-ids 1..highestNodeId (127 but for a few devices)
  size_t storageBytes;    ///< its non-volatile memory: the size of the --storage file
  /// Builds the device with `config` over `storage` (may be null; `config.storage` is it).
  std::unique_ptr<DeviceTarget> (*build)(CanTransmitter& can, const DeviceConfig& config,
                                         std::unique_ptr<port::FileStorage> storage);
};

/// Every device, in the list's order.
const std::vector<DeviceEntry>& devices();
/// The device named `name`, by its name or its alias; null when none is.
const DeviceEntry* findDevice(const std::string& name);
/// "example, solo, ..." for messages.
std::string deviceNames();

/// Creates `device` as costa-slave's options say: the node-id (the device's own without one),
/// the storage file (opened with the device's size), the bit rate control. On failure returns
/// nullptr with one line in `error`: a storage file that cannot be opened, or no node-id for
/// a device without LSS, a serial number that finds no room.
std::unique_ptr<DeviceTarget> createDevice(const DeviceEntry& device, CanTransmitter& can,
                                           const TargetOptions& options, std::string* error);

}  // namespace costa::host
