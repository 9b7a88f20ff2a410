// One transmit PDO (CiA 301 7.2.2): communication parameter 0x1800+n, mapping 0x1A00+n (or the
// device's static mapping), resolved into where each entry's bytes come from when configured.
//
// Context: the one that runs the node. No allocation. Sending is O(mapped entries): with a
// plain mapping a copy per entry straight into the frame, which goes to the controller at once
// when nothing waits ahead of it (TransmitPath).
#pragma once

#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/pdo_channel.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"

namespace costa {

class TpdoChannel : public PdoChannel {
 public:
  /// Gives the channel its communication object, before anything else is asked of it.
  void bind(uint16_t communicationIndex) noexcept {
    index_ = communicationIndex;
    inhibitUntil_ = kNever;
    eventDeadline_ = kNever;
  }

  /// Reads the communication parameters and resolves the mapping. The abort code of a mapping
  /// that could not be resolved (the PDO then carries nothing), else kNone.
  /// O(entries x log objects).
  AbortCode configure(PdoContext& context) noexcept;
  /// Resolves the mapping again (a hook was attached). Same result as configure().
  AbortCode resolveMapping(PdoContext& context) noexcept {
    return resolvePdoMapping(context, index_, &map_);
  }

  bool rtrAllowed() const noexcept { return rtrAllowed_; }
  bool eventDriven() const noexcept { return type_ >= 254U; }
  /// Events count for it: event-driven (254, 255) or acyclic synchronous (0, at the next SYNC).
  bool takesEvents() const noexcept { return type_ == 0U || eventDriven(); }
  /// Sends at SYNCs (types 0..240) or samples at them (252).
  bool synchronous() const noexcept { return type_ <= 240U || type_ == 252U; }

  /// Entering operational: SYNC counting restarts, the event timer starts, and an event-driven
  /// PDO is sent once when `initialEvent`.
  void start(PdoContext& context, Microseconds now, bool initialEvent) noexcept {
    begin(context, now, initialEvent && eventDriven(), kNever);
  }
  /// Reconfigured while operational (a parameter written): starts again like start(), but an
  /// event still waiting (while the PDO stays valid) and a running inhibit time are kept.
  void restart(PdoContext& context, Microseconds now) noexcept {
    // What a PDO made not valid had waiting is gone (and an old inhibit time would not expire);
    // type 0 sends what waits at the next SYNC still, and the transmission before the write
    // still inhibits the next.
    begin(context, now, event_ && valid_, valid_ ? inhibitUntil_ : kNever);
  }
  void stop() noexcept;

  /// A SYNC with `counter` (0 when the SYNC carries none), asked while running (as process()).
  /// Synchronous PDOs are sent with `expiry` (end of the SYNC window) so that they are dropped
  /// if they cannot go out in time.
  COSTA_HOT_INLINE void onSync(PdoContext& context, uint8_t counter, Microseconds now,
                               Microseconds expiry) noexcept {
    // Running, valid, synchronous cyclic and counting: the usual case, expanded where speed
    // counts; onOtherSync() does the same (for size: the one way).
    if (kExpandFastPaths && syncPeriod_ != 0U) {
      if (++syncCount_ >= syncPeriod_) {
        syncCount_ = 0;
        sendNow(context, expiry);
      }
      return;
    }
    if (valid_) {  // (running: PdoEngine::onSync() asks only then)
      onOtherSync(context, counter, now, expiry);
    }
  }
  /// A remote request, the PDO running and valid: answered when the COB-ID allows RTR and the
  /// type does (profile).
  void onRemoteRequest(PdoContext& context, Microseconds now) noexcept;
  /// The application changed mapped data (or asks for a transmission): an event. True when it
  /// raised one that was not pending already.
  bool signalEvent(NodeClock& clock) noexcept {
    if (!running_ || !takesEvents()) {
      return false;
    }
    const bool raised = !event_;
    event_ = true;
    clock.schedule(nextDeadline(clock.now));
    return raised;
  }
  /// Takes back an event signalled in the same moment (an answered RPDO that was refused).
  void withdrawEvent() noexcept { event_ = false; }
  bool maps(const od::EntryRef& ref) const noexcept { return map_.contains(ref); }

