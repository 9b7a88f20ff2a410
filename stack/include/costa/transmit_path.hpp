// The node's way to the CAN controller. A frame goes to the controller at once when nothing
// waits ahead of it and transmission is allowed; the bounded queue holds only what the
// controller refused (or what waits while transmission is held), so frames leave in the order
// the services produced them.
//
// Gates hold transmission: a bus-off (until the driver reports the recovery) and the LSS bit
// timing switch (between activate bit timing and the end of its second delay). While a gate is
// closed, frames are queued, and flush() sends them once every gate is open.
//
// Context: the one that runs the node (main loop), never an interrupt. No allocation; send() is
// O(1) plus the controller's tryTransmit(), flush() O(frames sent).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/port/can_port.hpp"
#include "costa/time.hpp"
#include "costa/tx_queue.hpp"

namespace costa {

class TransmitPath {
 public:
  /// Reasons to hold transmission.
  enum Gate : uint8_t {
    kBusOff = 1U << 0,     ///< the controller is bus-off
    kBitTiming = 1U << 1,  ///< an LSS bit timing switch is running
  };

  TransmitPath(CanTransmitter& can, QueuedFrame* slots, size_t capacity) noexcept
      : can_(can), queue_(slots, capacity) {}

  /// Sends `frame` now, or queues it behind earlier frames (or while a gate is closed, or when
  /// the controller refuses it). A synchronous PDO passes the end of its SYNC window as `expiry`:
  /// queued, it is dropped (and counted) if it cannot leave by then. A full queue drops the
  /// frame and counts it (dropped()).
  COSTA_SHARED_INLINE void send(const CanFrame& frame, Microseconds expiry = kNever) noexcept {
    if (queue_.empty() && gates_ == 0U) {
      if (can_.tryTransmit(frame)) {
        return;
      }
      ++refused_;
    }
    queue_.push(frame, expiry);
  }

  /// send() of the 11-bit data frame `id` carrying `length` (0..8) bytes of `data`, zeros after
  /// them: the frame built in one place for the services whose frames are their data alone
  /// (heartbeat and boot-up, node guarding, SYNC, EMCY, TIME, LSS).
  void send(uint32_t id, const uint8_t* data, uint8_t length) noexcept;

  /// Offers queued frames to the controller, oldest first, until it refuses one or a gate is
  /// closed; frames whose expiry is before `now` are dropped (expired()).
  void flush(Microseconds now) noexcept;

  /// Discards every queued frame (reset communication: what was waiting belongs to the state
  /// the node leaves). Counted in discarded().
  void discardQueued() noexcept { discarded_ += static_cast<uint32_t>(queue_.clear()); }

  /// Opens or closes a gate. Opening does not send by itself: the caller flushes.
  void setGate(Gate gate, bool closed) noexcept {
    gates_ = closed ? static_cast<uint8_t>(gates_ | gate) : static_cast<uint8_t>(gates_ & ~gate);
  }
  bool held() const noexcept { return gates_ != 0U; }

  /// Frames wait in the queue.
  bool pending() const noexcept { return !queue_.empty(); }
  size_t queued() const noexcept { return queue_.size(); }
  /// Whether a burst (block upload segments) may send another frame: a quarter of the queue
  /// stays free for the other services (heartbeat, emergency).
  bool roomForBurst() const noexcept {
    return queue_.size() < queue_.capacity() - queue_.capacity() / 4U;
  }

  /// Times the controller refused a frame (kept and offered again), since construction.
  uint32_t refused() const noexcept { return refused_; }
  /// Frames lost to a full queue.
  uint32_t dropped() const noexcept { return queue_.dropped(); }
  /// Synchronous PDOs that missed their SYNC window while queued.
  uint32_t expired() const noexcept { return queue_.expired(); }
  /// Frames discarded by discardQueued().
  uint32_t discarded() const noexcept { return discarded_; }

 private:
  CanTransmitter& can_;
  TxQueue queue_;
  uint8_t gates_ = 0;
  uint32_t refused_ = 0;
  uint32_t discarded_ = 0;
};

}  // namespace costa
