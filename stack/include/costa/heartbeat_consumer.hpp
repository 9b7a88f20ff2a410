// Heartbeat consumer (CiA 301 7.2.8.3.2.2, object 0x1016): monitors other nodes' heartbeats.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/nmt_state.hpp"
#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"

namespace costa {

/// State of one consumer entry (sub-index n of 0x1016).
struct HeartbeatMonitor {
  uint8_t nodeId = 0;     ///< 0: entry disabled
  Microseconds time = 0;  ///< 0: entry disabled
  bool active = false;    ///< a heartbeat has been received since configuration
  bool timedOut = false;
  /// The producer of an entry that had timed out, then got a new value: the error it found is
  /// to be cleared (a kWithdrawn event). 0: none (node-id 0 is never a producer's).
  uint8_t withdrawnFrom = 0;
  Microseconds deadline = kNever;
  uint8_t lastState = 0;
};

class HeartbeatConsumer : public ObjectHook {
 public:
  static constexpr uint16_t kIndex = 0x1016;

  /// kWithdrawn: an entry that had timed out has a new value (its error goes with the old one).
  enum class EventKind : uint8_t { kNone, kTimeout, kResumed, kWithdrawn };
  struct Event {
    EventKind kind = EventKind::kNone;
    uint8_t nodeId = 0;  ///< the producer (for kWithdrawn: the one the entry monitored before)
    uint8_t entry = 0;   ///< sub-index of 0x1016
  };

  HeartbeatConsumer(od::ObjectDictionary& dictionary, NodeClock& clock, HeartbeatMonitor* monitors,
                    size_t capacity) noexcept
      : dictionary_(dictionary), clock_(clock), monitors_(monitors), capacity_(capacity) {}

  /// Reads every entry of 0x1016; monitoring of an entry starts at its first heartbeat. With
  /// `reset` every entry starts over; otherwise only entries whose value changed, and those of
  /// them that had timed out are withdrawn (a kWithdrawn event at the next process()).
  void configure(bool reset) noexcept;

  /// A heartbeat (or boot-up) frame from `nodeId`. Returns kResumed for an entry that had timed
  /// out (the first such entry).
  Event onHeartbeat(uint8_t nodeId, uint8_t state, Microseconds now) noexcept;
  /// Returns one event per call, entry by entry: kWithdrawn for a withdrawn entry, kTimeout
  /// for one whose time has passed. Call until kNone.
  Event process(Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept;

  const HeartbeatMonitor* monitor(uint8_t subIndex) const noexcept;

  /// 0x1016 writes: two enabled entries for the same node-id abort 0x06040043. A write
  /// configures the entries (configure(false)) and asks for a process() at once.
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  od::ObjectDictionary& dictionary_;
  NodeClock& clock_;
  HeartbeatMonitor* monitors_;
  size_t capacity_;
  size_t count_ = 0;
};

}  // namespace costa
