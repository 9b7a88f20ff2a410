#include "slave_runner.hpp"

#include <poll.h>
#include <signal.h>

#include <cerrno>
#include <cstdio>
#include <memory>
#include <string>
#include <system_error>

#include "control_socket.hpp"
#include "costa/port/linux/monotonic_clock.hpp"
#include "costa/port/linux/socketcan_port.hpp"
#include "device_registry.hpp"
#include "frame_text.hpp"
#include "frame_trace.hpp"
#include "slave_counters.hpp"

namespace costa::host {
namespace {

// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables): all a handler may set
volatile sig_atomic_t stopRequested = 0;

void onStopSignal(int /*signal*/) {
  stopRequested = 1;
}

/// Prints one trace line per frame: time, direction, frame, meaning.
class Tracer {
 public:
  Tracer(bool enabled, port::LinuxMonotonicClock& clock)
      : enabled_(enabled), clock_(clock), epoch_(clock.nowMicroseconds()) {}

  void attach(DeviceTarget* target) {
    target_ = target;
    decoder_ = std::make_unique<FrameTracer>(&target->node().dictionary(), target->names(),
                                             target->node().profile());
  }

  void line(const char* direction, const CanFrame& frame) {
    if (!enabled_) {
      return;
    }
    const std::string meaning =
        decoder_ ? decoder_->describe(frame, target_->node().nodeId()) : std::string();
    print(direction, formatFrame(frame), meaning);
  }

  /// An error frame of the driver and the controller events it reported.
  void errorFrame(const port::SocketCanEvents& events) {
    if (!enabled_) {
      return;
    }
    std::string meaning;
    for (const CanControllerEvent event : events) {
      meaning += meaning.empty() ? "controller: " : ", ";
      meaning += controllerEventName(event);
    }
    print("rx", "error frame", meaning);
  }

  /// The counters of losses, when they changed since the last call.
  void counters(const SlaveCounters& now) {
    if (!enabled_ || now == shown_) {
      return;
    }
    shown_ = now;
    print("--", "counters", describeCounters(now));
  }

  /// "bit rate now 500 kbit/s": the node re-timed the port.
  void bitRate(uint32_t bitsPerSecond) {
    if (!enabled_) {
      return;
    }
    char text[40];
    if (bitsPerSecond % 1000U == 0U) {
      std::snprintf(text, sizeof(text), "bit rate now %u kbit/s", bitsPerSecond / 1000U);
    } else {
      std::snprintf(text, sizeof(text), "bit rate now %u bit/s", bitsPerSecond);
    }
    print("--", text, "");
  }

 private:
  void print(const char* direction, const std::string& what, const std::string& meaning) {
    const uint64_t elapsed = clock_.nowMicroseconds() - epoch_;
    std::printf("%5llu.%06llu %s %-32s %s\n", static_cast<unsigned long long>(elapsed / 1000000U),
                static_cast<unsigned long long>(elapsed % 1000000U), direction, what.c_str(),
                meaning.c_str());
    std::fflush(stdout);
  }

  bool enabled_;
  port::LinuxMonotonicClock& clock_;
  uint64_t epoch_;
  DeviceTarget* target_ = nullptr;
  std::unique_ptr<FrameTracer> decoder_;
  SlaveCounters shown_;
};

/// The node's transmitter: the socket, with every accepted frame traced.
class TracedSocket final : public CanTransmitter {
 public:
  TracedSocket(port::SocketCanPort& socket, Tracer& tracer) : socket_(socket), tracer_(tracer) {}
  bool tryTransmit(const CanFrame& frame) noexcept override {
    if (!socket_.tryTransmit(frame)) {
      return false;
    }
    tracer_.line("tx", frame);
    return true;
  }

 private:
  port::SocketCanPort& socket_;
  Tracer& tracer_;
};

/// The node's bit rate control: the socket's (which records the rate; the interface's own rate
/// is the system's), with every switch traced.
class TracedBitRate final : public CanBitRateControl {
 public:
  TracedBitRate(port::SocketCanPort& socket, Tracer& tracer) : socket_(socket), tracer_(tracer) {}
  bool setBitRate(uint32_t bitsPerSecond) noexcept override {
    if (!socket_.setBitRate(bitsPerSecond)) {
      return false;
    }
    tracer_.bitRate(bitsPerSecond);
    return true;
  }

