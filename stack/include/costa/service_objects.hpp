// Which of the node's services owns an object of the communication area: the hook the stack
// itself puts behind 0x1003, 0x1005..0x1007, 0x100C, 0x100D, 0x1010, 0x1011, 0x1014, 0x1016,
// 0x1017, 0x1019 and 0x1400..0x1BFF. A switch, not a table: no RAM per object, O(1).
// Application hooks (HookRegistry) take precedence over these.
#pragma once

#include <stdint.h>

#include "costa/object_hook.hpp"

namespace costa {

class ServiceObjects {
 public:
  /// The hooks of the services (a compiled-out service's stand-in answers 0x06020000).
  struct Hooks {
    ObjectHook* emcy;       ///< 0x1003, 0x1014
    ObjectHook* sync;       ///< 0x1005..0x1007, 0x1019
    ObjectHook* guarding;   ///< 0x100C, 0x100D
    ObjectHook* store;      ///< 0x1010, 0x1011
    ObjectHook* consumer;   ///< 0x1016
    ObjectHook* heartbeat;  ///< 0x1017
    ObjectHook* pdos;       ///< 0x1400..0x1BFF
  };

  explicit ServiceObjects(const Hooks& hooks) noexcept : hooks_(hooks) {}

  /// The hook of the service that owns `index`, or null.
  ObjectHook* find(uint16_t index) const noexcept {
    if (index >= 0x1400U && index <= 0x1BFFU) {
      return hooks_.pdos;
    }
    switch (index) {
      case 0x1003:
      case 0x1014: return hooks_.emcy;
      case 0x1005:
      case 0x1006:
      case 0x1007:
      case 0x1019: return hooks_.sync;
      case 0x100C:
      case 0x100D: return hooks_.guarding;
      case 0x1010:
      case 0x1011: return hooks_.store;
      case 0x1016: return hooks_.consumer;
      case 0x1017: return hooks_.heartbeat;
      default: return nullptr;
    }
  }

 private:
  Hooks hooks_;
};

}  // namespace costa
