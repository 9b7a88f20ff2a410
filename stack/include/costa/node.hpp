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

#include "costa/can_controller_event.hpp"
#include "costa/compiled_out.hpp"
#include "costa/device_profile.hpp"
#include "costa/emcy_producer.hpp"
#include "costa/features.hpp"
#include "costa/heartbeat_consumer.hpp"
#include "costa/heartbeat_producer.hpp"
#include "costa/hook_registry.hpp"
#include "costa/lss_slave.hpp"
#include "costa/nmt_state.hpp"
#include "costa/node_clock.hpp"
#include "costa/node_events.hpp"
#include "costa/node_guarding.hpp"
#include "costa/object_access.hpp"
#include "costa/od/object_dictionary.hpp"
#include "costa/parameter_store.hpp"
#include "costa/pdo_engine.hpp"
#include "costa/port/can_bit_rate.hpp"
#include "costa/port/can_port.hpp"
#include "costa/port/nv_storage.hpp"
#include "costa/sdo_server.hpp"
#include "costa/store_commands.hpp"
#include "costa/sync_service.hpp"
#include "costa/time.hpp"
#include "costa/tx_queue.hpp"

namespace costa {

/// Caller-owned storage of a node. Sizes are fixed for the node's lifetime.
struct NodeMemory {
  void* values;          ///< RAM block of the dictionary: Definition::valuesSize bytes.
  QueuedFrame* txSlots;  ///< Frames waiting for the controller.
  size_t txCapacity;
  uint8_t* sdoBuffer;  ///< Largest value downloadable by a segmented SDO transfer.
  size_t sdoBufferSize;
  HookBinding* hookSlots;  ///< Hooks of services and application.
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
};

/// Every storage group saved and restored by "all" (0x1010/0x1011 sub-index 1) by default: all
/// but the LSS group, which LSS stores on its own.
inline constexpr uint32_t kAllGroupsButLss = ~(groupBit(od::kGroupNone) | groupBit(od::kGroupLss));

struct NodeSettings {
  uint8_t nodeId = 1;       ///< 1..127, or 0xFF: no node-id yet (LSS only until configured).
  DeviceProfile profile{};  ///< Device-specific wire behaviour.
  Microseconds sdoTimeout = millisecondsToMicroseconds(1000);  ///< Segmented transfer timeout.
  StaticPdoMappings staticPdoMappings{};  ///< Mappings of PDOs without a mapping object.
  /// Non-volatile storage of parameters (0x1010/0x1011) and of the LSS configuration; null: none.
  /// Without effect when parameter storage is compiled out (features::kParameterStorage).
  NvStorage* storage = nullptr;
  /// Every stored slot starts at and spans a multiple of this many bytes: the erase page of a
  /// flash part, so that erasing one slot never touches another (docs/storage.md); 1: none.
  size_t storageSlotAlignment = 1;
  uint32_t storeAllGroups = kAllGroupsButLss;    ///< groups "save" to 0x1010:01 stores
  uint32_t restoreAllGroups = kAllGroupsButLss;  ///< groups "load" to 0x1011:01 restores
  bool restoreAllIncludesLss = false;  ///< 0x1011:01 also discards the stored LSS configuration
  bool lss = false;                    ///< CiA 305 LSS slave on 0x7E5 / 0x7E4 (features::kLss)
  uint16_t lssBitRates = 0;            ///< CiA 305 table indices the controller can switch to
  /// Bit timing at power-on (CiA 305 index 3: 250 kbit/s): the rate the integrator starts the
  /// CAN controller with. A stored LSS bit timing replaces it at power-on.
  LssBitTiming bitTiming{0, 3};
  /// The controller to re-time when the bit timing in use changes (LSS activate bit timing, a
  /// pending bit timing at reset communication or power-on); null: none, the node only records
  /// the change (and NodeEvents::onBitTimingActivation() tells the application of LSS's).
  CanBitRateControl* bitRateControl = nullptr;
  bool storedNodeIdWins = true;  ///< a stored LSS node-id replaces `nodeId` at power-on
  /// Every remote write that changes a stored entry saves its group at once (devices that keep
  /// parameters without a store command). CiA 301 saves only on 0x1010.
  bool saveParametersOnWrite = false;
};

/// Counters of events that are nobody's fault but worth seeing.
struct NodeStatistics {
  uint32_t framesIgnored = 0;  ///< Frames addressed to nobody here or malformed.
  uint32_t txRefused = 0;      ///< Times the controller refused a frame (kept and retried).
  uint32_t rxOverruns = 0;     ///< Overruns reported by the controller.
  uint32_t busOffs = 0;
};

class Node {
 public:
  /// The optional services of this build: the service, or its stand-in when compiled out.
  using NodeGuardingService = ServiceIf<features::kNodeGuarding, NodeGuarding, AbsentNodeGuarding>;
  using HeartbeatConsumerService =
      ServiceIf<features::kHeartbeatConsumer, HeartbeatConsumer, AbsentHeartbeatConsumer>;
  using LssSlaveService = ServiceIf<features::kLss, LssSlave, AbsentLssSlave>;
  using ParameterStoreService =
      ServiceIf<features::kParameterStorage, ParameterStore, AbsentParameterStore>;
  using StoreCommandsService =
      ServiceIf<features::kParameterStorage, StoreCommands, AbsentStoreCommands>;

