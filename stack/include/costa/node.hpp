// A CANopen slave node: one object dictionary and the CiA 301 services acting on it.
//
// The node owns no memory of its own beyond its members: the caller provides every buffer
// (see NodeMemory, or use NodeInstance, which holds them). It never reads a clock, never
// blocks, never allocates, and is driven by three calls from one context (the main loop):
//
//   node.start(now);                       // power-on: boot-up frame, pre-operational
//   node.onFrame(frame, now);              // for every frame received
//   Microseconds next = node.process(now); // timers; call again no later than `next`
//
// Several nodes, with the same or different dictionaries, may live in one program.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/device_profile.hpp"
#include "costa/heartbeat_producer.hpp"
#include "costa/hook_registry.hpp"
#include "costa/nmt_state.hpp"
#include "costa/node_clock.hpp"
#include "costa/node_events.hpp"
#include "costa/object_access.hpp"
#include "costa/od/object_dictionary.hpp"
#include "costa/port/can_port.hpp"
#include "costa/sdo_server.hpp"
#include "costa/time.hpp"
#include "costa/tx_queue.hpp"

namespace costa {

/// Caller-owned storage of a node. Sizes are fixed for the node's lifetime.
struct NodeMemory {
  void* values;       ///< RAM block of the dictionary: Definition::valuesSize bytes.
  CanFrame* txSlots;  ///< Frames waiting for the controller.
  size_t txCapacity;
  uint8_t* sdoBuffer;  ///< Largest value downloadable by a segmented SDO transfer.
  size_t sdoBufferSize;
  HookBinding* hookSlots;  ///< Hooks of services and application.
  size_t hookCapacity;
};

struct NodeSettings {
  uint8_t nodeId = 1;                                          ///< 1..127.
  DeviceProfile profile{};                                     ///< Device-specific wire behaviour.
  Microseconds sdoTimeout = millisecondsToMicroseconds(1000);  ///< Segmented transfer timeout.
};

/// Counters of events that are nobody's fault but worth seeing.
struct NodeStatistics {
  uint32_t framesIgnored = 0;  ///< Frames addressed to nobody here or malformed.
  uint32_t txRefused = 0;      ///< Times the controller refused a frame (kept and retried).
};

class Node {
 public:
  Node(const od::Definition& definition, const NodeMemory& memory, CanTransmitter& can,
       const NodeSettings& settings) noexcept;
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  void setEvents(NodeEvents* events) noexcept { events_ = events; }

  /// Attaches a hook to indices [first, last]; later attachments take precedence. False when
  /// the hook storage is full.
  bool attachHook(uint16_t first, uint16_t last, ObjectHook& hook) noexcept;

  /// Power-on: reset application, reset communication, boot-up frame, pre-operational.
  void start(Microseconds now) noexcept;

  /// Handles one received frame. Frames the node does not use are ignored. Any content is safe.
  void onFrame(const CanFrame& frame, Microseconds now) noexcept;

  /// Runs due timers and passes queued frames to the controller. Returns the time by which it
  /// must be called again (kNever when nothing is scheduled).
  Microseconds process(Microseconds now) noexcept;

  /// Offers queued frames to the controller again (after it signalled free space).
  void flushTx() noexcept;
  bool txPending() const noexcept { return !tx_.empty(); }
  uint32_t txDropped() const noexcept { return tx_.dropped(); }

  /// Local NMT control (for example an automatic start after power-on).
  void enterState(NmtState state) noexcept;
  void resetNode() noexcept;
  void resetCommunication() noexcept;

  NmtState state() const noexcept { return state_; }
  uint8_t nodeId() const noexcept { return nodeId_; }
  /// Node-id to use from the next reset communication on (1..127).
  void setPendingNodeId(uint8_t nodeId) noexcept { pendingNodeId_ = nodeId; }

  od::ObjectDictionary& dictionary() noexcept { return dictionary_; }
  const od::ObjectDictionary& dictionary() const noexcept { return dictionary_; }
  const NodeStatistics& statistics() const noexcept { return statistics_; }
  Microseconds now() const noexcept { return clock_.now; }

 private:
  void setState(NmtState state) noexcept;
  void advanceClock(Microseconds now) noexcept;

  NodeSettings settings_;
  od::ObjectDictionary dictionary_;
  CanTransmitter& can_;
  TxQueue tx_;
  HookRegistry hooks_;
  ObjectAccess access_;
  NodeClock clock_;
  SdoServer sdo_;
  HeartbeatProducer heartbeat_;
  NodeEvents* events_ = nullptr;
  NodeStatistics statistics_;
  NmtState state_ = NmtState::kInitialising;
  uint8_t nodeId_;
  uint8_t pendingNodeId_;
};

/// Compile-time capacities of a NodeInstance beyond what the dictionary dictates.
struct DefaultNodeCapacity {
  static constexpr size_t kTxQueueDepth = 32;
  static constexpr size_t kHooks = 16;
  static constexpr size_t kMinimumSdoBuffer = 32;
};

namespace detail {
/// Storage of a NodeInstance; a base class so that it is initialised before the Node base.
template <typename Values, size_t TxDepth, size_t SdoBytes, size_t Hooks>
struct NodeStorage {
  Values values{};
  CanFrame tx[TxDepth]{};
  uint8_t sdo[SdoBytes]{};
  HookBinding hooks[Hooks]{};
};

template <typename DictionaryCapacity, typename Extra>
constexpr size_t sdoBufferSize() {
  return DictionaryCapacity::kLargestValue > Extra::kMinimumSdoBuffer
             ? DictionaryCapacity::kLargestValue
             : Extra::kMinimumSdoBuffer;
}
}  // namespace detail

/// A node together with its storage, sized at compile time from the generated dictionary
/// (`Values`, `Capacity` of a `costa::gen::NAME` namespace) and `Extra`.
template <typename Values, typename DictionaryCapacity, typename Extra = DefaultNodeCapacity>
class NodeInstance : private detail::NodeStorage<Values, Extra::kTxQueueDepth,
                                                 detail::sdoBufferSize<DictionaryCapacity, Extra>(),
                                                 Extra::kHooks>,
                     public Node {
  using Storage =
      detail::NodeStorage<Values, Extra::kTxQueueDepth,
                          detail::sdoBufferSize<DictionaryCapacity, Extra>(), Extra::kHooks>;

 public:
  NodeInstance(const od::Definition& definition, CanTransmitter& can,
               const NodeSettings& settings) noexcept
      : Storage{},
        Node(definition,
             NodeMemory{&this->Storage::values, this->Storage::tx, Extra::kTxQueueDepth,
                        this->Storage::sdo, sizeof(this->Storage::sdo), this->Storage::hooks,
                        Extra::kHooks},
             can, settings) {}

  /// The dictionary's RAM block, typed.
  Values& values() noexcept { return this->Storage::values; }
};

}  // namespace costa
