// EMCY consumer (CiA 301 7.2.7, object 0x1028): the node watches the EMCY COB-IDs listed in
// 0x1028 (sub-index n: bit 31 set = not valid, bit 29 = 29-bit CAN-ID, bits 10..0 the CAN-ID)
// and tells its listeners of every emergency message received there
// (NodeEvents::onEmcyReceived), with the producer's node-id when the CAN-ID is the pre-defined
// one (0x80 + node-id). A frame of another length than 8, or a remote frame, is ignored and
// counted (NodeStatistics::emcyFramesIgnored). Received in pre-operational and operational.
//
// Context: the one that runs the node. Routes are added by the node (addRoutes()) when it
// builds its routing table; a write to 0x1028 rebuilds it.
#pragma once

#include <stdint.h>

#include "costa/emcy_message.hpp"
#include "costa/frame_router.hpp"
#include "costa/object_hook.hpp"
#include "costa/port/can_frame.hpp"

namespace costa {

class NodeListeners;

class EmcyConsumer : public ObjectHook {
 public:
  static constexpr uint16_t kIndex = 0x1028;

  EmcyConsumer(const NodeListeners& listeners, FrameRouter& routes) noexcept
      : listeners_(listeners), routes_(routes) {}

  /// A route (Route::kEmcy, channel = sub-index) for every valid 11-bit entry of 0x1028.
  static void addRoutes(const od::ObjectDictionary& dictionary, FrameRouter& router) noexcept;

  /// A frame on a consumed EMCY CAN-ID, listed at sub-index `entry`: tells the listeners.
  /// False (and counted) for a remote frame or a length other than 8.
  [[nodiscard]] bool onFrame(const CanFrame& frame, uint8_t entry) noexcept;

  uint32_t framesIgnored() const noexcept { return framesIgnored_; }

  /// 0x1028:n: a 29-bit CAN-ID, or a restricted one in a valid entry, is refused (0x06090030);
  /// every accepted write rebuilds the routing table.
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  const NodeListeners& listeners_;
  FrameRouter& routes_;
  uint32_t framesIgnored_ = 0;
};

}  // namespace costa
