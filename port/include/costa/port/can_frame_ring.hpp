// A lock-free ring of received CAN frames between one producer and one consumer: how a port
// hands frames from its receive interrupt to the context that runs the node.
//
//   receive interrupt:  while (controller has a frame) ring.push(frame);      // producer
//   main loop:          while (ring.pop(&frame)) node.onFrame(frame, now);    // consumer
//
// Exactly one context calls push() and exactly one (another) calls pop(), empty(),
// takeOverrun(); neither blocks nor disables interrupts. The indices are 32-bit atomics written
// by one side each (plain loads and stores with acquire/release ordering, no read-modify-write),
// so the ring works on cores without exclusive access instructions (Cortex-M0/M0+: there
// is_always_lock_free is false, as read-modify-write would need a library, but a load or a
// store is one instruction and a barrier) and between two threads on a host. A frame is copied in
// whole before the producer publishes it, and copied out whole before the consumer frees its slot.
//
// When the ring is full, push() drops the new frame and counts it; the consumer learns of it
// through takeOverrun() and tells the node (Node::onControllerEvent(kRxOverrun), CiA 301 EMCY
// 0x8110), as for an overrun of the controller's own FIFO.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <atomic>

#include "costa/port/can_frame.hpp"

namespace costa::port {

/// `Capacity` frames (a power of two, at least 2); RAM: Capacity x sizeof(CanFrame) + 16 bytes.
template <size_t Capacity>
class CanFrameRing {
  static_assert(Capacity >= 2U && (Capacity & (Capacity - 1U)) == 0U,
                "the capacity is a power of two (the indices wrap at 2^32)");
  static_assert(Capacity <= (size_t{1} << 31U), "the capacity fits the 32-bit indices");

 public:
  static constexpr size_t kCapacity = Capacity;

  // --- Producer (the receive interrupt) --------------------------------------------------------
  /// Appends a copy of `frame`. False when the ring is full: the frame is dropped and counted.
  bool push(const CanFrame& frame) noexcept {
    const uint32_t head = head_.load(std::memory_order_relaxed);  // written only here
    if (head - tail_.load(std::memory_order_acquire) == Capacity) {
      dropped_.store(dropped_.load(std::memory_order_relaxed) + 1U, std::memory_order_release);
      return false;
    }
    slots_[head & kMask] = frame;
    head_.store(head + 1U, std::memory_order_release);  // publishes the slot
    return true;
  }

  // --- Consumer (the context that runs the node) -----------------------------------------------
  /// Takes the oldest frame. False when the ring is empty.
  bool pop(CanFrame* frame) noexcept {
    const uint32_t tail = tail_.load(std::memory_order_relaxed);  // written only here
    if (head_.load(std::memory_order_acquire) == tail) {
      return false;
    }
    *frame = slots_[tail & kMask];
    tail_.store(tail + 1U, std::memory_order_release);  // frees the slot
    return true;
  }
  bool empty() const noexcept {
    return head_.load(std::memory_order_acquire) == tail_.load(std::memory_order_relaxed);
  }
  /// True once after frames were dropped since the last call (how many: dropped()).
  bool takeOverrun() noexcept {
    const uint32_t dropped = dropped_.load(std::memory_order_acquire);
    const bool overrun = dropped != reported_;
    reported_ = dropped;
    return overrun;
  }
  /// Frames dropped because the ring was full, since power-on (wraps at 2^32).
  uint32_t dropped() const noexcept { return dropped_.load(std::memory_order_acquire); }

 private:
  static constexpr uint32_t kMask = static_cast<uint32_t>(Capacity - 1U);

  CanFrame slots_[Capacity] = {};
  std::atomic<uint32_t> head_{0};     ///< frames pushed (producer)
  std::atomic<uint32_t> tail_{0};     ///< frames popped (consumer)
  std::atomic<uint32_t> dropped_{0};  ///< frames dropped (producer)
  uint32_t reported_ = 0;             ///< dropped_ at the last takeOverrun() (consumer)
};

}  // namespace costa::port
