// Bounded FIFO of frames waiting for the CAN controller.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/can_frame.hpp"

namespace costa {

/// Ring buffer over caller-owned storage. Push never blocks: when full, the frame is dropped and
/// counted. O(1) per operation, no allocation.
class TxQueue {
 public:
  TxQueue(CanFrame* storage, size_t capacity) noexcept : slots_(storage), capacity_(capacity) {}

  /// Appends a frame. Returns false (and counts a drop) when full.
  bool push(const CanFrame& frame) noexcept {
    if (count_ == capacity_) {
      ++dropped_;
      return false;
    }
    slots_[(head_ + count_) % capacity_] = frame;
    ++count_;
    return true;
  }

  bool empty() const noexcept { return count_ == 0U; }
  size_t size() const noexcept { return count_; }
  size_t capacity() const noexcept { return capacity_; }
  const CanFrame& front() const noexcept { return slots_[head_]; }

  void pop() noexcept {
    if (count_ != 0U) {
      head_ = (head_ + 1U) % capacity_;
      --count_;
    }
  }

  void clear() noexcept {
    head_ = 0;
    count_ = 0;
  }

  /// Frames refused because the queue was full, since construction.
  uint32_t dropped() const noexcept { return dropped_; }

 private:
  CanFrame* slots_;
  size_t capacity_;
  size_t head_ = 0;
  size_t count_ = 0;
  uint32_t dropped_ = 0;
};

}  // namespace costa
