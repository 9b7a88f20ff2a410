#include "socket_bus.hpp"

#include <chrono>
#include <thread>

namespace costa::test {

SocketBus::SocketBus(const std::string& device, int nodeId, const std::vector<std::string>& extra) {
  if (!socket_.open(testInterface(), &error_)) {
    return;
  }
  std::vector<std::string> arguments = {"--iface", testInterface(), "--node-id",
                                        std::to_string(nodeId)};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  arguments.push_back(device);
  slave_ = std::make_unique<SlaveProcess>(arguments);
}

void SocketBus::send(const CanFrame& frame) {
  socket_.send(frame);
}

bool SocketBus::receive(CanFrame* frame, int timeoutMs) {
  return socket_.receive(frame, timeoutMs);
}

void SocketBus::wait(uint64_t milliseconds) {
  std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
}

}  // namespace costa::test
