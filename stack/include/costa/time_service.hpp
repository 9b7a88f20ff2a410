// TIME consumer and producer (CiA 301 7.2.6): COB-ID 0x1012 (bit 31: this node consumes, bit
// 30: it produces, bits 10..0: the CAN-ID, 0x100 by default). The TIME object carries
// TIME_OF_DAY in 6 bytes: milliseconds after midnight (28 bits, little-endian in bytes 0..3, the
// top 4 bits reserved) and days since 1 January 1984 (bytes 4..5).
//
// The node keeps a clock of day: set by each TIME frame it consumes, or by the application
// (Node::setTimeOfDay), and running on from there with the node's own clock. A producer sends it
// at the period the application chooses (Node::setTimeProducerPeriod), in pre-operational and
// operational. A frame of another length, or with a millisecond count of a day or more, is
// ignored and counted (NodeStatistics::timeFramesIgnored).
//
// Context: the one that runs the node. O(1) everything.
#pragma once

#include <stdint.h>

#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class FrameRouter;

/// CiA 301 TIME_OF_DAY.
struct TimeOfDay {
  static constexpr uint32_t kMillisecondsPerDay = 86400000;

  uint32_t milliseconds = 0;  ///< after midnight: 0..86,399,999
  uint16_t days = 0;          ///< since 1 January 1984

  bool operator==(const TimeOfDay& other) const noexcept {
    return milliseconds == other.milliseconds && days == other.days;
  }
};

class TimeService : public ObjectHook {
 public:
  static constexpr uint16_t kCobIdIndex = 0x1012;
  static constexpr uint32_t kConsume = 1U << 31U;
  static constexpr uint32_t kProduce = 1U << 30U;
  static constexpr uint8_t kLength = 6;

  TimeService(od::ObjectDictionary& dictionary, TransmitPath& tx, NodeClock& clock,
              FrameRouter& routes) noexcept
      : dictionary_(dictionary), tx_(tx), clock_(clock), routes_(routes) {}

  /// Reads 0x1012 (after a reset communication, or a write). Without the object: neither.
  void configure() noexcept;

  bool consumer() const noexcept { return consumer_; }
  bool producer() const noexcept { return producer_; }
  uint32_t canId() const noexcept { return canId_; }

  /// A frame on the TIME CAN-ID while consuming: sets the clock of day. False (and counted) for
  /// a remote frame, a length other than 6 or milliseconds of a day or more.
  [[nodiscard]] bool onFrame(const CanFrame& frame, Microseconds now) noexcept;

  /// The clock of day at `now`; false while it has never been set.
  bool timeOfDay(Microseconds now, TimeOfDay* out) const noexcept;
  /// Sets the clock of day (the application's own time source). Milliseconds of a day or more
  /// are refused.
  bool setTimeOfDay(const TimeOfDay& time, Microseconds now) noexcept;
  /// Producer: sends TIME every `period` (0: stops), the first one period from `now`, once the
  /// clock of day is set and while 0x1012 has bit 30 set.
  void setProducerPeriod(Microseconds period, Microseconds now) noexcept;

  /// Sends TIME when due (`allowed`: pre-operational or operational); re-bases the clock of day
  /// so that it survives the wrap of the 32-bit microsecond clock.
  void process(Microseconds now, bool allowed) noexcept;
  Microseconds nextDeadline() const noexcept { return earliest(nextTime_, rebaseAt_); }

  uint32_t framesIgnored() const noexcept { return framesIgnored_; }

  /// 0x1012: 29-bit and restricted CAN-IDs refused (0x06090030), and the CAN-ID stays while
  /// the object consumes or produces (CiA 301: clear bits 31 and 30 first, then change it).
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

  static void encode(const TimeOfDay& time, uint8_t* bytes) noexcept;

 private:
  /// Folds the time since `base_` into it (keeps the microseconds below a millisecond).
  void advanceTo(Microseconds now) noexcept;
  void schedule(Microseconds* deadline, Microseconds at) noexcept {
    *deadline = at;
    clock_.schedule(at);
  }

  od::ObjectDictionary& dictionary_;
  TransmitPath& tx_;
  NodeClock& clock_;
  FrameRouter& routes_;
  TimeOfDay base_;
  Microseconds baseAt_ = 0;         ///< the node's time of base_
  Microseconds period_ = 0;         ///< of the producer (at most kLongestDelay); 0: none
  Microseconds nextTime_ = kNever;  ///< the next TIME this node produces
  Microseconds rebaseAt_ = kNever;  ///< the next fold of the clock of day; kNever: never set
  uint32_t framesIgnored_ = 0;
  uint16_t canId_ = 0x100;
  bool consumer_ = false;
  bool producer_ = false;
};

}  // namespace costa