  static constexpr uint16_t kErrorBehaviourIndex = 0x1029;
  static constexpr uint16_t kEmcyLifeGuardOrHeartbeat = 0x8130;
  static constexpr uint16_t kEmcyRxOverrun = 0x8110;
  static constexpr uint16_t kEmcyErrorPassive = 0x8120;
  static constexpr uint16_t kEmcyBusOffRecovered = 0x8140;
  static constexpr uint8_t kLssRecord = 1;  ///< ParameterStore record of the LSS configuration
  /// Bytes of that record: pending node-id, bit timing table selector, bit timing table index.
  static constexpr size_t kLssRecordLength = 3;

  Node(const od::Definition& definition, const NodeMemory& memory, CanTransmitter& can,
       const NodeSettings& settings) noexcept;
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  ~Node() = default;

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
  uint32_t txExpired() const noexcept { return tx_.expired(); }
  /// EMCY frames dropped because the EMCY queue (NodeMemory::emcyQueueCapacity frames waiting
  /// for their inhibit time) was full, since construction.
  uint32_t emcyLost() const noexcept { return emcy_.lost(); }

  /// Local NMT control (for example an automatic start after power-on).
  void enterState(NmtState state) noexcept;
  void resetNode() noexcept;
  void resetCommunication() noexcept;

  NmtState state() const noexcept { return state_; }
  uint8_t nodeId() const noexcept { return nodeId_; }
  /// Node-id to use from the next reset communication on (1..127).
  void setPendingNodeId(uint8_t nodeId) noexcept { pendingNodeId_ = nodeId; }
  uint8_t pendingNodeId() const noexcept { return pendingNodeId_; }
  /// Bit timing to use from the next reset communication on (devices that set it by SDO).
  void setPendingBitTiming(LssBitTiming timing) noexcept { pendingBitTiming_ = timing; }
  LssBitTiming pendingBitTiming() const noexcept { return pendingBitTiming_; }