  /// Event-driven transmission: events and the event timer, within the inhibit time. Asked
  /// while running (PdoEngine keeps every TPDO running exactly while it runs).
  void process(PdoContext& context, Microseconds now) noexcept;
  /// When process() has work: an event or the event timer, the end of the inhibit time. Asked
  /// while running, as process().
  Microseconds nextDeadline(Microseconds now) const noexcept;

 private:
  /// A SYNC in every case the fast path of onSync() does not take (built for size: in every
  /// case): type 0, a cyclic type (still waiting for its SYNC start value), type 252.
  void onOtherSync(PdoContext& context, uint8_t counter, Microseconds now,
                   Microseconds expiry) noexcept {
    if (type_ == 0U) {
      if (context.profile.tpdoType0 == TpdoType0::kEverySync || event_) {
        event_ = false;
        sendCurrent(context, now, expiry);
      }
    } else if (type_ <= 240U) {
      if (waitingForStart_ && counter != 0U) {
        if (counter != syncStart_) {
          return;
        }
        waitingForStart_ = false;
        updateSyncPeriod();
        syncCount_ = 0;
        sendCurrent(context, now, expiry);
        return;
      }
      if (++syncCount_ >= type_) {
        syncCount_ = 0;
        sendCurrent(context, now, expiry);
      }
    } else if (type_ == 252U) {
      map_.pack(context.access, sampled_);
      sampledValid_ = true;
    }
  }
  /// What start() and restart() share: running from `now`, with `event` waiting (for a type
  /// that takes events) and, for an event-driven PDO, an inhibit time that ends at `inhibitEnd`
  /// (kNever: none) and the event timer started.
  void begin(PdoContext& context, Microseconds now, bool event, Microseconds inhibitEnd) noexcept;
  /// Sends the current values of a synchronous PDO (no inhibit time, no event timer).
  COSTA_HOT_INLINE void sendNow(PdoContext& context, Microseconds expiry) noexcept {
    CanFrame frame;
    frame.id = canId_;
    frame.dlc = static_cast<uint8_t>(map_.bytes());
    map_.pack(context.access, frame.data);
    context.tx.send(frame, expiry);
  }
  /// Sends `sample` (the values sampled at a SYNC, type 252), or with nullptr the current
  /// values, and restarts the inhibit time and the event timer of an event-driven PDO.
  void send(PdoContext& context, const uint8_t* sample, Microseconds now,
            Microseconds expiry) noexcept;
  void sendCurrent(PdoContext& context, Microseconds now, Microseconds expiry) noexcept {
    send(context, nullptr, now, expiry);
  }
  /// Keeps syncPeriod_ true to the state it summarises (built for size, onSync() does not look
  /// at it: it stays 0).
  void updateSyncPeriod() noexcept {
    if constexpr (kExpandFastPaths) {
      syncPeriod_ = running_ && valid_ && type_ - 1U < 240U && !waitingForStart_ ? type_ : 0U;
    }
  }

  uint16_t inhibit_ = 0;  ///< 100 us units (sub-index 3)
  uint8_t syncStart_ = 0;
  uint8_t syncCount_ = 0;
  uint8_t syncPeriod_ = 0;  ///< the type of a running synchronous cyclic PDO that counts SYNCs
  bool rtrAllowed_ = false;
  bool running_ = false;
  bool waitingForStart_ = false;
  bool event_ = false;
  bool sampledValid_ = false;
  // Both kNever from bind() on (set there, so that an array of channels is all zeros at first).
  Microseconds inhibitUntil_ = 0;  ///< end of the inhibit time of the last PDO sent
  Microseconds eventDeadline_ = 0;
  PdoMap map_;
  uint8_t sampled_[PdoMap::kMaxBytes] = {};
};

}  // namespace costa