 private:
  port::SocketCanPort& socket_;
  Tracer& tracer_;
};

int timeoutMilliseconds(Microseconds deadline, Microseconds now, bool txPending) {
  Microseconds wait = deadline == kNever ? kNever : reached(now, deadline) ? 0U : deadline - now;
  if (txPending && wait > 1000U) {
    wait = 1000U;  // the controller refused frames: offer them again soon
  }
  const Microseconds limit = 1000000U;  // wake at least every second
  if (wait > limit) {
    wait = limit;
  }
  return static_cast<int>((wait + 999U) / 1000U);
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

/// Passes every frame the socket holds to the target, and the controller events of error
/// frames to its node.
void receiveFrames(port::SocketCanPort& socket, Tracer& tracer, DeviceTarget& target,
                   port::LinuxMonotonicClock& clock) {
  CanFrame frame;
  port::SocketCanEvents events;
  for (;;) {
    const auto received = socket.receive(&frame, &events);
    if (received == port::SocketCanPort::Received::kFrame) {
      tracer.line("rx", frame);
      target.onFrame(frame, nodeTime(clock));
    } else if (received == port::SocketCanPort::Received::kErrorFrame) {
      tracer.errorFrame(events);
      for (const CanControllerEvent event : events) {
        target.node().onControllerEvent(event, nodeTime(clock));
      }
    } else {
      break;
    }
  }
}

}  // namespace

int runSlave(const SlaveOptions& options) {
  port::SocketCanPort socket;
  std::string error;
  if (!socket.open(options.interfaceName, &error)) {
    std::fprintf(stderr, "costa-slave: %s\n", error.c_str());
    return 1;
  }
  port::LinuxMonotonicClock clock;
  Tracer tracer(options.trace, clock);
  TracedSocket transmitter(socket, tracer);
  TracedBitRate bitRate(socket, tracer);
  TargetOptions targetOptions;
  targetOptions.nodeId = options.nodeId;
  targetOptions.storagePath = options.storagePath;
  targetOptions.bitRate = &bitRate;
  std::unique_ptr<DeviceTarget> target =
      createDevice(*findDevice(options.device), transmitter, targetOptions, &error);
  if (!target) {
    std::fprintf(stderr, "costa-slave: %s\n", error.c_str());
    return 1;
  }
  tracer.attach(target.get());
  ControlSocket control;
  if (!options.controlPath.empty() && !control.open(options.controlPath, &error)) {
    std::fprintf(stderr, "costa-slave: %s\n", error.c_str());
    return 1;
  }

  const sigset_t waiting = catchStopSignals();
  target->start(nodeTime(clock));
  std::fprintf(stderr, "costa-slave: %s on %s, node-id %u\n", options.device.c_str(),
               options.interfaceName.c_str(), target->node().nodeId());

  while (stopRequested == 0) {
    const Microseconds now = nodeTime(clock);
    const Microseconds deadline = target->process(now);
    const int timeout = timeoutMilliseconds(deadline, nodeTime(clock), target->node().txPending());
    pollfd descriptors[2] = {{socket.fd(), POLLIN, 0}, {control.fd(), POLLIN, 0}};
    const timespec wait{timeout / 1000, (timeout % 1000) * 1000000L};
    const nfds_t count = control.fd() >= 0 ? 2U : 1U;
    const int ready = ppoll(descriptors, count, &wait, &waiting);  // signals arrive only here
    if (ready > 0 && count == 2U && (descriptors[1].revents & POLLIN) != 0) {
      control.serve([&](const std::string& command) {
        std::fprintf(stderr, "costa-slave: control: %s\n", command.c_str());
        return target->control(command);
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
      receiveFrames(socket, tracer, *target, clock);
    }
    if (target->node().txPending()) {
      target->node().flushTx();
    }
    tracer.counters(countersOf(target->node(), socket.counters()));
  }
  std::fprintf(stderr, "costa-slave: stopped: %s\n",
               describeCounters(countersOf(target->node(), socket.counters())).c_str());
  return 0;
}

}  // namespace costa::host
