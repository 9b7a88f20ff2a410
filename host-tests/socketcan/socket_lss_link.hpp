// An LSS master's link over a SocketCAN test's raw socket.
#pragma once

#include <chrono>

#include "lss_master.hpp"
#include "socket_bus.hpp"

namespace costa::test {

/// LSS master link over the test's raw socket: only LSS responses count as answers. A
/// Fastscan query without a matching slave has no answer, so the wait is the slave's chance to
/// answer: generous, for a slave process on a loaded machine or an emulated CPU. An answer that
/// comes after its wait is dropped before the next request, so it cannot pass for the next
/// query's.
class SocketLink : public LssMasterLink {
 public:
  static constexpr int kAnswerWaitMs = 250;

  explicit SocketLink(SocketBus& bus) : bus_(bus) {}
  void send(const CanFrame& frame) override {
    discardAnswers();
    bus_.send(frame);
  }
  /// Only what has arrived: a later answer is dropped by the next send().
  void discardAnswers() override {
    CanFrame late;
    while (bus_.receive(&late, 0)) {
    }
  }
  bool receive(CanFrame* frame) override {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(kAnswerWaitMs);
    while (std::chrono::steady_clock::now() < end) {
      if (bus_.receive(frame, kAnswerWaitMs) && frame->id == 0x7E4) {
        return true;
      }
    }
    return false;
  }

 private:
  SocketBus& bus_;
};

}  // namespace costa::test
