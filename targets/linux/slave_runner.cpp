#include "slave_runner.hpp"

#include <poll.h>
#include <signal.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

#include "control_socket.hpp"
#include "costa/port/linux/monotonic_clock.hpp"
#include "costa/port/linux/socketcan_port.hpp"
#include "device_registry.hpp"
#include "local_bus.hpp"
#include "slave_counters.hpp"
#include "slave_tracer.hpp"

namespace costa::host {
namespace {

// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables): all a handler may set
volatile sig_atomic_t stopRequested = 0;

void onStopSignal(int /*signal*/) {
  stopRequested = 1;
}

/// The node's bit rate control: the socket's (which records the rate; the interface's own rate
/// is the system's), with every switch traced.
class TracedBitRate final : public CanBitRateControl {
 public:
  TracedBitRate(port::SocketCanPort& socket, SlaveTracer& tracer)
      : socket_(socket), tracer_(tracer) {}
  bool setBitRate(uint32_t bitsPerSecond) noexcept override {
    if (!socket_.setBitRate(bitsPerSecond)) {
      return false;
    }
    tracer_.bitRate(bitsPerSecond);
    return true;
  }

 private:
  port::SocketCanPort& socket_;
  SlaveTracer& tracer_;
};

/// How long to wait for `deadline`, in microseconds.
timespec waitTime(Microseconds deadline, Microseconds now, bool txPending) {
  Microseconds wait = deadline == kNever ? kNever : reached(now, deadline) ? 0U : deadline - now;
  if (txPending && wait > 1000U) {
    wait = 1000U;  // the controller refused frames: offer them again soon
  }
  const Microseconds limit = 1000000U;  // wake at least every second
  if (wait > limit) {
    wait = limit;
  }
  timespec result{};
  result.tv_sec = static_cast<time_t>(wait / 1000000U);
  result.tv_nsec = static_cast<decltype(result.tv_nsec)>(wait % 1000000U) * 1000;
  return result;
}

/// Lets SIGINT and SIGTERM stop the loop. They are blocked except while the loop waits (in
/// ppoll, with the mask returned here), so a stop request is never missed between two waits.
sigset_t catchStopSignals() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  sigset_t blocked;
  sigset_t waiting;
  sigemptyset(&blocked);
  sigaddset(&blocked, SIGINT);
  sigaddset(&blocked, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &blocked, &waiting);
  sigdelset(&waiting, SIGINT);
  sigdelset(&waiting, SIGTERM);
  return waiting;
}

/// The node's time: the low 32 bits of the monotonic clock (the node handles their wrap).
Microseconds nodeTime(port::LinuxMonotonicClock& clock) {
  return static_cast<Microseconds>(clock.nowMicroseconds());
}

/// Passes every frame the socket holds to the nodes, and the controller events of error frames.
void receiveFrames(port::SocketCanPort& socket, SlaveTracer& tracer, LocalBus& bus,
                   port::LinuxMonotonicClock& clock) {
  CanFrame frame;
  port::SocketCanEvents events;
  for (;;) {
    const auto received = socket.receive(&frame, &events);
    if (received == port::SocketCanPort::Received::kFrame) {
      bus.receive(frame, nodeTime(clock));
    } else if (received == port::SocketCanPort::Received::kErrorFrame) {
      tracer.errorFrame(events);
      for (const CanControllerEvent event : events) {
        bus.controllerEvent(event, nodeTime(clock));
      }
    } else {
      break;
    }
  }
}

/// The losses of every node together.
SlaveCounters totalCounters(LocalBus& bus, const port::SocketCanPort::Counters& socket) {
  SlaveCounters total = countersOf(bus.node(0).node(), socket);
  for (size_t i = 1; i < bus.nodeCount(); ++i) {
    const SlaveCounters more = countersOf(bus.node(i).node(), socket);
    total.txDropped += more.txDropped;
    total.txExpired += more.txExpired;
    total.emcyLost += more.emcyLost;
  }
  return total;
}

/// Creates every node of `options` on `bus`. False with one line in `error`.
bool createNodes(const SlaveOptions& options, LocalBus& bus, CanBitRateControl& bitRate,
                 std::string* error) {
  const bool several = options.nodes.size() > 1U;
  if (several && !options.storagePath.empty()) {
    std::error_code failed;
    std::filesystem::create_directories(options.storagePath, failed);
    if (failed) {
      *error =
          "cannot create the storage directory " + options.storagePath + ": " + failed.message();
      return false;
    }
  }
  for (size_t i = 0; i < options.nodes.size(); ++i) {
    std::unique_ptr<DeviceTarget> target =
        createDevice(*findDevice(options.nodes[i].device), bus.nextPort(),
                     nodeTargetOptions(options, i, bitRate), error);
    if (!target) {
      return false;
    }
    bus.attach(std::move(target));
  }
  return true;
}

/// Runs a --control command: "[@NODE-ID] command" (with several nodes the node-id is needed).
std::string control(LocalBus& bus, const std::string& command) {
  if (command.empty() || command[0] != '@') {
    if (bus.nodeCount() > 1U) {
      return "name the node: @NODE-ID " + command;
    }
    bus.touch(0);
    return bus.node(0).control(command);
  }
  const size_t space = command.find(' ');
  const std::string nodeText = command.substr(1, space == std::string::npos ? space : space - 1U);
  char* end = nullptr;
  const uint64_t nodeId = std::strtoull(nodeText.c_str(), &end, 0);
  if (nodeText.empty() || *end != '\0') {
    return "invalid node-id '" + nodeText + "'";
  }
  const std::string rest = space == std::string::npos ? std::string() : command.substr(space + 1U);
  for (size_t i = 0; i < bus.nodeCount(); ++i) {
    if (bus.node(i).node().nodeId() == nodeId) {
      bus.touch(i);
      return bus.node(i).control(rest);
    }
  }
  return "no node with node-id " + nodeText;
}

/// "example on vcan0, node-id 1" or "3 nodes on vcan0: example@1 solo@2 gra@3".
std::string describeNodes(const SlaveOptions& options, LocalBus& bus) {
  if (bus.nodeCount() == 1U) {
    return options.nodes[0].device + " on " + options.interfaceName + ", node-id " +
           std::to_string(bus.node(0).node().nodeId());
  }
  std::string text = std::to_string(bus.nodeCount()) + " nodes on " + options.interfaceName + ":";
  for (size_t i = 0; i < bus.nodeCount(); ++i) {
    text += " " + options.nodes[i].device + "@" + std::to_string(bus.node(i).node().nodeId());
  }
  return text;
}

}  // namespace

