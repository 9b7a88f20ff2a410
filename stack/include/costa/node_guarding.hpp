// Node guarding and life guarding (CiA 301 7.2.8.3.1): the reply to a remote request on
// 0x700+id, the toggle bit, and the life time 0x100C × 0x100D.
#pragma once

#include <stdint.h>

#include "costa/nmt_state.hpp"
#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class NodeGuarding : public ObjectHook {
 public:
  static constexpr uint16_t kGuardTimeIndex = 0x100C;
  static constexpr uint16_t kLifeTimeFactorIndex = 0x100D;

  enum class Event : uint8_t { kNone, kLifeTimeExpired, kResumed };

  NodeGuarding(od::ObjectDictionary& dictionary, TransmitPath& tx, NodeClock& clock) noexcept
      : dictionary_(dictionary), tx_(tx), clock_(clock) {}

  /// Reset communication: the toggle bit restarts at `toggleStart`; life guarding stops until
  /// the next request.
  void reset(uint8_t nodeId, uint8_t toggleStart) noexcept;

  /// A remote request on 0x700+id: replies state | toggle << 7 and toggles; (re)starts the
  /// life time. Returns kResumed when guarding resumes after an expiry.
  Event onRequest(NmtState state, Microseconds now) noexcept;
  /// Returns kLifeTimeExpired once when no request came within the life time. When the
  /// heartbeat producer time (0x1017) is not 0 by then, life guarding stops instead: the node
  /// no longer answers requests while it sends heartbeats.
  Event process(Microseconds now) noexcept;
  /// A request the node does not answer (the heartbeat producer runs): life guarding stops
  /// until the next answered request; an expiry already reported stays until then.
  void ignoreRequest() noexcept {
    guarded_ = false;
    life_.stop();
  }
  Microseconds nextDeadline() const noexcept { return expired_ ? kNever : life_.next(); }
  bool expired() const noexcept { return expired_; }

  /// 0x100C/0x100D writes restart the life time with the new values.
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  uint64_t lifeTime() const noexcept;
  void restartLife(Microseconds now) noexcept;

  od::ObjectDictionary& dictionary_;
  TransmitPath& tx_;
  NodeClock& clock_;
  uint8_t nodeId_ = 0;
  uint8_t toggle_ = 0;
  bool guarded_ = false;
  bool expired_ = false;
  LongTimer life_;  ///< the node life time, from the latest guarding request
};

}  // namespace costa
