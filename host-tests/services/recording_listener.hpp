// A node listener that writes down every event it hears, one short line each, in order.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include "costa/node_events.hpp"

namespace costa::test {

class RecordingListener final : public NodeEvents {
 public:
  void onNmtStateChanged(NmtState previous, NmtState current) noexcept override {
    add(std::string("state ") + describe(previous) + " -> " + describe(current));
  }
  void onResetApplication() noexcept override { add("reset application"); }
  void onResetCommunication() noexcept override { add("reset communication"); }
  void onRpdoWriting(uint16_t communicationIndex) noexcept override {
    add("rpdo writing", communicationIndex);
  }
  void onRpdoReceived(uint16_t communicationIndex) noexcept override {
    add("rpdo received", communicationIndex);
  }
  void onRpdoTimeout(uint16_t communicationIndex) noexcept override {
    add("rpdo timeout", communicationIndex);
  }
  void onSync(uint8_t counter) noexcept override { add("sync", counter); }
  void onHeartbeatTimeout(uint8_t nodeId) noexcept override { add("heartbeat timeout", nodeId); }
  void onHeartbeatResumed(uint8_t nodeId) noexcept override { add("heartbeat resumed", nodeId); }
  void onHeartbeatWithdrawn(uint8_t nodeId) noexcept override {
    add("heartbeat withdrawn", nodeId);
  }
  void onLifeGuardingExpired() noexcept override { add("life guarding expired"); }
  void onLifeGuardingResumed() noexcept override { add("life guarding resumed"); }
  void onBusOff() noexcept override { add("bus-off"); }
  void onBusOffRecovered() noexcept override { add("bus-off recovered"); }

  /// The events since the last call; they count as read then.
  std::vector<std::string> take() {
    std::vector<std::string> result;
    result.swap(events_);
    return result;
  }

 private:
  void add(const std::string& event) { events_.push_back(event); }
  /// `event` and `number` in upper-case hexadecimal ("rpdo received 1400").
  void add(const char* event, unsigned number) {
    std::string digits;
    do {
      digits.insert(digits.begin(), "0123456789ABCDEF"[number & 0xFU]);
      number >>= 4U;
    } while (number != 0U);
    events_.push_back(std::string(event) + " " + digits);
  }

  std::vector<std::string> events_;
};

}  // namespace costa::test
