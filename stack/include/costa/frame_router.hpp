// Which service a received frame belongs to: a table from CAN-ID to service, built when the
// node's CAN-IDs change (reset communication, a new PDO or SYNC COB-ID), so that a frame reaches
// its service through one lookup instead of a chain of tests.
//
// The routes are sorted by CAN-ID and indexed by function code (the CAN-ID's top four bits, as
// CiA 301's pre-defined connection set assigns them), so a lookup looks at the few routes of
// one function code. The error control CAN-IDs (0x701..0x77F: heartbeats of other nodes, node
// guarding requests) are a range and are not in the table; the node tests them when the lookup
// finds no route.
//
// Context: the one that runs the node. No allocation: entries live in caller-owned storage
// (NodeMemory::routes). find() is O(routes of one function code); add() O(routes).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/hot_path.hpp"

namespace costa {

/// Services a frame can be routed to.
enum class Route : uint8_t {
  kNmt,          ///< NMT command (0x000)
  kSync,         ///< SYNC (consumer)
  kTime,         ///< TIME (consumer)
  kGfc,          ///< global fail-safe command (0x001, CiA 304)
  kSrdo,         ///< a receive SRDO's frame; `channel` is 2 x its slot, + 1 for the inverted
  kEmcy,         ///< another node's EMCY (consumer); `channel` is its sub-index of 0x1028
  kSdo,          ///< SDO request to the node's server
  kSdoServer,    ///< SDO request to an additional server; `channel` is its SdoServers index
  kLss,          ///< LSS master request (0x7E5)
  kRpdo,         ///< an RPDO; `channel` is its RpdoChannel
  kTpdoRequest,  ///< a remote request for a TPDO; `channel` is its TpdoChannel
};

struct alignas(4) RouteEntry {  // (4-byte aligned: copied as one word)
  uint16_t id = 0;
  Route route = Route::kNmt;
  uint8_t channel = 0;
};

class FrameRouter {
 public:
  static constexpr uint32_t kLargestId = 0x7FF;  ///< 11-bit identifiers only

  /// Over `capacity` slots, of which it uses at most 255 (the index holds 8-bit positions).
  FrameRouter(RouteEntry* slots, size_t capacity) noexcept
      : slots_(slots),
        capacity_(static_cast<uint8_t>(capacity < UINT8_MAX ? capacity : UINT8_MAX)) {}

  /// Empties the table.
  void clear() noexcept {
    count_ = 0;
    shared_ = false;
    fastId_ = kNoFastId;
    __builtin_memset(first_, 0, sizeof(first_));  // one call: smaller than a loop on Thumb-1
    stale_ = false;
  }
  /// Adds a route (`id` <= kLargestId), keeping the table sorted by CAN-ID (routes with one id
  /// stay in the order they were added). False when the table is full (the capacity covers
  /// every service and PDO of the node, so this does not happen for a node's own table).
  bool add(uint16_t id, Route route, uint8_t channel = 0) noexcept;

  /// The first route of `id` (<= kLargestId), or null. O(routes with the same function code).
  const RouteEntry* find(uint32_t id) const noexcept {
    const size_t code = id >> 7U;
    for (size_t i = first_[code]; i < first_[code + 1U]; ++i) {
      if (slots_[i].id == id) {
        return &slots_[i];
      }
    }
    return nullptr;
  }
  /// The route after `entry` when it has the same CAN-ID, else null.
  const RouteEntry* nextOfSameId(const RouteEntry* entry) const noexcept {
    if (!shared_) {
      return nullptr;  // the usual table: one route per CAN-ID
    }
    const RouteEntry* next = entry + 1;
    return next != slots_ + count_ && next->id == entry->id ? next : nullptr;
  }

  /// Some CAN-ID has more than one route.
  bool shared() const noexcept { return shared_; }

  /// A CAN-ID whose frames may skip the lookup: `id`'s one route is `route`, which the caller
  /// takes on its own (Node::onFrame: the requests to its SDO server, which come in bursts of
  /// segments). Holds until the table is cleared or invalidated. False, and no fast CAN-ID, when
  /// `id` has no route, another one, or several.
  bool setFastId(uint32_t id, Route route) noexcept {
    const RouteEntry* entry = id <= kLargestId ? find(id) : nullptr;
    const bool single = entry != nullptr && entry->route == route && nextOfSameId(entry) == nullptr;
    fastId_ = single ? id : kNoFastId;
    return single;
  }
  /// The CAN-ID of setFastId() while the table is fresh, else kNoFastId (beyond 11 and 29 bits:
  /// a caller that compares a frame's identifier with it also checks the frame's bound).
  uint32_t fastId() const noexcept { return fastId_; }
  static constexpr uint32_t kNoFastId = UINT32_MAX;

  /// The node's CAN-IDs changed: rebuild before the next lookup.
  COSTA_SHARED_INLINE void invalidate() noexcept {
    stale_ = true;
    fastId_ = kNoFastId;
    ++changes_;
  }
  /// How many times the CAN-IDs changed (invalidate()): a port compares it with the value it
  /// saw when it programmed its acceptance filters.
  uint32_t changes() const noexcept { return changes_; }
  bool stale() const noexcept { return stale_; }
  size_t size() const noexcept { return count_; }
  /// The route at `index` (< size()), in CAN-ID order.
  const RouteEntry& at(size_t index) const noexcept { return slots_[index]; }

 private:
  static constexpr size_t kFunctionCodes = 16;

  RouteEntry* slots_;
  uint8_t capacity_;  ///< at most UINT8_MAX
  uint8_t count_ = 0;
  // (the flags before the index, within reach of Thumb-1's short offsets: every frame reads them)
  bool stale_ = true;
  bool shared_ = false;  ///< some CAN-ID has more than one route
  /// first_[c]: the index of the first route of function code c; first_[16] = count_.
  uint8_t first_[kFunctionCodes + 1U] = {};
  uint32_t changes_ = 0;
  uint32_t fastId_ = kNoFastId;
};

}  // namespace costa
