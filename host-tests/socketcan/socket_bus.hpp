// costa-slave on a vcan interface, as a TranscriptBus: the test's raw socket sends the `rx`
// frames and receives what the slave sends; time is real.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "raw_socket.hpp"
#include "slave_process.hpp"
#include "transcript_player.hpp"

namespace costa::test {

/// Several nodes of one costa-slave: DEVICE[@NODE-ID] each.
struct SlaveNodes {
  std::vector<std::string> nodes;
};

class SocketBus : public TranscriptBus {
 public:
  /// Opens the test socket first (so the boot-up frame is seen), then starts costa-slave with
  /// `--iface <testInterface()> --node-id <nodeId> <extra...> <device>`; without `--node-id`
  /// when `nodeId` is negative (the device's own or stored node-id).
  SocketBus(const std::string& device, int nodeId, const std::vector<std::string>& extra = {});
  /// Starts one costa-slave running `nodes`: `--iface <testInterface()> <extra...> <nodes...>`.
  explicit SocketBus(const SlaveNodes& nodes, const std::vector<std::string>& extra = {});

  /// Empty when the bus is usable, else why not.
  const std::string& error() const { return error_; }

  void send(const CanFrame& frame) override;
  bool receive(CanFrame* frame, int timeoutMs) override;
  /// Lets `milliseconds` pass from the last thing on the bus (a frame sent, the time stamp of
  /// a frame received, the end of a command or of the previous wait), as a transcript means it,
  /// not from the moment this process gets to it: a test thread slow to read a heartbeat does
  /// not push the next request later in the slave's cycle.
  void wait(uint64_t milliseconds) override;
  bool checksTiming() const override { return false; }
  /// Sends the command to costa-slave's --control socket and waits for its answer.
  std::string simulate(const std::string& command) override;

  SlaveProcess& slave() { return *slave_; }
  /// Sends an error frame to costa-slave (RawCanSocket::sendErrorFrame).
  bool sendErrorFrame(uint32_t errorClass, uint8_t controller) {
    return socket_.sendErrorFrame(errorClass, controller);
  }

 private:
  void start(const std::vector<std::string>& arguments);

  RawCanSocket socket_;
  std::unique_ptr<SlaveProcess> slave_;
  std::string controlPath_;
  std::string error_;
  std::chrono::steady_clock::time_point lastOnBus_ = std::chrono::steady_clock::now();
};

/// Milliseconds to wait for each expected frame over SocketCAN. Generous: the suite may run in
/// an emulated machine on a busy host, where a sanitized costa-slave has taken more than 3 s
/// to send its boot-up; a passing test never waits this long.
inline constexpr int kSocketReceiveTimeoutMs = 20000;

}  // namespace costa::test