  // --- Application API ---------------------------------------------------------------------
  /// The application changed entry (index, subIndex): event-driven and synchronous acyclic
  /// TPDOs mapping it will be sent.
  void markChanged(uint16_t index, uint8_t subIndex) noexcept {
    pdos_.markChanged(index, subIndex);
  }
  /// Asks the TPDO whose communication parameter is at `index` to send (an application event).
  bool requestTpdo(uint16_t communicationIndex) noexcept {
    return pdos_.requestTransmission(communicationIndex);
  }
  /// Raises a device error: EMCY with `code`, `registerBits` (ErrorRegisterBit) and up to 5
  /// manufacturer-specific bytes; the error register and 0x1003 follow. See EmcyProducer.
  bool raiseError(uint16_t code, uint8_t registerBits, const uint8_t* manufacturer = nullptr,
                  uint8_t source = 0) noexcept {
    return emcy_.raise(code, source, registerBits, manufacturer);
  }
  bool clearError(uint16_t code, uint8_t source = 0) noexcept { return emcy_.clear(code, source); }
  void signalError(uint16_t code, uint8_t registerBits,
                   const uint8_t* manufacturer = nullptr) noexcept {
    emcy_.signal(code, registerBits, manufacturer);
  }
  uint8_t errorRegister() const noexcept { return emcy_.errorRegister(); }
  /// Reports a CAN controller condition (from the driver's status or interrupt).
  void onControllerEvent(CanControllerEvent event, Microseconds now) noexcept;
  bool busOff() const noexcept { return busOff_; }

  od::ObjectDictionary& dictionary() noexcept { return dictionary_; }
  const od::ObjectDictionary& dictionary() const noexcept { return dictionary_; }
  const NodeStatistics& statistics() const noexcept { return statistics_; }
  const DeviceProfile& profile() const noexcept { return settings_.profile; }
  const HeartbeatConsumerService& heartbeatConsumer() const noexcept { return heartbeatConsumer_; }
  const LssSlaveService& lss() const noexcept { return lss_; }
  /// The SDO server (read-only: whether a transfer runs, consistency checks).
  const SdoServer& sdo() const noexcept { return sdo_; }
  /// Bit timing in use (CiA 305 table selector and index). With a NodeSettings::bitRateControl,
  /// the rate the controller last accepted.
  LssBitTiming bitTiming() const noexcept { return bitTiming_; }
  /// The parameter store when the node has storage (laid out), else null.
  ParameterStore* parameterStore() noexcept {
    return storageReady_ ? parameterStoreOf(store_) : nullptr;
  }
  /// Stores the LSS configuration (node-id, bit timing) as LSS "store configuration" does.
  LssStoreResult storeLssConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept;
  const PdoEngine& pdos() const noexcept { return pdos_; }
  Microseconds now() const noexcept { return clock_.now; }

 private:
  void setState(NmtState state) noexcept;
  void advanceClock(Microseconds now) noexcept;
  void handleSync(const SyncEvent& sync) noexcept;
  bool handleErrorControl(const CanFrame& frame) noexcept;
  void handleHeartbeatEvent(const HeartbeatConsumer::Event& event) noexcept;
  void onCommunicationError() noexcept;
  bool emcyAllowed() const noexcept;
  void loadGroups(uint32_t groups) noexcept;
  void reportInvalidParameters() noexcept;
  void loadLssConfiguration() noexcept;
  /// Re-times the controller (when there is one to re-time) and makes `timing` the one in use
  /// if it accepted.
  void switchBitTiming(LssBitTiming timing) noexcept;
  LssIdentity identity() const noexcept;

  /// The node's side of the LSS slave and of "restore all".
  class LssBridge final : public LssSlaveHost, public StoreCommands::RestoreAllListener {
   public:
    explicit LssBridge(Node& node) noexcept : node_(node) {}
    bool bitTimingSupported(LssBitTiming timing) noexcept override;
    void activateBitTiming(LssBitTiming timing) noexcept override;
    LssStoreResult storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept override;
    void requestResetCommunication() noexcept override;
    void onRestoreAll() noexcept override;

   private:
    Node& node_;
  };
  class NoStorage final : public NvStorage {};
  /// Saves the group of a changed entry when NodeSettings::saveParametersOnWrite.
  class AutoSave final : public WriteObserver {
   public:
    explicit AutoSave(Node& node) noexcept : node_(node) {}
    void onWritten(const od::EntryRef& ref, bool changed) noexcept override;

