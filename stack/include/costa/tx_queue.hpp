// Bounded FIFO of frames waiting for the CAN controller (the part of TransmitPath that holds
// what the controller refused).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"

namespace costa {

/// A queued frame and the time after which it is no longer worth sending (synchronous PDOs
/// whose SYNC window has passed); kNever for most frames. TxQueue::push() sets both, and a slot
/// is never read before: its initial value is zero, so that a block of slots needs no set-up.
struct QueuedFrame {
  CanFrame frame;
  Microseconds expiry = 0;
};

/// Ring buffer over caller-owned storage. Push never blocks: when full, the frame is dropped and
/// counted. O(1) per operation (no division), no allocation. Context: the one that runs the node.
class TxQueue {
 public:
  TxQueue(QueuedFrame* storage, size_t capacity) noexcept : slots_(storage), capacity_(capacity) {}

  /// Appends a frame. Returns false (and counts a drop) when full.
  bool push(const CanFrame& frame, Microseconds expiry = kNever) noexcept {
    if (count_ == capacity_) {
      ++dropped_;
      return false;
    }
    size_t tail = head_ + count_;
    if (tail >= capacity_) {
      tail -= capacity_;
    }
    QueuedFrame& slot = slots_[tail];
    slot.frame = frame;
    slot.expiry = expiry;
    ++count_;
    return true;
  }

  bool empty() const noexcept { return count_ == 0U; }
  size_t size() const noexcept { return count_; }
  size_t capacity() const noexcept { return capacity_; }
  const QueuedFrame& front() const noexcept { return slots_[head_]; }

  void pop() noexcept {
    if (count_ != 0U) {
      head_ = head_ + 1U == capacity_ ? 0U : head_ + 1U;
      --count_;
    }
  }

  /// Removes the front frame because it expired before it could be sent.
  void expireFront() noexcept {
    pop();
    ++expired_;
  }

  /// Empties the queue; returns how many frames it held.
  size_t clear() noexcept {
    const size_t held = count_;
    head_ = 0;
    count_ = 0;
    return held;
  }

  /// Frames refused because the queue was full, since construction.
  uint32_t dropped() const noexcept { return dropped_; }
  /// Frames discarded because their deadline passed while they waited.
  uint32_t expired() const noexcept { return expired_; }

 private:
  QueuedFrame* slots_;
  size_t capacity_;
  size_t head_ = 0;
  size_t count_ = 0;
  uint32_t dropped_ = 0;
  uint32_t expired_ = 0;
};

}  // namespace costa
