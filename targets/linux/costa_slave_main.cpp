// costa-slave: Costa devices (one or several nodes) on a SocketCAN interface.
#include <cstdio>
#include <string>
#include <vector>

#include "device_registry.hpp"
#include "slave_options.hpp"
#include "slave_runner.hpp"

int main(int argc, char** argv) {
  using namespace costa::host;
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  SlaveOptions options;
  std::string error;
  if (!parseSlaveOptions(arguments, &options, &error)) {
    std::fprintf(stderr, "costa-slave: %s\n", error.c_str());
    return 2;
  }
  if (options.help) {
    std::fputs(slaveUsage().c_str(), stdout);
    return 0;
  }
  if (options.listDevices) {
    for (const DeviceEntry& entry : devices()) {
      if (entry.alias != nullptr) {
        std::printf("%-10s %s (also: %s)\n", entry.name, entry.summary, entry.alias);
      } else {
        std::printf("%-10s %s\n", entry.name, entry.summary);
      }
    }
    return 0;
  }
  return runSlave(options);
}
