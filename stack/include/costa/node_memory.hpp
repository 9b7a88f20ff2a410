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
  RouteEntry* routes;  ///< The frame routing table: one entry per CAN-ID a service takes (at
                       ///< most 255 are used).
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
  uint8_t sdoServerBuffers[kCount * kBytes]{};  ///< kBytes per server
};
template <size_t kBytes>
struct SdoServerStorage<0, kBytes> {
  // NodeMemory's names, which the node's constructor reads (NOLINT: not kNames, not const):
  // NOLINTBEGIN(readability-identifier-naming,cppcoreguidelines-avoid-non-const-global-variables)
  static constexpr SdoServerSlot* sdoServerSlots = nullptr;
  static constexpr uint8_t* sdoServerBuffers = nullptr;
  // NOLINTEND(readability-identifier-naming,cppcoreguidelines-avoid-non-const-global-variables)
};

/// The SRDOs' channels; a base class, so that none takes no room.
template <size_t kCount>
struct SrdoStorage {
  SrdoChannel srdoChannels[kCount]{};
};
template <>
struct SrdoStorage<0> {
  // NodeMemory's names, which the node's constructor reads (NOLINT: not kNames, not const):
  // NOLINTBEGIN(readability-identifier-naming,cppcoreguidelines-avoid-non-const-global-variables)
  static constexpr SrdoChannel* srdoChannels = nullptr;
  // NOLINTEND(readability-identifier-naming,cppcoreguidelines-avoid-non-const-global-variables)
};

/// The heartbeat consumer's monitors; a base class, so that a build without the consumer
/// takes no room for them.
template <size_t kCount>
struct HeartbeatMonitorStorage {
  HeartbeatMonitor heartbeatMonitors[kCount]{};
};
template <>
struct HeartbeatMonitorStorage<0> {
  // NodeMemory's names, which the node's constructor reads (NOLINT: not kNames, not const):
  // NOLINTBEGIN(readability-identifier-naming,cppcoreguidelines-avoid-non-const-global-variables)
  static constexpr HeartbeatMonitor* heartbeatMonitors = nullptr;
  // NOLINTEND(readability-identifier-naming,cppcoreguidelines-avoid-non-const-global-variables)
};

/// One monitor per sub-index of 0x1016 with the consumer, none without it.
template <typename DictionaryCapacity>
constexpr size_t kHeartbeatMonitors = features::kHeartbeatConsumer
                                          ? atLeastOne(DictionaryCapacity::kHeartbeatConsumers)
                                          : 0U;

template <typename DictionaryCapacity, typename Extra>
struct SdoSizes {
  static constexpr size_t kBytes = DictionaryCapacity::kLargestValue > Extra::kMinimumSdoBuffer
                                       ? DictionaryCapacity::kLargestValue
                                       : Extra::kMinimumSdoBuffer;
  static constexpr size_t kServers = features::kSdoServers ? DictionaryCapacity::kSdoServers : 0U;
};

/// Storage of a NodeInstance; a base class so that it is initialised before the Node base. Its
/// members have NodeMemory's names, the capacities as constants: the node's constructor takes
/// either (Node::Node), and over these buffers it needs no NodeMemory built at run time.
template <typename Values, typename DictionaryCapacity, typename Extra>
struct NodeBuffers : SdoServerStorage<SdoSizes<DictionaryCapacity, Extra>::kServers,
                                      SdoSizes<DictionaryCapacity, Extra>::kBytes>,
                     SrdoStorage<features::kSafety ? DictionaryCapacity::kSrdoCount : 0U>,
                     HeartbeatMonitorStorage<kHeartbeatMonitors<DictionaryCapacity>> {
  // NodeMemory's names, which the node's constructor reads (NOLINT: not kNames).
  // NOLINTBEGIN(readability-identifier-naming)
  static constexpr size_t txCapacity = Extra::kTxQueueDepth;
  static constexpr size_t sdoBufferSize = SdoSizes<DictionaryCapacity, Extra>::kBytes;
  static constexpr size_t hookCapacity = Extra::kHooks;
  static constexpr size_t rpdoCapacity = atLeastOne(DictionaryCapacity::kRpdoCount);
  static constexpr size_t tpdoCapacity = atLeastOne(DictionaryCapacity::kTpdoCount);
  static constexpr size_t emcyConditionCapacity = Extra::kEmcyConditions;
  static constexpr size_t emcyQueueCapacity = Extra::kEmcyQueueDepth;
  static constexpr size_t heartbeatMonitorCapacity = kHeartbeatMonitors<DictionaryCapacity>;
  static constexpr size_t sdoServerCount = SdoSizes<DictionaryCapacity, Extra>::kServers;
  static constexpr size_t srdoCount = features::kSafety ? DictionaryCapacity::kSrdoCount : 0U;
  static constexpr size_t kEmcyConsumers =
      features::kEmcyConsumer ? DictionaryCapacity::kEmcyConsumers : 0U;
  /// Two per SRDO (its normal and inverted CAN-IDs), and GFC.
  static constexpr size_t kSafetyRoutes = features::kSafety ? 1U + 2U * srdoCount : 0U;
  /// NMT, SYNC, SDO, LSS, TIME (when compiled in), one per PDO, per consumed EMCY CAN-ID and
  /// per additional SDO server, and the safety service's.
  static constexpr size_t routeCapacity = 4U + (features::kTime ? 1U : 0U) + rpdoCapacity +
                                          tpdoCapacity + kEmcyConsumers + sdoServerCount +
                                          kSafetyRoutes;
  // NOLINTEND(readability-identifier-naming)

  Values values{};
  QueuedFrame txSlots[txCapacity]{};
  uint8_t sdoBuffer[sdoBufferSize]{};
  HookBinding hookSlots[hookCapacity]{};
  RpdoChannel rpdos[rpdoCapacity]{};
  TpdoChannel tpdos[tpdoCapacity]{};
  EmcyCondition emcyConditions[emcyConditionCapacity]{};
  PendingEmcy emcyQueue[emcyQueueCapacity]{};
  RouteEntry routes[routeCapacity]{};
};
}  // namespace detail

}  // namespace costa
