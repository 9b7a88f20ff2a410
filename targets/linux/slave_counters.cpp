#include "slave_counters.hpp"

namespace costa::host {

SlaveCounters countersOf(const Node& node, const port::SocketCanPort::Counters& socket) {
  SlaveCounters counters;
  counters.txDropped = node.txDropped();
  counters.txExpired = node.txExpired();
  counters.emcyLost = node.emcyLost();
  counters.errorFrames = socket.errorFrames;
  counters.rxOverruns = node.statistics().rxOverruns;
  counters.busOffs = node.statistics().busOffs;
  return counters;
}

const char* controllerEventName(CanControllerEvent event) {
  switch (event) {
    case CanControllerEvent::kRxOverrun: return "rx overrun";
    case CanControllerEvent::kErrorPassive: return "error passive";
    case CanControllerEvent::kErrorActive: return "error active";
    case CanControllerEvent::kBusOff: return "bus-off";
    case CanControllerEvent::kBusOffRecovered: return "bus-off recovered";
  }
  return "?";
}

std::string describeCounters(const SlaveCounters& counters) {
  return "tx dropped " + std::to_string(counters.txDropped) + ", tx expired " +
         std::to_string(counters.txExpired) + ", EMCY lost " + std::to_string(counters.emcyLost) +
         ", error frames " + std::to_string(counters.errorFrames) + ", rx overruns " +
         std::to_string(counters.rxOverruns) + ", bus-offs " + std::to_string(counters.busOffs);
}

}  // namespace costa::host