TargetOptions nodeTargetOptions(const SlaveOptions& options, size_t index,
                                CanBitRateControl& bitRate) {
  TargetOptions targetOptions;
  targetOptions.nodeId = options.nodes[index].nodeId;
  targetOptions.storagePath = nodeStoragePath(options, index);
  targetOptions.bitRate = &bitRate;
  targetOptions.sdoTimeout = millisecondsToMicroseconds(options.sdoTimeoutMs);
  targetOptions.serialNumber = options.nodes.size() > 1U ? static_cast<uint32_t>(index + 1U) : 0U;
  return targetOptions;
}

int runSlave(const SlaveOptions& options) {
  port::SocketCanPort socket;
  std::string error;
  if (!socket.open(options.interfaceName, &error)) {
    std::fprintf(stderr, "costa-slave: %s\n", error.c_str());
    return 1;
  }
  port::LinuxMonotonicClock clock;
  SlaveTracer tracer(options.trace, options.nodes.size() > 1U, clock);
  TracedBitRate bitRate(socket, tracer);
  LocalBus bus(socket, tracer, clock);
  if (!createNodes(options, bus, bitRate, &error)) {
    std::fprintf(stderr, "costa-slave: %s\n", error.c_str());
    return 1;
  }
  ControlSocket controlSocket;
  if (!options.controlPath.empty() && !controlSocket.open(options.controlPath, &error)) {
    std::fprintf(stderr, "costa-slave: %s\n", error.c_str());
    return 1;
  }

  const sigset_t waiting = catchStopSignals();
  bus.start(nodeTime(clock));
  std::fprintf(stderr, "costa-slave: %s\n", describeNodes(options, bus).c_str());

  while (stopRequested == 0) {
    const Microseconds deadline = bus.process();
    const timespec wait = waitTime(deadline, nodeTime(clock), bus.txPending());
    pollfd descriptors[2] = {{socket.fd(), POLLIN, 0}, {controlSocket.fd(), POLLIN, 0}};
    const nfds_t count = controlSocket.fd() >= 0 ? 2U : 1U;
    const int ready = ppoll(descriptors, count, &wait, &waiting);  // signals arrive only here
    if (ready > 0 && count == 2U && (descriptors[1].revents & POLLIN) != 0) {
      controlSocket.serve([&](const std::string& command) {
        std::fprintf(stderr, "costa-slave: control: %s\n", command.c_str());
        return control(bus, command);
      });
    }
    if (ready < 0 && errno != EINTR) {
      const int code = errno;
      std::fprintf(stderr, "costa-slave: poll failed: %s\n",
                   std::system_category().message(code).c_str());
      return 1;
    }
    if (ready > 0) {
      if ((descriptors[0].revents & (POLLERR | POLLHUP | POLLNVAL)) != 0) {
        std::fprintf(stderr, "costa-slave: CAN interface %s failed\n",
                     options.interfaceName.c_str());
        return 1;
      }
      receiveFrames(socket, tracer, bus, clock);
    }
    if (bus.txPending()) {
      bus.flushTx();
    }
    tracer.counters(totalCounters(bus, socket.counters()));
  }
  std::fprintf(stderr, "costa-slave: stopped: %s\n",
               describeCounters(totalCounters(bus, socket.counters())).c_str());
  return 0;
}

}  // namespace costa::host
