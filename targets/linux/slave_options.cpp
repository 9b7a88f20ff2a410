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

/// --sdo-timeout's value: 1..kLongestSdoTimeoutMs milliseconds, decimal.
bool parseSdoTimeout(const std::string& text, uint32_t* milliseconds) {
  if (text.empty() || text[0] < '0' || text[0] > '9') {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const auto parsed = std::strtoul(text.c_str(), &end, 10);
  if (errno != 0 || end == nullptr || *end != '\0' || parsed < 1U ||
      parsed > kLongestSdoTimeoutMs) {
    return false;
  }
  *milliseconds = static_cast<uint32_t>(parsed);
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

/// An option with a number for its value.
bool isNumberOption(const std::string& argument) {
  return argument == "--node-id" || argument == "--sdo-timeout";
}

/// Parses the value `text` of a number option (isNumberOption) into `options`, or returns false
/// with one line in `error`.
bool parseNumberOption(const std::string& argument, const std::string& text, SlaveOptions* options,
                       std::string* error) {
  if (argument == "--node-id" && !parseNodeId(text, &options->nodeId)) {
    *error = "invalid node-id '" + text + "': expected 1..127 (or 255: unconfigured, LSS only)";
    return false;
  }
  if (argument == "--sdo-timeout" && !parseSdoTimeout(text, &options->sdoTimeoutMs)) {
    *error = "invalid SDO timeout '" + text + "': expected 1.." +
             std::to_string(kLongestSdoTimeoutMs) + " ms";
    return false;
  }
  return true;
}

/// Splits DEVICE[@NODE-ID]. False with one line in `error` when the node-id is invalid.
bool parseNodeArgument(const std::string& argument, int defaultNodeId, NodeArgument* node,
                       std::string* error) {
  const size_t at = argument.find('@');
  node->device = argument.substr(0, at);
  node->nodeId = defaultNodeId;
  if (at == std::string::npos) {
    return true;
  }
  const std::string text = argument.substr(at + 1U);
  if (!parseNodeId(text, &node->nodeId)) {
    *error = "invalid node-id '" + text + "' in '" + argument +
             "': expected 1..127 (or 255: unconfigured, LSS only)";
    return false;
  }
  return true;
}

/// The node's device exists and takes its node-id.
bool checkNode(const NodeArgument& node, std::string* error) {
  const DeviceEntry* device = findDevice(node.device);
  if (device == nullptr) {
    *error = "unknown device '" + node.device + "' (one of: " + deviceNames() + ")";
    return false;
  }
  if (node.nodeId == cob::kLssUnconfigured && !device->lss) {
    *error = node.device + " has no LSS: it needs a node-id (--node-id 1.." +
             std::to_string(device->highestNodeId) + ")";
    return false;
  }
  if (node.nodeId > device->highestNodeId && node.nodeId != cob::kLssUnconfigured) {
    *error = "invalid node-id " + std::to_string(node.nodeId) + " for " + node.device +
             ": it takes 1.." + std::to_string(device->highestNodeId);
    return false;
  }
  return true;
}

/// The nodes of complete options (not --help, --list-devices): at least one, at most
/// kMostNodes, each a known device, no node-id twice (a device's own counts; 255 may repeat).
bool checkNodes(const SlaveOptions& options, std::string* error) {
  if (options.nodes.empty()) {
    *error = "no DEVICE given (one of: " + deviceNames() + ")";
    return false;
  }
  if (options.nodes.size() > kMostNodes) {
    *error = std::to_string(options.nodes.size()) + " nodes given: at most " +
             std::to_string(kMostNodes) + " fit on one bus";
    return false;
  }
  bool taken[256] = {};
  for (const NodeArgument& node : options.nodes) {
    if (!checkNode(node, error)) {
      return false;
    }
    const int nodeId = node.nodeId >= 0 ? node.nodeId : findDevice(node.device)->defaultNodeId;
    if (nodeId != cob::kLssUnconfigured && taken[nodeId]) {
      *error = "node-id " + std::to_string(nodeId) + " given twice (" + node.device +
               "): every node needs its own";
      return false;
    }
    taken[nodeId] = true;
  }
  return true;
}

/// --eds names a device (its name or its alias).
bool checkEdsDevice(const SlaveOptions& options, std::string* error) {
  if (findDevice(options.edsDevice) == nullptr) {
    *error = "unknown device '" + options.edsDevice + "' (one of: " + deviceNames() + ")";
    return false;
  }
  return true;
}

/// The DEVICE arguments, after the options: --node-id applies wherever it stands.
bool parseNodes(const std::vector<std::string>& positional, SlaveOptions* options,
                std::string* error) {
  for (const std::string& argument : positional) {
    NodeArgument node;
    if (!parseNodeArgument(argument, options->nodeId, &node, error)) {
      return false;
    }
    options->nodes.push_back(node);
  }
  return true;
}

/// After the options: what the command asks for is complete (--help and --list-devices need
/// nothing more; --eds a device; else the nodes).
bool finishOptions(const std::vector<std::string>& positional, SlaveOptions* options,
                   std::string* error) {
  if (options->help || options->listDevices) {
    return true;
  }
  if (!options->edsDevice.empty()) {
    return checkEdsDevice(*options, error);
  }
  return parseNodes(positional, options, error) && checkNodes(*options, error);
}

}  // namespace

std::string slaveUsage() {
  return "usage: costa-slave [--iface NAME] [--node-id N] [--storage FILE] [--trace] DEVICE\n"
         "       costa-slave [options] DEVICE[@NODE-ID] [DEVICE[@NODE-ID] ...]\n"
         "\n"
         "Runs CANopen slave devices on a SocketCAN interface: one, or several nodes on one bus\n"
         "(each node's frames reach the others in the process and go out once).\n"
         "\n"
         "  --iface NAME     CAN interface (default vcan0)\n"
         "  --node-id N      node-id 1..127 (decimal or 0x hex; default: the device's own);\n"
         "                   255 starts without a node-id, waiting for LSS. DEVICE@N gives a\n"
         "                   node its node-id in the same way (@255 may repeat)\n"
         "  --storage FILE   file holding the device's non-volatile parameters; with several\n"
         "                   nodes a directory holding DEVICE-K.bin for the K-th node given\n"
         "                   (K from 1, DEVICE the device's name, e.g. mseries-3.bin)\n"
         "  --trace          print every frame received and sent, with its meaning (with\n"
         "                   several nodes each line names its node: @05 tx 705 ...)\n"
         "  --sdo-timeout MS how long an SDO transfer waits for the client before the node\n"
         "                   aborts it (0x05040000), 1.." +
         std::to_string(kLongestSdoTimeoutMs) +
         " ms (default: the device's own)\n"
         "  --control PATH   accept simulation commands (for example 'angle 90' for gra/grn) as\n"
         "                   datagrams on a UNIX socket at PATH; each gets 'ok' or 'error: ...';\n"
         "                   with several nodes a command names its node: '@0x10 angle 90'\n"
         "  --list-devices   list the devices with their identity (0x1018) and exit\n"
         "  --eds DEVICE     print the EDS the device was built from, byte for byte, and exit\n"
         "  --help           show this help and exit\n"
         "\n"
         "DEVICE is one of: " +
         deviceNames() +
         "\n"
         "With several nodes (at most 127, node-ids distinct), the K-th node given has serial\n"
         "number K in 0x1018:04, so that LSS Fastscan tells unconfigured (@255) nodes apart.\n";
}

std::string nodeStoragePath(const SlaveOptions& options, size_t index) {
  if (options.storagePath.empty() || options.nodes.size() == 1U) {
    return options.storagePath;
  }
  const DeviceEntry* device = findDevice(options.nodes[index].device);
  return options.storagePath + "/" + device->name + "-" + std::to_string(index + 1U) + ".bin";
}

bool parseSlaveOptions(const std::vector<std::string>& arguments, SlaveOptions* options,
                       std::string* error) {
  std::vector<std::string> positional;
  for (size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if (setFlag(argument, options)) {
      continue;
    }
    if (textOption(argument, *options) != nullptr || isNumberOption(argument)) {
      if (i + 1U >= arguments.size()) {
        *error = argument + " needs a value";
        return false;
      }
      const std::string& value = arguments[++i];
      if (std::string* destination = textOption(argument, *options)) {
        *destination = value;
      } else if (!parseNumberOption(argument, value, options, error)) {
        return false;
      }
    } else if (!argument.empty() && argument[0] == '-') {
      *error = "unknown option '" + argument + "' (see --help)";
      return false;
    } else {
      positional.push_back(argument);
    }
  }
  return finishOptions(positional, options, error);
}

}  // namespace costa::host
