// The losses costa-slave makes visible: frames the node dropped or let expire, EMCY frames lost
// to a full EMCY queue, and the controller conditions the driver reported.
#pragma once

#include <stdint.h>

#include <string>

#include "costa/node.hpp"
#include "costa/port/linux/socketcan_port.hpp"

namespace costa::host {

struct SlaveCounters {
  uint32_t txDropped = 0;    ///< Frames dropped by the node's full transmit queue.
  uint32_t txExpired = 0;    ///< Frames that expired in the queue before they could be sent.
  uint32_t emcyLost = 0;     ///< EMCY frames dropped by the node's full EMCY queue.
  uint64_t errorFrames = 0;  ///< Error frames of the driver (controller state changes).
  uint32_t rxOverruns = 0;   ///< Overruns among them (EMCY 0x8110).
  uint32_t busOffs = 0;      ///< Bus-offs among them.

  bool operator==(const SlaveCounters& other) const {
    return txDropped == other.txDropped && txExpired == other.txExpired &&
           emcyLost == other.emcyLost && errorFrames == other.errorFrames &&
           rxOverruns == other.rxOverruns && busOffs == other.busOffs;
  }
  bool operator!=(const SlaveCounters& other) const { return !(*this == other); }
};

SlaveCounters countersOf(const Node& node, const port::SocketCanPort::Counters& socket);

/// "rx overrun", "error passive", "error active", "bus-off", "bus-off recovered".
const char* controllerEventName(CanControllerEvent event);

/// One line: "tx dropped 0, tx expired 0, EMCY lost 0, error frames 0, rx overruns 0,
/// bus-offs 0".
std::string describeCounters(const SlaveCounters& counters);

}  // namespace costa::host
