// A tank monitor on Linux: a CANopen slave (Costa) with the dictionary of monitor.eds on a
// SocketCAN interface, until SIGINT or SIGTERM.
//
//   tank-monitor [--node-id N] [--exit-after-boot-up] INTERFACE
//
// --exit-after-boot-up stops once the boot-up frame is on the bus (a smoke test).
#include <poll.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "costa/node.hpp"
#include "costa/port/linux/monotonic_clock.hpp"
#include "costa/port/linux/socketcan_port.hpp"
#include "monitor_od.hpp"

namespace {

using MonitorNode = costa::NodeInstance<costa::gen::monitor::Values, costa::gen::monitor::Capacity>;

// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables): all a handler may set
volatile std::sig_atomic_t stopRequested = 0;

void onStopSignal(int /*signal*/) {
  stopRequested = 1;
}

struct Options {
  std::string interfaceName;
  uint8_t nodeId = 0x20;
  bool exitAfterBootUp = false;
};

bool parseOptions(int argc, char** argv, Options* options) {
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--node-id" && i + 1 < argc) {
      const auto nodeId = std::strtol(argv[++i], nullptr, 0);
      if (nodeId < 1 || nodeId > 127) {
        return false;
      }
      options->nodeId = static_cast<uint8_t>(nodeId);
    } else if (argument == "--exit-after-boot-up") {
      options->exitAfterBootUp = true;
    } else if (options->interfaceName.empty() && argument.rfind("--", 0) != 0) {
      options->interfaceName = argument;
    } else {
      return false;
    }
  }
  return !options->interfaceName.empty();
}

/// The node's time: the low 32 bits of the monotonic clock (the node handles their wrap).
costa::Microseconds nodeTime(costa::port::LinuxMonotonicClock& clock) {
  return static_cast<costa::Microseconds>(clock.nowMicroseconds());
}

/// Milliseconds to wait for a frame before `deadline` (at most one second).
int waitMilliseconds(costa::Microseconds deadline, costa::Microseconds now) {
  constexpr costa::Microseconds kLongestWait = 1000000U;
  costa::Microseconds wait = kLongestWait;
  if (deadline != costa::kNever) {
    wait = costa::reached(now, deadline) ? 0U : deadline - now;
  }
  if (wait > kLongestWait) {
    wait = kLongestWait;
  }
  return static_cast<int>((wait + 999U) / 1000U);
}

/// The fill level input (a stand-in for the sensor), a slow ramp, into 0x2000.
void updateFillLevel(MonitorNode& node, costa::Microseconds now) {
  const auto level = static_cast<int16_t>((now / 100000U) % 1000U);
  if (level != node.values().x2000_fill_level) {
    node.values().x2000_fill_level = level;
    node.markChanged(0x2000, 0);  // the event-driven TPDO 1 sends it
  }
}

/// Passes every frame the socket holds to the node, and the controller events of error frames.
void receiveFrames(costa::port::SocketCanPort& socket, MonitorNode& node,
                   costa::port::LinuxMonotonicClock& clock) {
  costa::CanFrame frame;
  costa::port::SocketCanEvents events;
  for (;;) {
    const auto received = socket.receive(&frame, &events);
    if (received == costa::port::SocketCanPort::Received::kFrame) {
      node.onFrame(frame, nodeTime(clock));
    } else if (received == costa::port::SocketCanPort::Received::kErrorFrame) {
      for (const costa::CanControllerEvent event : events) {
        node.onControllerEvent(event, nodeTime(clock));
      }
    } else {
      return;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!parseOptions(argc, argv, &options)) {
    std::fprintf(stderr, "usage: tank-monitor [--node-id N] [--exit-after-boot-up] INTERFACE\n");
    return 2;
  }
  costa::port::SocketCanPort socket;
  std::string error;
  if (!socket.open(options.interfaceName, &error)) {
    std::fprintf(stderr, "tank-monitor: %s\n", error.c_str());
    return 1;
  }
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);

  costa::NodeSettings settings;
  settings.nodeId = options.nodeId;
  MonitorNode node(costa::gen::monitor::kDefinition, socket, settings);
  costa::port::LinuxMonotonicClock clock;
  node.start(nodeTime(clock));
  std::fprintf(stderr, "tank-monitor: node-id %u on %s\n", node.nodeId(),
               options.interfaceName.c_str());

  while (stopRequested == 0) {
    const costa::Microseconds now = nodeTime(clock);
    updateFillLevel(node, now);
    const costa::Microseconds deadline = node.process(now);
    if (node.txPending()) {
      node.flushTx();
    }
    if (options.exitAfterBootUp && socket.counters().transmitted > 0U) {
      std::fprintf(stderr, "tank-monitor: boot-up sent\n");
      return 0;
    }
    // Frames the controller refused are offered again within a millisecond.
    const int timeout = node.txPending() ? 1 : waitMilliseconds(deadline, nodeTime(clock));
    pollfd descriptor{socket.fd(), POLLIN, 0};
    const int ready = poll(&descriptor, 1, timeout);
    if (ready > 0 && (descriptor.revents & (POLLERR | POLLHUP | POLLNVAL)) != 0) {
      std::fprintf(stderr, "tank-monitor: CAN interface %s failed\n",
                   options.interfaceName.c_str());
      return 1;
    }
    if (ready > 0) {
      receiveFrames(socket, node, clock);
    }
  }
  return 0;
}
