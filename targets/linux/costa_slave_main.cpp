// costa-slave: Costa devices (one or several nodes) on a SocketCAN interface.
#include <cstdio>
#include <string>
#include <vector>

#include "device_eds.hpp"
#include "device_listing.hpp"
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
    std::fputs(describeDevices().c_str(), stdout);
    return 0;
  }
  if (!options.edsDevice.empty()) {
    const std::string_view eds = deviceEds(findDevice(options.edsDevice)->name);
    return std::fwrite(eds.data(), 1, eds.size(), stdout) == eds.size() ? 0 : 1;
  }
  return runSlave(options);
}
