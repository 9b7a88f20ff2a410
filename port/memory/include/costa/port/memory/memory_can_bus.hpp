// A CAN bus in memory: several endpoints (nodes, test clients) see each other's frames.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/can_port.hpp"

namespace costa::port {

class MemoryCanBus;

/// One station on a MemoryCanBus. Frames it transmits reach every other endpoint; frames from
/// the others wait in its inbox until taken.
class MemoryCanEndpoint : public CanTransmitter {
 public:
  static constexpr size_t kInboxCapacity = 1024;

  bool tryTransmit(const CanFrame& frame) noexcept override;

  /// Takes the oldest received frame; false when the inbox is empty.
  bool receive(CanFrame* frame) noexcept;
  size_t pending() const noexcept { return count_; }
  /// Frames lost because the inbox was full.
  uint32_t overruns() const noexcept { return overruns_; }

 private:
  friend class MemoryCanBus;
  void deliver(const CanFrame& frame) noexcept;

  MemoryCanBus* bus_ = nullptr;
  CanFrame inbox_[kInboxCapacity];
  size_t head_ = 0;
  size_t count_ = 0;
  uint32_t overruns_ = 0;
};

/// Connects up to kMaxEndpoints endpoints. Delivery is immediate and in transmission order.
class MemoryCanBus {
 public:
  static constexpr size_t kMaxEndpoints = 16;

  /// Returns false when the bus is full.
  bool attach(MemoryCanEndpoint& endpoint) noexcept;
  void broadcast(const MemoryCanEndpoint& sender, const CanFrame& frame) noexcept;

 private:
  MemoryCanEndpoint* endpoints_[kMaxEndpoints] = {};
  size_t count_ = 0;
};

}  // namespace costa::port
