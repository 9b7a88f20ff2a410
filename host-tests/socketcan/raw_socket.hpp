// A test client's own raw SocketCAN socket.
#pragma once

#include <string>

#include "costa/port/can_frame.hpp"

namespace costa::test {

class RawCanSocket {
 public:
  RawCanSocket() = default;
  ~RawCanSocket();
  RawCanSocket(const RawCanSocket&) = delete;
  RawCanSocket& operator=(const RawCanSocket&) = delete;

  /// Opens and binds; returns false with a reason.
  bool open(const std::string& interfaceName, std::string* error);
  bool send(const CanFrame& frame);
  /// Waits up to `timeoutMs` for a frame.
  bool receive(CanFrame* frame, int timeoutMs);

 private:
  int fd_ = -1;
};

/// The interface the SocketCAN tests use: $COSTA_TEST_IFACE or vcan0.
std::string testInterface();

}  // namespace costa::test
