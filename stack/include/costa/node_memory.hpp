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
  RouteEntry* routes;  ///< The frame routing table: NMT, SYNC, SDO, LSS, TIME and every PDO.
  size_t routeCapacity;
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

/// Storage of a NodeInstance; a base class so that it is initialised before the Node base.
template <typename Values, typename DictionaryCapacity, typename Extra>
struct NodeBuffers {
  static constexpr size_t kSdoBytes = DictionaryCapacity::kLargestValue > Extra::kMinimumSdoBuffer
                                          ? DictionaryCapacity::kLargestValue
                                          : Extra::kMinimumSdoBuffer;
  static constexpr size_t kRpdos = atLeastOne(DictionaryCapacity::kRpdoCount);
  static constexpr size_t kTpdos = atLeastOne(DictionaryCapacity::kTpdoCount);
  static constexpr size_t kMonitors =
      features::kHeartbeatConsumer ? atLeastOne(DictionaryCapacity::kHeartbeatConsumers) : 1U;
  static constexpr size_t kEmcyConsumers =
      features::kEmcyConsumer ? DictionaryCapacity::kEmcyConsumers : 0U;
  /// Two per SRDO the safety service runs (its normal and inverted CAN-IDs), and GFC.
  static constexpr size_t kSafetyRoutes =
      features::kSafety ? 1U + 2U * (DictionaryCapacity::kSrdoCount < SafetyService::kSrdoCapacity
                                         ? DictionaryCapacity::kSrdoCount
                                         : SafetyService::kSrdoCapacity)
                        : 0U;
  /// NMT, SYNC, SDO, LSS, TIME (when compiled in), one per PDO and per consumed EMCY CAN-ID,
  /// and the safety service's.
  static constexpr size_t kRoutes =
      4U + (features::kTime ? 1U : 0U) + kRpdos + kTpdos + kEmcyConsumers + kSafetyRoutes;

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
                      kRoutes};
  }
};
}  // namespace detail

}  // namespace costa
