// A raw SocketCAN socket as the node's CAN controller.
#pragma once

#include <stdint.h>

#include <string>

#include "costa/port/can_bit_rate.hpp"
#include "costa/port/can_port.hpp"
#include "costa/port/linux/socketcan_error_frames.hpp"

namespace costa::port {

/// Owns one non-blocking CAN_RAW socket bound to an interface. Receives data frames, RTR frames
/// and the error frames of controller state changes (CAN_ERR_CRTL, CAN_ERR_BUSOFF,
/// CAN_ERR_RESTARTED: counted, and reported as controller events); transmits without blocking.
///
/// Bit rate: a socket cannot set it. A virtual interface (vcan) has none, and a real one's is
/// set by the system (`ip link set can0 down; ip link set can0 type can bitrate 500000; ip link
/// set can0 up`, which needs CAP_NET_ADMIN). setBitRate() therefore only records the rate the
/// node asked for (see bitRate()) and reports success, so that the node's view of its bit
/// timing follows LSS and its stored configuration as on a controller it can re-time; the
/// interface's rate is not changed.
class SocketCanPort final : public CanTransmitter, public CanBitRateControl {
 public:
  enum class Received { kFrame, kErrorFrame, kNothing, kFailed };

  struct Counters {
    uint64_t received = 0;
    uint64_t transmitted = 0;
    uint64_t refused = 0;      ///< Writes refused by a full queue (retried by the node).
    uint64_t errorFrames = 0;  ///< Error frames reported by the driver.
  };

  SocketCanPort() = default;
  ~SocketCanPort();
  SocketCanPort(const SocketCanPort&) = delete;
  SocketCanPort& operator=(const SocketCanPort&) = delete;

  /// Opens and binds the socket. On failure returns false and sets `error` to one line saying
  /// why (no SocketCAN in the kernel, no such interface, ...).
  bool open(const std::string& interfaceName, std::string* error);
  void close() noexcept;
  int fd() const noexcept { return fd_; }

  bool tryTransmit(const CanFrame& frame) noexcept override;

  /// Reads one frame if one is waiting. Error frames are counted and returned as kErrorFrame,
  /// with the controller events they report (controllerEventsOf) in `events`.
  Received receive(CanFrame* frame, SocketCanEvents* events = nullptr) noexcept;

  const Counters& counters() const noexcept { return counters_; }

  /// Records `bitsPerSecond` as the rate the node now expects; changes nothing on the
  /// interface (see the class comment). True for every non-zero rate.
  bool setBitRate(uint32_t bitsPerSecond) noexcept override;
  /// The rate last given to setBitRate(), in bit/s; 0 before the first.
  uint32_t bitRate() const noexcept { return bitRate_; }

 private:
  int fd_ = -1;
  uint32_t bitRate_ = 0;
  Counters counters_;
  SocketCanErrorState errorState_;
};

}  // namespace costa::port
