#include "socket_bus.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>

namespace costa::test {

SocketBus::SocketBus(const std::string& device, int nodeId, const std::vector<std::string>& extra) {
  std::vector<std::string> arguments;
  if (nodeId >= 0) {
    arguments.insert(arguments.end(), {"--node-id", std::to_string(nodeId)});
  }
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  arguments.push_back(device);
  start(arguments);
}

SocketBus::SocketBus(const SlaveNodes& nodes, const std::vector<std::string>& extra) {
  std::vector<std::string> arguments = extra;
  arguments.insert(arguments.end(), nodes.nodes.begin(), nodes.nodes.end());
  start(arguments);
}

void SocketBus::start(const std::vector<std::string>& arguments) {
  if (!socket_.open(testInterface(), &error_)) {
    return;
  }
  static std::atomic<int> counter{0};
  controlPath_ = "/tmp/costa-control-" + std::to_string(::getpid()) + "-" +
                 std::to_string(counter.fetch_add(1));
  std::vector<std::string> all = {"--iface", testInterface(), "--control", controlPath_};
  all.insert(all.end(), arguments.begin(), arguments.end());
  slave_ = std::make_unique<SlaveProcess>(all);
}

void SocketBus::send(const CanFrame& frame) {
  socket_.send(frame);
  lastOnBus_ = std::chrono::steady_clock::now();
}

bool SocketBus::receive(CanFrame* frame, int timeoutMs) {
  return socket_.receive(frame, timeoutMs, &lastOnBus_);
}

std::string SocketBus::simulate(const std::string& command) {
  const int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    return "cannot create a socket";
  }
  sockaddr_un own{};
  own.sun_family = AF_UNIX;
  ::bind(fd, reinterpret_cast<sockaddr*>(&own), sizeof(sa_family_t));  // autobind: replies
  sockaddr_un target{};
  target.sun_family = AF_UNIX;
  std::memcpy(target.sun_path, controlPath_.c_str(), controlPath_.size());
  std::string result = "costa-slave did not answer on " + controlPath_;
  const auto end =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(kSlaveExitTimeoutMs);
  while (std::chrono::steady_clock::now() < end) {
    if (::sendto(fd, command.data(), command.size(), 0, reinterpret_cast<sockaddr*>(&target),
                 sizeof(target)) < 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // not listening yet
      continue;
    }
    pollfd descriptor{fd, POLLIN, 0};
    if (::poll(&descriptor, 1, kSocketReceiveTimeoutMs) > 0) {
      char reply[512];
      const ssize_t got = ::recv(fd, reply, sizeof(reply), 0);
      const std::string text(reply, got > 0 ? static_cast<size_t>(got) : 0U);
      result = text == "ok" ? "" : text;
    }
    break;
  }
  ::close(fd);
  lastOnBus_ = std::chrono::steady_clock::now();
  return result;
}

void SocketBus::wait(uint64_t milliseconds) {
  lastOnBus_ += std::chrono::milliseconds(milliseconds);
  std::this_thread::sleep_until(lastOnBus_);
}

}  // namespace costa::test
