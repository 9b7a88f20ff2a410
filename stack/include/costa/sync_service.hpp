// SYNC consumer and producer (CiA 301 7.2.5): COB-ID 0x1005 (bit 30: this node produces),
// communication cycle period 0x1006 (µs), synchronous window length 0x1007 (µs), synchronous
// counter overflow value 0x1019.
#pragma once

#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class EmcyProducer;
class FrameRouter;

/// A SYNC seen by the node (received, or produced by itself).
struct SyncEvent {
  uint8_t counter = 0;  ///< 0 when the SYNC carries no counter
  Microseconds time = 0;
  Microseconds windowEnd = kNever;  ///< synchronous PDOs not sent by then are dropped
};

class SyncService : public ObjectHook {
 public:
  static constexpr uint16_t kCobIdIndex = 0x1005;
  static constexpr uint16_t kPeriodIndex = 0x1006;
  static constexpr uint16_t kWindowIndex = 0x1007;
  static constexpr uint16_t kOverflowIndex = 0x1019;
  static constexpr uint16_t kEmcyUnexpectedLength = 0x8240;

  /// `routes` is told when the SYNC CAN-ID changes.
  SyncService(od::ObjectDictionary& dictionary, TransmitPath& tx, EmcyProducer& emcy,
              NodeClock& clock, FrameRouter& routes) noexcept
      : dictionary_(dictionary), tx_(tx), emcy_(emcy), clock_(clock), routes_(routes) {}

  /// Reads 0x1005/0x1006/0x1007/0x1019 (after a reset communication, or a write): the counter
  /// starts at 1, a SYNC length error (EMCY 0x8240) ends, production starts from `now`.
  void configure(Microseconds now) noexcept;
  /// Entering stopped: the producer's counter starts over at 1 when SYNC production resumes.
  void restartCounter() noexcept { counter_ = 1; }

  /// True for a frame on the SYNC COB-ID (consumer side).
  bool accepts(const CanFrame& frame) const noexcept {
    return !frame.rtr && !frame.extended && frame.id == canId_;
  }
  /// A received SYNC. A length that does not match 0x1019 (DLC 0 without a counter, 1 with)
  /// raises EMCY 0x8240 and the SYNC is ignored; returns false then (`event` is not valid).
  [[nodiscard]] bool onFrame(const CanFrame& frame, Microseconds now, SyncEvent* event) noexcept;

  /// Producer: sends the SYNC when due. Returns true (and fills `event`) when it sent one.
  [[nodiscard]] bool process(Microseconds now, bool allowed, SyncEvent* event) noexcept;
  Microseconds nextDeadline() const noexcept { return producer_ ? timer_.next() : kNever; }

  bool producer() const noexcept { return producer_; }
  /// The SYNC CAN-ID (consumer and producer).
  uint32_t canId() const noexcept { return canId_; }

  /// 0x1005 (29-bit and restricted CAN-IDs refused, cob::acceptableCobId; the CAN-ID cannot
  /// change while producing), 0x1019 (0 or 2..240, only while the period is 0). An accepted
  /// write takes effect at once: 0x1007 changes the window alone; one of 0x1005, 0x1006 or
  /// 0x1019 configures the service from the write (configure()), except that production that
  /// goes on keeps its counter (production the write stops starts from 1 when it resumes).
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  bool producing() const noexcept { return producer_ && period_ != 0U; }
  void readParameters() noexcept;
  void clearLengthError() noexcept;
  /// The time of a SYNC seen at `now` and the end of its window into `event`; true (the SYNC is
  /// reported). One copy for the SYNC received and the SYNC produced.
  COSTA_SHARED_INLINE bool report(Microseconds now, SyncEvent* event) const noexcept {
    event->time = now;
    event->windowEnd = window_ == 0U ? kNever : at(now, window_);
    return true;
  }

  // The bytes first, within reach of Thumb-1's short offsets.
  uint8_t overflow_ = 0;
  uint8_t counter_ = 0;  ///< producer's next counter value
  bool producer_ = false;
  bool lengthError_ = false;  ///< EMCY 0x8240 raised
  od::ObjectDictionary& dictionary_;
  TransmitPath& tx_;
  EmcyProducer& emcy_;
  NodeClock& clock_;
  FrameRouter& routes_;
  uint32_t canId_ = 0x080;
  uint32_t period_ = 0;  ///< µs, 0x1006
  uint32_t window_ = 0;  ///< µs, 0x1007 (at most kLongestDelay)
  LongTimer timer_;      ///< the next SYNC this node produces
};

}  // namespace costa
