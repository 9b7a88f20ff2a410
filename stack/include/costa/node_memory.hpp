// Caller-owned storage of a node (NodeMemory), and NodeInstance: a node together with its
// storage, sized at compile time from the generated dictionary.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/emcy_producer.hpp"
#include "costa/features.hpp"
#include "costa/frame_router.hpp"
#include "costa/heartbeat_consumer.hpp"
#include "costa/hook_registry.hpp"
#include "costa/rpdo_channel.hpp"
#include "costa/safety_service.hpp"
#include "costa/sdo_servers.hpp"
#include "costa/tpdo_channel.hpp"
#include "costa/tx_queue.hpp"

namespace costa {

/// Caller-owned storage of a node. Sizes are fixed for the node's lifetime.
struct NodeMemory {
  void* values;          ///< RAM block of the dictionary: Definition::valuesSize bytes.
  QueuedFrame* txSlots;  ///< Frames the controller refused, waiting for it.
  size_t txCapacity;
  uint8_t* sdoBuffer;  ///< Largest value downloadable by a segmented SDO transfer.
  size_t sdoBufferSize;
  HookBinding* hookSlots;  ///< Hooks of the application.
  size_t hookCapacity;
  RpdoChannel* rpdos;  ///< One per RPDO communication object (0x1400..0x15FF).
  size_t rpdoCapacity;
  TpdoChannel* tpdos;  ///< One per TPDO communication object (0x1800..0x19FF).
  size_t tpdoCapacity;
  EmcyCondition* emcyConditions;  ///< Error conditions active at the same time.
  size_t emcyConditionCapacity;
  PendingEmcy* emcyQueue;  ///< EMCY frames waiting for their inhibit time.
  size_t emcyQueueCapacity;
  HeartbeatMonitor* heartbeatMonitors;  ///< One per sub-index of 0x1016.
  size_t heartbeatMonitorCapacity;
  RouteEntry* routes;  ///< The frame routing table: one entry per CAN-ID a service takes.
  size_t routeCapacity;
  SdoServerSlot* sdoServerSlots;  ///< One per additional SDO server (0x1201..0x127F).
  uint8_t* sdoServerBuffers;      ///< sdoBufferSize bytes per additional SDO server.
  size_t sdoServerCount;
  SrdoChannel* srdoChannels;  ///< One per SRDO (0x1301..0x1340) of the dictionary (safety).
  size_t srdoCount;
};

/// Compile-time capacities of a NodeInstance beyond what the dictionary dictates.
struct DefaultNodeCapacity {
  static constexpr size_t kTxQueueDepth = 8;
  static constexpr size_t kHooks = 8;
  static constexpr size_t kMinimumSdoBuffer = 32;
  static constexpr size_t kEmcyConditions = 8;
  static constexpr size_t kEmcyQueueDepth = 8;
};

namespace detail {
constexpr size_t atLeastOne(size_t n) {
  return n == 0U ? 1U : n;
}

/// The additional SDO servers' storage; a base class, so that none takes no room.
template <size_t kCount, size_t kBytes>
struct SdoServerStorage {
  SdoServerSlot sdoServerSlots[kCount]{};
  uint8_t sdoServerBuffers[kCount][kBytes]{};
  SdoServerSlot* slots() noexcept { return sdoServerSlots; }
  uint8_t* buffers() noexcept { return &sdoServerBuffers[0][0]; }
};
template <size_t kBytes>
struct SdoServerStorage<0, kBytes> {
  static SdoServerSlot* slots() noexcept { return nullptr; }
  static uint8_t* buffers() noexcept { return nullptr; }
};

/// The SRDOs' channels; a base class, so that none takes no room.
template <size_t kCount>
struct SrdoStorage {
  SrdoChannel srdoChannels[kCount]{};
  SrdoChannel* channels() noexcept { return srdoChannels; }
};
template <>
struct SrdoStorage<0> {
  static SrdoChannel* channels() noexcept { return nullptr; }
};

template <typename DictionaryCapacity, typename Extra>
struct SdoSizes {
  static constexpr size_t kBytes = DictionaryCapacity::kLargestValue > Extra::kMinimumSdoBuffer
                                       ? DictionaryCapacity::kLargestValue
                                       : Extra::kMinimumSdoBuffer;
  static constexpr size_t kServers = features::kSdoServers ? DictionaryCapacity::kSdoServers : 0U;
};

/// Storage of a NodeInstance; a base class so that it is initialised before the Node base.
template <typename Values, typename DictionaryCapacity, typename Extra>
struct NodeBuffers : SdoServerStorage<SdoSizes<DictionaryCapacity, Extra>::kServers,
                                      SdoSizes<DictionaryCapacity, Extra>::kBytes>,
                     SrdoStorage<features::kSafety ? DictionaryCapacity::kSrdoCount : 0U> {
  using SrdoRoom = SrdoStorage<features::kSafety ? DictionaryCapacity::kSrdoCount : 0U>;
  static constexpr size_t kSrdos = features::kSafety ? DictionaryCapacity::kSrdoCount : 0U;
  using SdoServerRoom = SdoServerStorage<SdoSizes<DictionaryCapacity, Extra>::kServers,
                                         SdoSizes<DictionaryCapacity, Extra>::kBytes>;
  static constexpr size_t kSdoBytes = SdoSizes<DictionaryCapacity, Extra>::kBytes;
  static constexpr size_t kSdoServers = SdoSizes<DictionaryCapacity, Extra>::kServers;
  static constexpr size_t kRpdos = atLeastOne(DictionaryCapacity::kRpdoCount);
  static constexpr size_t kTpdos = atLeastOne(DictionaryCapacity::kTpdoCount);
  static constexpr size_t kMonitors =
      features::kHeartbeatConsumer ? atLeastOne(DictionaryCapacity::kHeartbeatConsumers) : 1U;
  static constexpr size_t kEmcyConsumers =
      features::kEmcyConsumer ? DictionaryCapacity::kEmcyConsumers : 0U;
  /// Two per SRDO (its normal and inverted CAN-IDs), and GFC.
  static constexpr size_t kSafetyRoutes = features::kSafety ? 1U + 2U * kSrdos : 0U;
  /// NMT, SYNC, SDO, LSS, TIME (when compiled in), one per PDO, per consumed EMCY CAN-ID and
  /// per additional SDO server, and the safety service's.
  static constexpr size_t kRoutes = 4U + (features::kTime ? 1U : 0U) + kRpdos + kTpdos +
                                    kEmcyConsumers + kSdoServers + kSafetyRoutes;

  Values values{};
  QueuedFrame tx[Extra::kTxQueueDepth]{};
  uint8_t sdo[kSdoBytes]{};
  HookBinding hooks[Extra::kHooks]{};
  RpdoChannel rpdos[kRpdos]{};
  TpdoChannel tpdos[kTpdos]{};
  EmcyCondition emcyConditions[Extra::kEmcyConditions]{};
  PendingEmcy emcyQueue[Extra::kEmcyQueueDepth]{};
  HeartbeatMonitor monitors[kMonitors]{};
  RouteEntry routes[kRoutes]{};

  NodeMemory memory() noexcept {
    return NodeMemory{&values,
                      tx,
                      Extra::kTxQueueDepth,
                      sdo,
                      kSdoBytes,
                      hooks,
                      Extra::kHooks,
                      rpdos,
                      kRpdos,
                      tpdos,
                      kTpdos,
                      emcyConditions,
                      Extra::kEmcyConditions,
                      emcyQueue,
                      Extra::kEmcyQueueDepth,
                      monitors,
                      kMonitors,
                      routes,
                      kRoutes,
                      SdoServerRoom::slots(),
                      SdoServerRoom::buffers(),
                      kSdoServers,
                      SrdoRoom::channels(),
                      kSrdos};
  }
};
}  // namespace detail

}  // namespace costa
