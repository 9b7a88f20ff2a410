// One transmit PDO (CiA 301 7.2.2): communication parameter 0x1800+n, mapping 0x1A00+n (or the
// device's static mapping).
#pragma once

#include <stdint.h>

#include "costa/pdo_channel.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"

namespace costa {

class TpdoChannel {
 public:
  void bind(uint16_t communicationIndex) noexcept { index_ = communicationIndex; }
  uint16_t communicationIndex() const noexcept { return index_; }

  /// Reads the communication parameters and the mapping.
  void configure(PdoContext& context) noexcept;

  bool valid() const noexcept { return valid_; }
  uint32_t canId() const noexcept { return canId_; }
  uint8_t transmissionType() const noexcept { return type_; }
  bool rtrAllowed() const noexcept { return rtrAllowed_; }
  bool eventDriven() const noexcept { return type_ >= 254U; }

  /// True for a remote request on this PDO's CAN-ID.
  bool acceptsRemoteRequest(const CanFrame& frame) const noexcept {
    return valid_ && frame.rtr && !frame.extended && frame.id == canId_;
  }

  /// Entering operational (or reconfigured while operational): SYNC counting restarts, the
  /// event timer starts, and an event-driven PDO is sent once when `initialEvent`.
  void start(PdoContext& context, Microseconds now, bool initialEvent) noexcept;
  void stop() noexcept;

  /// A SYNC with `counter` (0 when the SYNC carries none). Synchronous PDOs are queued with
  /// `expiry` (end of the SYNC window) so that they are dropped if they cannot go out in time.
  void onSync(PdoContext& context, uint8_t counter, Microseconds now, Microseconds expiry) noexcept;
  /// A remote request: answered when the COB-ID allows RTR and the type does (profile).
  void onRemoteRequest(PdoContext& context, Microseconds now) noexcept;
  /// The application changed mapped data (or asks for a transmission): an event.
  void signalEvent(NodeClock& clock) noexcept;
  bool maps(uint16_t index, uint8_t subIndex) const noexcept {
    return map_.contains(index, subIndex);
  }

  /// Event-driven transmission: events and the event timer, within the inhibit time.
  void process(PdoContext& context, Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept;

 private:
  void send(PdoContext& context, const uint8_t* data, Microseconds now,
            Microseconds expiry) noexcept;
  void sendCurrent(PdoContext& context, Microseconds now, Microseconds expiry) noexcept;

  uint16_t index_ = 0;
  bool valid_ = false;
  bool rtrAllowed_ = false;
  uint32_t canId_ = 0;
  uint8_t type_ = 0;
  uint8_t syncStart_ = 0;
  Microseconds inhibit_ = 0;
  Microseconds eventTimer_ = 0;
  PdoMap map_;
  bool running_ = false;
  uint8_t syncCount_ = 0;
  bool waitingForStart_ = false;
  bool event_ = false;
  uint8_t sampled_[8] = {};
  bool sampledValid_ = false;
  Microseconds inhibitUntil_ = 0;
  Microseconds eventDeadline_ = kNever;
};

}  // namespace costa
