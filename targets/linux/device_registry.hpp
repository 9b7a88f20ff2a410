// The devices costa-slave can be: example, solo, gra, grn, ...
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "device_target.hpp"

namespace costa::host {

struct DeviceEntry {
  const char* name;
  const char* summary;
  /// Creates the device. On failure returns nullptr and sets `error`.
  std::unique_ptr<DeviceTarget> (*create)(CanTransmitter& can, const TargetOptions& options,
                                          std::string* error);
};

const std::vector<DeviceEntry>& devices();
const DeviceEntry* findDevice(const std::string& name);
/// "example, solo, ..." for messages.
std::string deviceNames();

}  // namespace costa::host
