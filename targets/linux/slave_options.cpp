#include "slave_options.hpp"

#include <cerrno>
#include <cstdlib>

#include "costa/cob_ids.hpp"
#include "device_registry.hpp"

namespace costa::host {
namespace {

bool parseNodeId(const std::string& text, int* value) {
  if (text.empty()) {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const auto parsed = std::strtol(text.c_str(), &end, 0);
  const bool valid = (parsed >= 1 && parsed <= 127) || parsed == 255;  // 255: unconfigured (LSS)
  if (errno != 0 || end == nullptr || *end != '\0' || !valid) {
    return false;
  }
  *value = static_cast<int>(parsed);
  return true;
}

/// An option without a value: sets it and returns true, or returns false for anything else.
bool setFlag(const std::string& argument, SlaveOptions* options) {
  if (argument == "--help" || argument == "-h") {
    options->help = true;
  } else if (argument == "--trace") {
    options->trace = true;
  } else if (argument == "--list-devices") {
    options->listDevices = true;
  } else {
    return false;
  }
  return true;
}

/// Where the value of an option with a text value goes; nullptr for any other argument.
std::string* textOption(const std::string& argument, SlaveOptions& options) {
  if (argument == "--iface") {
    return &options.interfaceName;
  }
  if (argument == "--storage") {
    return &options.storagePath;
  }
  if (argument == "--control") {
    return &options.controlPath;
  }
  if (argument == "--eds") {
    return &options.edsDevice;
  }
  return nullptr;
}

/// The device of complete options (not --help, --list-devices) exists.
bool checkDevice(const SlaveOptions& options, std::string* error) {
  if (options.device.empty()) {
    *error = "no DEVICE given (one of: " + deviceNames() + ")";
    return false;
  }
  const DeviceEntry* device = findDevice(options.device);
  if (device == nullptr) {
    *error = "unknown device '" + options.device + "' (one of: " + deviceNames() + ")";
    return false;
  }
  if (options.nodeId > device->highestNodeId && options.nodeId != cob::kLssUnconfigured) {
    *error = "invalid node-id " + std::to_string(options.nodeId) + " for " + options.device +
             ": it takes 1.." + std::to_string(device->highestNodeId);
    return false;
  }
  return true;
}

}  // namespace

std::string slaveUsage() {
  return "usage: costa-slave [--iface NAME] [--node-id N] [--storage FILE] [--trace] DEVICE\n"
         "\n"
         "Runs a CANopen slave device on a SocketCAN interface.\n"
         "\n"
         "  --iface NAME     CAN interface (default vcan0)\n"
         "  --node-id N      node-id 1..127 (decimal or 0x hex; default: the device's own);\n"
         "                   255 starts without a node-id, waiting for LSS\n"
         "  --storage FILE   file holding the device's non-volatile parameters\n"
         "  --trace          print every frame received and sent, with its meaning\n"
         "  --control PATH   accept simulation commands (for example 'angle 90' for gra/grn) as\n"
         "                   datagrams on a UNIX socket at PATH; each gets 'ok' or 'error: ...'\n"
         "  --list-devices   list the devices with their identity (0x1018) and exit\n"
         "  --eds DEVICE     print the EDS the device was built from, byte for byte, and exit\n"
         "  --help           show this help and exit\n"
         "\n"
         "DEVICE is one of: " +
         deviceNames() + "\n";
}

bool parseSlaveOptions(const std::vector<std::string>& arguments, SlaveOptions* options,
                       std::string* error) {
  for (size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    auto value = [&](std::string* out) {
      if (i + 1U >= arguments.size()) {
        *error = argument + " needs a value";
        return false;
      }
      *out = arguments[++i];
      return true;
    };
    if (setFlag(argument, options)) {
      continue;
    }
    if (std::string* destination = textOption(argument, *options)) {
      if (!value(destination)) {
        return false;
      }
    } else if (argument == "--node-id") {
      std::string text;
      if (!value(&text)) {
        return false;
      }
      if (!parseNodeId(text, &options->nodeId)) {
        *error = "invalid node-id '" + text + "': expected 1..127 (or 255: unconfigured, LSS only)";
        return false;
      }
    } else if (!argument.empty() && argument[0] == '-') {
      *error = "unknown option '" + argument + "' (see --help)";
      return false;
    } else if (options->device.empty()) {
      options->device = argument;
    } else {
      *error = "unexpected argument '" + argument + "': only one DEVICE";
      return false;
    }
  }
  if (options->help || options->listDevices) {
    return true;
  }
  if (!options->edsDevice.empty()) {
    if (findDevice(options->edsDevice) == nullptr) {
      *error = "unknown device '" + options->edsDevice + "' (one of: " + deviceNames() + ")";
      return false;
    }
    return true;
  }
  return checkDevice(*options, error);
}

}  // namespace costa::host