   private:
    Node& node_;
  };

  NodeSettings settings_;
  od::ObjectDictionary dictionary_;
  CanTransmitter& can_;
  TxQueue tx_;
  HookRegistry hooks_;
  ObjectAccess access_;
  NodeClock clock_;
  NodeEvents* events_ = nullptr;
  EmcyProducer emcy_;
  PdoContext pdoContext_;
  SdoServer sdo_;
  HeartbeatProducer heartbeat_;
  HeartbeatConsumerService heartbeatConsumer_;
  NodeGuardingService guarding_;
  SyncService sync_;
  PdoEngine pdos_;
  NoStorage noStorage_;
  ParameterStoreService store_;
  bool storageReady_ = false;
  bool powerOn_ = false;
  StoreCommandsService storeCommands_;
  LssBridge lssBridge_;
  AutoSave autoSave_;
  LssSlaveService lss_;
  LssBitTiming bitTiming_;
  LssBitTiming pendingBitTiming_;
  struct InvalidParameters {
    uint8_t groups[8] = {};
    StoreResult results[8] = {};
    size_t count = 0;
    void add(uint8_t group, StoreResult result) noexcept {
      if (count < 8U) {
        groups[count] = group;
        results[count] = result;
        ++count;
      }
    }
  } invalid_;
  NodeStatistics statistics_;
  NmtState state_ = NmtState::kInitialising;
  uint8_t nodeId_;
  uint8_t pendingNodeId_;
  bool busOff_ = false;
};

/// Compile-time capacities of a NodeInstance beyond what the dictionary dictates.
struct DefaultNodeCapacity {
  static constexpr size_t kTxQueueDepth = 32;
  static constexpr size_t kHooks = 24;
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
struct NodeStorage {
  static constexpr size_t kSdoBytes = DictionaryCapacity::kLargestValue > Extra::kMinimumSdoBuffer
                                          ? DictionaryCapacity::kLargestValue
                                          : Extra::kMinimumSdoBuffer;
  static constexpr size_t kRpdos = atLeastOne(DictionaryCapacity::kRpdoCount);
  static constexpr size_t kTpdos = atLeastOne(DictionaryCapacity::kTpdoCount);
  static constexpr size_t kMonitors =
      features::kHeartbeatConsumer ? atLeastOne(DictionaryCapacity::kHeartbeatConsumers) : 1U;

  Values values{};
  QueuedFrame tx[Extra::kTxQueueDepth]{};
  uint8_t sdo[kSdoBytes]{};
  HookBinding hooks[Extra::kHooks]{};
  RpdoChannel rpdos[kRpdos]{};
  TpdoChannel tpdos[kTpdos]{};
  EmcyCondition emcyConditions[Extra::kEmcyConditions]{};
  PendingEmcy emcyQueue[Extra::kEmcyQueueDepth]{};
  HeartbeatMonitor monitors[kMonitors]{};

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
                      kMonitors};
  }
};
}  // namespace detail

/// A node together with its storage, sized at compile time from the generated dictionary
/// (`Values`, `Capacity` of a `costa::gen::NAME` namespace) and `Extra`.
template <typename Values, typename DictionaryCapacity, typename Extra = DefaultNodeCapacity>
class NodeInstance : private detail::NodeStorage<Values, DictionaryCapacity, Extra>, public Node {
  using Storage = detail::NodeStorage<Values, DictionaryCapacity, Extra>;

 public:
  NodeInstance(const od::Definition& definition, CanTransmitter& can,
               const NodeSettings& settings) noexcept
      : Storage{}, Node(definition, Storage::memory(), can, settings) {}

  /// The dictionary's RAM block, typed.
  Values& values() noexcept { return this->Storage::values; }
};

}  // namespace costa
