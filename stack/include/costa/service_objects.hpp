// Which of the node's services owns an object of the communication area: the hook the stack
// itself puts behind 0x1003, 0x1005..0x1007, 0x100C, 0x100D, 0x1010, 0x1011, 0x1012, 0x1014,
// 0x1016, 0x1017, 0x1019, 0x1028, 0x1201..0x127F, 0x1300..0x13FF and 0x1400..0x1BFF. A constant
// table of owners for 0x1003..0x1028 and range tests for the rest: no RAM per object, O(1).
// Application hooks (HookRegistry) take precedence over these.
#pragma once

#include <stdint.h>

#include "costa/features.hpp"
#include "costa/object_hook.hpp"

namespace costa {

class ServiceObjects {
 public:
  /// The hooks of the services (a compiled-out service's stand-in answers 0x06020000).
  struct Hooks {
    ObjectHook* emcy;          ///< 0x1003, 0x1014
    ObjectHook* sync;          ///< 0x1005..0x1007, 0x1019
    ObjectHook* guarding;      ///< 0x100C, 0x100D
    ObjectHook* store;         ///< 0x1010, 0x1011
    ObjectHook* consumer;      ///< 0x1016
    ObjectHook* heartbeat;     ///< 0x1017
    ObjectHook* time;          ///< 0x1012
    ObjectHook* emcyConsumer;  ///< 0x1028
    ObjectHook* safety;        ///< 0x1300..0x13FF
    ObjectHook* pdos;          ///< 0x1400..0x1BFF
    ObjectHook* sdoServers;    ///< 0x1201..0x127F
  };

  explicit ServiceObjects(const Hooks& hooks) noexcept
      : hooks_{{nullptr, hooks.emcy, hooks.sync, hooks.guarding, hooks.store, hooks.consumer,
                hooks.heartbeat, hooks.time, hooks.emcyConsumer},
               hooks.pdos,
               hooks.sdoServers,
               hooks.safety} {}

  /// The hook of the service that owns `index` when that service refines reads (prepareRead:
  /// the store commands' 0x1010/0x1011, which read 1 or 0 by whether storage is there, and the
  /// stand-ins of compiled-out services, whose objects do not exist), else null: the other
  /// services read as the dictionary does.
  ObjectHook* findReader(uint16_t index) const noexcept {
    if constexpr (!features::kSdoServers) {
      if (index - 0x1201U <= 0x127FU - 0x1201U) {
        return hooks_.sdoServers;  // the stand-in: they do not exist
      }
    }
    const uint32_t offset = index - kFirstOwned;
    if (offset < sizeof(kOwners)) {
      const uint8_t owner = kOwners[offset];
      return (kReaders & (1U << owner)) != 0U ? hooks_.of[owner] : nullptr;
    }
    return !features::kSafety && index - 0x1300U <= 0xFFU ? hooks_.safety : nullptr;
  }

  /// The hook of the service that owns `index`, or null. A table lookup for 0x1003..0x1028;
  /// range tests for the PDOs and the additional SDO servers.
  ObjectHook* find(uint16_t index) const noexcept {
    const uint32_t offset = index - kFirstOwned;
    if (offset < sizeof(kOwners)) {
      return hooks_.of[kOwners[offset]];
    }
    if (index - 0x1400U <= 0x1BFFU - 0x1400U) {
      return hooks_.pdos;
    }
    // cppcheck-suppress knownConditionTrueFalse ; true for 0x1201..0x127F
    if (index - 0x1201U <= 0x127FU - 0x1201U) {
      return hooks_.sdoServers;
    }
    // cppcheck-suppress knownConditionTrueFalse ; false only for a call site's constant index
    return index - 0x1300U <= 0xFFU ? hooks_.safety : nullptr;
  }

 private:
  /// Table::of positions of the services with a prepareRead() of their own.
  static constexpr uint32_t kStoreReader = 1U << 4U;  // store commands (or their stand-in)
  static constexpr uint32_t kGuardingReader = features::kNodeGuarding ? 0U : 1U << 3U;
  static constexpr uint32_t kConsumerReader = features::kHeartbeatConsumer ? 0U : 1U << 5U;
  static constexpr uint32_t kTimeReader = features::kTime ? 0U : 1U << 7U;
  static constexpr uint32_t kEmcyConsumerReader = features::kEmcyConsumer ? 0U : 1U << 8U;
  // cppcheck-suppress badBitmaskCheck ; a service's bit is zero when the service is compiled in
  static constexpr uint32_t kReaders =
      kStoreReader | kGuardingReader | kConsumerReader | kTimeReader | kEmcyConsumerReader;
  /// The first object of the table (0x1003, EMCY's); the last is 0x1028 (the EMCY consumer's).
  static constexpr uint16_t kFirstOwned = 0x1003;
  /// Which service owns kFirstOwned + n: 0 none, else a position in Table::of.
  static constexpr uint8_t kOwners[0x1028 - kFirstOwned + 1] = {
      1, 0, 2, 2, 2, 0, 0, 0, 0, 3, 3, 0, 0,           // 0x1003 EMCY; 0x1005-7 SYNC; 0x100C/D
      4, 4, 7, 0, 1, 0, 5, 6, 0, 2, 0, 0, 0, 0, 0, 0,  // 0x1010/1 store; 0x1012 TIME; 0x1014; ...
      0, 0, 0, 0, 0, 0, 0, 0, 8,                       // 0x1028 EMCY consumer
  };
  struct Table {
    ObjectHook* of[9];  ///< [0] null, emcy, sync, guarding, store, consumer, heartbeat, time,
                        ///< EMCY consumer
    ObjectHook* pdos;
    ObjectHook* sdoServers;
    ObjectHook* safety;
  };
  Table hooks_;
};

}  // namespace costa
