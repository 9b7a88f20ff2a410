// One receive PDO (CiA 301 7.2.2): communication parameter 0x1400+n, mapping 0x1600+n (or the
// device's static mapping).
#pragma once

#include <stdint.h>

#include "costa/pdo_channel.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"

namespace costa {

class RpdoChannel {
 public:
  static constexpr uint16_t kEmcyLengthShort = 0x8210;  ///< PDO not processed: too few bytes
  static constexpr uint16_t kEmcyLengthLong = 0x8220;   ///< PDO longer than its mapping
  static constexpr uint16_t kEmcyTimeout = 0x8250;      ///< RPDO deadline (event timer) missed

  void bind(uint16_t communicationIndex) noexcept { index_ = communicationIndex; }
  uint16_t communicationIndex() const noexcept { return index_; }

  /// Reads the communication parameters and the mapping; drops held data.
  void configure(PdoContext& context) noexcept;

  bool valid() const noexcept { return valid_; }
  uint32_t canId() const noexcept { return canId_; }
  uint8_t transmissionType() const noexcept { return type_; }
  size_t mappedBytes() const noexcept { return map_.bytes(); }

  /// True for a data frame on this PDO's CAN-ID.
  bool accepts(const CanFrame& frame) const noexcept {
    return valid_ && !frame.rtr && !frame.extended && frame.id == canId_;
  }

  /// A received PDO (node operational). Too few bytes: EMCY 0x8210, nothing applied. More bytes
  /// than mapped: the mapped bytes are applied and EMCY 0x8220 is raised (cleared by the next
  /// PDO of the right length). Types 0..240 hold the data until the next SYNC; 254/255 apply it
  /// at once.
  void onFrame(PdoContext& context, const CanFrame& frame, Microseconds now) noexcept;
  /// Applies the data held since the previous SYNC.
  void onSync(PdoContext& context) noexcept;
  /// Deadline monitoring with the event timer (sub-index 5): EMCY 0x8250 when no PDO arrived
  /// within it after the first one.
  void process(PdoContext& context, Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept;
  /// Leaving operational: held data and monitoring stop.
  void stop() noexcept;

 private:
  void apply(PdoContext& context, const uint8_t* data) noexcept;
  uint8_t source() const noexcept { return static_cast<uint8_t>(index_ & 0xFFU); }

  uint16_t index_ = 0;
  bool valid_ = false;
  uint32_t canId_ = 0;
  uint8_t type_ = 0;
  Microseconds eventTimer_ = 0;
  PdoMap map_;
  uint8_t held_[8] = {};
  bool holding_ = false;
  Microseconds deadline_ = kNever;
  bool timedOut_ = false;
};

}  // namespace costa
