// Heartbeat producer (CiA 301 7.2.8.3.2.1): sends the NMT state on 0x700+id every 0x1017 ms.
#pragma once

#include <stdint.h>

#include "costa/nmt_state.hpp"
#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class HeartbeatProducer : public ObjectHook {
 public:
  static constexpr uint16_t kIndex = 0x1017;

  HeartbeatProducer(od::ObjectDictionary& dictionary, TransmitPath& tx, NodeClock& clock) noexcept
      : dictionary_(dictionary), tx_(tx), clock_(clock) {}

  void setNodeId(uint8_t nodeId) noexcept { nodeId_ = nodeId; }

  /// (Re)starts production from 0x1017: the first heartbeat one period after `now`. 0 disables.
  void restart(Microseconds now) noexcept {
    restartWith(now, dictionary_.readUnsigned32(kIndex, 0, 0));
  }
  /// restart() with the period `periodMs` (the value of 0x1017).
  void restartWith(Microseconds now, uint32_t periodMs) noexcept;
  void stop() noexcept { next_ = kNever; }

  /// Sends a heartbeat carrying `state` when due.
  void process(Microseconds now, NmtState state) noexcept;
  /// Sends the frame of 0x700+id carrying `state` now, outside the period: the boot-up is this
  /// frame with state 0 (initialising), CiA 301 7.2.8.3.2.1.
  void send(NmtState state) noexcept;
  Microseconds nextDeadline() const noexcept { return next_; }

  /// 0x1017 write: store, then restart with the new period.
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  od::ObjectDictionary& dictionary_;
  TransmitPath& tx_;
  NodeClock& clock_;
  uint8_t nodeId_ = 0;
  Microseconds period_ = 0;
  Microseconds next_ = kNever;
};

}  // namespace costa
