// Which service a received frame belongs to: a table from CAN-ID to service, built when the
// node's CAN-IDs change (reset communication, a new PDO or SYNC COB-ID), so that a frame reaches
// its service through one lookup instead of a chain of tests.
//
// The error control CAN-IDs (0x701..0x77F: heartbeats of other nodes, node guarding requests)
// are a range and are not in the table; the node tests them before looking up.
//
// Context: the one that runs the node. No allocation: entries live in caller-owned storage
// (NodeMemory::routes). find() is O(log n) in the entries; add() O(n) (sorted insertion).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// Services a frame can be routed to.
enum class Route : uint8_t {
  kNmt,          ///< NMT command (0x000)
  kSync,         ///< SYNC (consumer)
  kSdo,          ///< SDO request to the node's server
  kLss,          ///< LSS master request (0x7E5)
  kRpdo,         ///< an RPDO; `channel` is its RpdoChannel
  kTpdoRequest,  ///< a remote request for a TPDO; `channel` is its TpdoChannel
};

struct RouteEntry {
  uint16_t id = 0;
  Route route = Route::kNmt;
  uint8_t channel = 0;
};

class FrameRouter {
 public:
  FrameRouter(RouteEntry* slots, size_t capacity) noexcept : slots_(slots), capacity_(capacity) {}

  /// Empties the table.
  void clear() noexcept {
    count_ = 0;
    stale_ = false;
  }
  /// Adds a route, keeping the table sorted by CAN-ID (routes with one id stay in the order they
  /// were added). False when the table is full (the capacity covers every service and PDO of
  /// the node, so this does not happen for a node's own table).
  bool add(uint16_t id, Route route, uint8_t channel = 0) noexcept;

  /// The first route of `id`, or null. The routes of one id follow it up to end().
  const RouteEntry* find(uint32_t id) const noexcept {
    size_t low = 0;
    size_t high = count_;
    while (low < high) {
      const size_t middle = (low + high) / 2U;
      if (slots_[middle].id < id) {
        low = middle + 1U;
      } else {
        high = middle;
      }
    }
    return low < count_ && slots_[low].id == id ? &slots_[low] : nullptr;
  }
  const RouteEntry* end() const noexcept { return slots_ + count_; }

  /// The node's CAN-IDs changed: rebuild before the next lookup.
  void invalidate() noexcept { stale_ = true; }
  bool stale() const noexcept { return stale_; }
  size_t size() const noexcept { return count_; }

 private:
  RouteEntry* slots_;
  size_t capacity_;
  size_t count_ = 0;
  bool stale_ = true;
};

}  // namespace costa
