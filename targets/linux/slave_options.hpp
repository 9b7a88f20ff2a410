// The command line of costa-slave:
//   costa-slave [--iface NAME] [--node-id N] [--storage FILE|DIR] [--trace] [--control PATH]
//               [--sdo-timeout MS] DEVICE[@NODE-ID] [DEVICE[@NODE-ID] ...]
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

namespace costa::host {

/// One DEVICE[@NODE-ID] of the command line.
struct NodeArgument {
  std::string device;  ///< as given (a name or an alias)
  int nodeId = -1;     ///< @NODE-ID, else --node-id, else -1: the device's own
};

struct SlaveOptions {
  std::string interfaceName = "vcan0";
  int nodeId = -1;          ///< --node-id: the node-id of a DEVICE given without @; -1: none.
  std::string storagePath;  ///< --storage: a file (one node) or a directory (several)
  std::string controlPath;  ///< --control: a UNIX datagram socket for simulation commands
  /// --sdo-timeout: how long every node's SDO server waits for the client within a transfer,
  /// in ms (1..kLongestSdoTimeoutMs); 0: each device's own.
  uint32_t sdoTimeoutMs = 0;
  bool trace = false;
  bool help = false;
  bool listDevices = false;
  std::string edsDevice;            ///< --eds DEVICE: print that device's EDS and exit
  std::vector<NodeArgument> nodes;  ///< the nodes, in the command line's order
};

/// The longest --sdo-timeout: 100 s, well within a deadline's reach (kLongestDelay).
inline constexpr uint32_t kLongestSdoTimeoutMs = 100000;

/// The most nodes one costa-slave runs: every node-id of CiA 301.
inline constexpr size_t kMostNodes = 127;

/// Parses arguments (without argv[0]). On error returns false with one line in `error`.
bool parseSlaveOptions(const std::vector<std::string>& arguments, SlaveOptions* options,
                       std::string* error);

/// The storage file of node `index` (0-based, in the command line's order): --storage itself
/// for a single node, else "<dir>/<device>-<index + 1>.bin" (the device's name, not its alias);
/// empty without --storage.
std::string nodeStoragePath(const SlaveOptions& options, size_t index);

std::string slaveUsage();

}  // namespace costa::host
