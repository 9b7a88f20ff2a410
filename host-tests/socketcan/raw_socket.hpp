// A test client's own raw SocketCAN socket.
#pragma once

#include <stdint.h>

#include <chrono>
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
  /// Sends an error frame as a driver reports one: CAN_ERR_FLAG | `errorClass`, 8 bytes with
  /// `controller` (CAN_ERR_CRTL_*) in data[1]. Other sockets on the interface that asked for
  /// error frames receive it.
  bool sendErrorFrame(uint32_t errorClass, uint8_t controller);
  /// Waits up to `timeoutMs` for a frame. `onBus`, when given, receives the moment the frame
  /// went onto the interface (the kernel's time stamp) on the steady clock: earlier than the
  /// return when this process was slow to read it.
  bool receive(CanFrame* frame, int timeoutMs,
               std::chrono::steady_clock::time_point* onBus = nullptr);

 private:
  int fd_ = -1;
};

/// The interface the SocketCAN tests use: $COSTA_TEST_IFACE or vcan0.
std::string testInterface();

}  // namespace costa::test
