// Safety (EN 50325-5 / CiA 304), the global fail-safe command (GFC): COB-ID 0x001, no data.
// Object 0x1300 (UNSIGNED8) enables it: 1 = valid, 0 = not valid (other values are refused,
// 0x06090030). While valid, the node consumes GFC in every state but initialising and tells its
// listeners (NodeEvents::onGlobalFailSafe), whose application enters its safe state; it sends
// GFC when its application asks (Node::sendGlobalFailSafe), in pre-operational and operational.
// A GFC frame with data, or a remote frame, is ignored (NodeStatistics::framesIgnored).
//
// The service owns 0x1300..0x13FF (ServiceObjects).
//
// Context: the one that runs the node. O(1) everything.
#pragma once

#include <stdint.h>

#include "costa/frame_router.hpp"
#include "costa/object_hook.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class NodeListeners;

class SafetyService : public ObjectHook {
 public:
  static constexpr uint16_t kGfcIndex = 0x1300;
  static constexpr uint16_t kGfcCanId = 0x001;

  SafetyService(od::ObjectDictionary& dictionary, TransmitPath& tx, const NodeListeners& listeners,
                FrameRouter& routes) noexcept
      : dictionary_(dictionary), tx_(tx), listeners_(listeners), routes_(routes) {}

  /// GFC is valid: 0x1300 exists and is 1.
  bool gfcValid() const noexcept;

  /// The GFC route (Route::kGfc on 0x001) while GFC is valid.
  void addRoutes(FrameRouter& router) const noexcept;

  /// A frame on 0x001 (GFC valid, the node past initialising): tells the listeners. False for a
  /// remote frame or one with data.
  [[nodiscard]] bool onGfc(const CanFrame& frame) noexcept;

  /// Sends GFC when it is valid and `allowed` (pre-operational or operational).
  bool sendGfc(bool allowed) noexcept;

  /// 0x1300: 0 or 1 (else 0x06090030); a write rebuilds the routing table.
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  od::ObjectDictionary& dictionary_;
  TransmitPath& tx_;
  const NodeListeners& listeners_;
  FrameRouter& routes_;
};

}  // namespace costa
