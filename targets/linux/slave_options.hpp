// The command line of costa-slave:
//   costa-slave [--iface NAME] [--node-id N] [--storage FILE] [--trace] DEVICE
#pragma once

#include <string>
#include <vector>

namespace costa::host {

struct SlaveOptions {
  std::string interfaceName = "vcan0";
  int nodeId = -1;  ///< -1: the device's default.
  std::string storagePath;
  std::string controlPath;  ///< --control: a UNIX datagram socket for simulation commands
  bool trace = false;
  bool help = false;
  bool listDevices = false;
  std::string edsDevice;  ///< --eds DEVICE: print that device's EDS and exit
  std::string device;
};

/// Parses arguments (without argv[0]). On error returns false with one line in `error`.
bool parseSlaveOptions(const std::vector<std::string>& arguments, SlaveOptions* options,
                       std::string* error);

std::string slaveUsage();

}  // namespace costa::host
