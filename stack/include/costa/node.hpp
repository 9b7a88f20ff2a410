// A CANopen slave node: one object dictionary and the CiA 301 services acting on it. The node is
// the composition root and the façade: it owns the services, routes frames to them and passes
// the application's calls on; the services do the work (nmt_state_machine.hpp, error_control.hpp,
// transmit_path.hpp, frame_router.hpp, stored_parameters.hpp, ...).
//
// The node owns no memory of its own beyond its members: the caller provides every buffer (see
// NodeMemory, or use NodeInstance, which holds them). It never reads a clock, never blocks,
// never allocates, and is driven from one context (the main loop, never an interrupt):
//
//   node.start(now);                       // power-on: boot-up frame, pre-operational
//   node.onFrame(frame, now);              // every received frame, as soon as convenient
//   Microseconds next = node.process(now); // call again no later than `next`
//   node.flushTx();                        // when the controller has room again
//
// Event-driven: onFrame() handles its frame and sends the answers at once (a frame goes to the
// controller directly when nothing is queued ahead of it); it runs no timers. process() runs
// what is due and returns the next deadline, which the node keeps current as frames, writes,
// timers and application calls change it, so a process() with nothing due costs a comparison.
// A burst of frames costs one onFrame() each and one process() after them. Frames the controller
// refused wait in the transmit queue until flushTx() (or a process() that runs due work).
//
// `now` is a free-running 32-bit microsecond count that may wrap (costa/time.hpp); call
// process() by the time it returns (never 35 minutes or more after it).
//
// Several nodes, with the same or different dictionaries, may live in one program.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/bit_timing_switch.hpp"
#include "costa/emcy_producer.hpp"
#include "costa/error_control.hpp"
#include "costa/frame_router.hpp"
#include "costa/heartbeat_producer.hpp"
#include "costa/hook_registry.hpp"
#include "costa/hot_path.hpp"
#include "costa/lss_bridge.hpp"
#include "costa/nmt_state_machine.hpp"
#include "costa/node_clock.hpp"
#include "costa/node_events.hpp"
#include "costa/node_memory.hpp"
#include "costa/node_settings.hpp"
#include "costa/node_statistics.hpp"
#include "costa/object_access.hpp"
#include "costa/od/object_dictionary.hpp"
#include "costa/pdo_engine.hpp"
#include "costa/port/can_controller_event.hpp"
#include "costa/port/can_id_filter.hpp"
#include "costa/port/can_port.hpp"
#include "costa/sdo_server.hpp"
#include "costa/sdo_servers.hpp"
#include "costa/service_objects.hpp"
#include "costa/stored_parameters.hpp"
#include "costa/sync_service.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class Node {
 public:
  using LssSlaveService = NmtStateMachine::LssSlaveService;
  using HeartbeatConsumerService = ErrorControl::HeartbeatConsumerService;

  static constexpr uint8_t kLssRecord = StoredParameters::kLssRecord;
  static constexpr size_t kLssRecordLength = StoredParameters::kLssRecordLength;

  /// Sets the services up over `memory`; sends nothing until start(). O(objects).
  Node(const od::Definition& definition, const NodeMemory& memory, CanTransmitter& can,
       const NodeSettings& settings) noexcept
      : Node(definition, memory.values, memory, can, settings) {}
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  ~Node() = default;

  // --- Composition ---------------------------------------------------------------------------
  /// Adds a listener: every listener hears every event (NodeEvents), in the order added. False
  /// when NodeListeners::kCapacity are there already (counted: statistics().listenersRefused).
  [[nodiscard]] bool addListener(NodeEvents& listener) noexcept;
  /// Attaches `hook` to indices [first, last]; later attachments take precedence, also over the
  /// stack's own objects. False when the hook table (NodeMemory::hookCapacity) is full (counted:
  /// statistics().hooksRefused). Call before start(). O(1).
  [[nodiscard]] bool attachHook(uint16_t first, uint16_t last, ObjectHook& hook) noexcept;

  // --- Driving the node ------------------------------------------------------------------------
  /// Power-on: loads stored parameters, reset node, boot-up frame, pre-operational. Once.
  void start(Microseconds now) noexcept;
  /// Handles one received frame and sends its answers. Any content is safe: frames the node
  /// does not use are ignored and counted (statistics().framesIgnored). O(log routes) to find
  /// the service, plus the service's cost (an SDO access: O(log objects) and its hook).
  void onFrame(const CanFrame& frame, Microseconds now) noexcept;
  /// Runs what is due at `now`, offers queued frames to the controller, and returns the time by
  /// which it must be called again (kNever: nothing scheduled; `now` itself: call again at once,
  /// a block upload waiting for room; at the one instant whose value is kNever's, 1 µs before
  /// it, atOnce(now)). With nothing due and nothing queued it only compares `now` with that
  /// time.
  Microseconds process(Microseconds now) noexcept {
    clock_.advance(now);
    if (tx_.pending()) {
      flushTx();
    }
    return clock_.due() ? runDue() : clock_.next;
  }
  /// Offers queued frames to the controller again (after it signalled room); a block upload
  /// that waited for room continues at the next process(). O(frames sent).
  void flushTx() noexcept;
  bool txPending() const noexcept { return tx_.pending(); }
  uint32_t txDropped() const noexcept { return tx_.dropped(); }
  uint32_t txExpired() const noexcept { return tx_.expired(); }
  /// EMCY frames dropped because the EMCY queue (NodeMemory::emcyQueueCapacity frames waiting
  /// for their inhibit time) was full.
  uint32_t emcyLost() const noexcept { return emcy_.lost(); }

  // --- Acceptance filters --------------------------------------------------------------------
  /// The CAN-IDs the node listens to now, as acceptance filters for the controller's banks:
  /// one exact filter per CAN-ID of a service (NMT, SYNC, its SDO servers, each valid RPDO, each
  /// valid TPDO's remote request, LSS), in CAN-ID order, then 0x700/0x780 for the error control
  /// frames (other nodes' heartbeats, node guarding requests) once the node has a node-id, in a
  /// build with the heartbeat consumer or node guarding. Every
  /// frame the node uses passes; a few it does not use may (the rest of 0x700..0x77F). Writes at
  /// most `capacity` and returns how many filters there are: more than `capacity` means the
  /// controller must accept every standard frame. The node takes only standard frames. Call it
  /// from the context that runs the node, when receiveFiltersVersion() changed. O(routes).
  size_t receiveFilters(CanIdFilter* filters, size_t capacity) noexcept;
  /// Changes whenever receiveFilters() may answer differently: reset communication, a node-id
  /// given by LSS, a PDO's, SYNC's or additional SDO server's COB-ID written. A port keeps the
  /// value it programmed its filters for and compares it after each onFrame() and process().
  /// O(1).
  uint32_t receiveFiltersVersion() const noexcept { return router_.changes(); }

  // --- NMT ------------------------------------------------------------------------------------
  /// Local NMT control (not into or out of initialising; the resets below are the way there).
  void enterState(NmtState state) noexcept { nmt_.enter(state); }
  void resetNode() noexcept { nmt_.resetNode(); }
  void resetCommunication() noexcept { nmt_.resetCommunication(); }
  NmtState state() const noexcept { return nmt_.state(); }
  /// The node-id in use (1..127), or 0xFF while the node waits for LSS.
  uint8_t nodeId() const noexcept { return nmt_.nodeId(); }
  /// Node-id to use from the next reset communication on (1..127).
  void setPendingNodeId(uint8_t nodeId) noexcept { nmt_.setPendingNodeId(nodeId); }
  uint8_t pendingNodeId() const noexcept { return nmt_.pendingNodeId(); }
  /// Bit timing to use from the next reset communication on (devices that set it by SDO).
  void setPendingBitTiming(LssBitTiming timing) noexcept { bitTiming_.setPending(timing); }
  LssBitTiming pendingBitTiming() const noexcept { return bitTiming_.pending(); }
  /// Bit timing in use; with a NodeSettings::bitRateControl, the rate the controller accepted.
  LssBitTiming bitTiming() const noexcept { return bitTiming_.inUse(); }
  /// Enters operational by itself after every boot-up (NodeSettings::automaticStart). Takes
  /// effect at the next boot-up: a device object deciding it sets it at reset communication.
  void setAutomaticStart(bool on) noexcept { nmt_.setAutomaticStart(on); }

  // --- Application ----------------------------------------------------------------------------
  /// The application changed entry (index, subIndex): event-driven and synchronous acyclic
  /// TPDOs mapping it will be sent. O(TPDOs).
  void markChanged(uint16_t index, uint8_t subIndex) noexcept {
    pdos_.markChanged(index, subIndex);
  }
  /// An application event for the TPDO whose communication parameter is at `index`. False when
  /// there is none. O(TPDOs).
  [[nodiscard]] bool requestTpdo(uint16_t communicationIndex) noexcept {
    return pdos_.requestTransmission(communicationIndex);
  }
  /// Raises a device error: EMCY with `code`, `registerBits` (ErrorRegisterBit) and up to 5
  /// manufacturer-specific bytes; 0x1001 and 0x1003 follow (EmcyProducer::raise). False when the
  /// condition was already active or the condition table is full (the EMCY still goes out).
  /// `source` tells conditions of one code apart. With ErrorControlProfile::emcyForErrors, the
  /// node's own 0x8130 conditions use source 0 (life guarding) and n (entry n of 0x1016): a
  /// device that raises 0x8130 itself then uses other sources.
  bool raiseError(uint16_t code, uint8_t registerBits, const uint8_t* manufacturer = nullptr,
                  uint8_t source = 0) noexcept {
    return emcy_.raise(code, source, registerBits, manufacturer);
  }
  /// Clears a condition; the last one sends the error reset EMCY. False when it was not active.
  bool clearError(uint16_t code, uint8_t source = 0) noexcept { return emcy_.clear(code, source); }
  /// An error event without a lasting condition: one EMCY, recorded in 0x1003.
  void signalError(uint16_t code, uint8_t registerBits,
                   const uint8_t* manufacturer = nullptr) noexcept {
    emcy_.signal(code, registerBits, manufacturer);
  }
  uint8_t errorRegister() const noexcept { return emcy_.errorRegister(); }
  /// True while the condition (`code`, `source`) is active. O(conditions).
  bool errorActive(uint16_t code, uint8_t source = 0) const noexcept {
    return emcy_.active(code, source);
  }
  /// A CAN controller condition from the driver (ErrorControl::onControllerEvent); the EMCY it
  /// raises goes out before this returns.
  void onControllerEvent(CanControllerEvent event, Microseconds now) noexcept;
  bool busOff() const noexcept { return errorControl_.busOff(); }
  /// Writes an entry as a remote write does, through its hook (a service's own: 0x1017 restarts
  /// the heartbeat, a PDO parameter rebinds its PDO), but without access rights: the device's
  /// own way of configuring itself (a serial port, a keypad). Returns the CiA 301 abort code an
  /// SDO download would get (0x06020000 for a missing entry). O(log objects) and the hook.
  [[nodiscard]] AbortCode writeEntry(uint16_t index, uint8_t subIndex, const uint8_t* data,
                                     size_t length) noexcept;
  /// Saves storage groups now (bit g for group g: groupBit()), each on its own, with the
  /// power-loss guarantee of 0x1010: for vendor save objects. kNotLaidOut without storage.
  [[nodiscard]] StoreResult saveGroups(uint32_t groups) noexcept { return stored_.save(groups); }
  /// Stores the LSS configuration (node-id, bit timing) as LSS store configuration does.
  [[nodiscard]] LssStoreResult storeLssConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept {
    return stored_.storeLssConfiguration(nodeId, timing);
  }

  // --- TIME (features::kTime) -----------------------------------------------------------------
  /// The clock of day: set by the TIME frames the node consumes (0x1012 bit 31) or by
  /// setTimeOfDay(), running on with the node's clock. False while never set (or without TIME).
  bool timeOfDay(TimeOfDay* out) const noexcept { return time_.timeOfDay(clock_.now, out); }
  /// Sets the clock of day from the application's time source. False for milliseconds of a day
  /// or more (or without TIME).
  bool setTimeOfDay(const TimeOfDay& time) noexcept { return time_.setTimeOfDay(time, clock_.now); }
  /// A producer (0x1012 bit 30) sends TIME every `period` from now on (0: stops), in
  /// pre-operational and operational, once the clock of day is set.
  void setTimeProducerPeriod(Microseconds period) noexcept {
    time_.setProducerPeriod(period, clock_.now);
  }

  // --- Safety, CiA 304 (features::kSafety) --------------------------------------------------
  /// Sends the global fail-safe command (0x001) when 0x1300 enables it and the node is
  /// pre-operational or operational; false otherwise.
  bool sendGlobalFailSafe() noexcept { return safety_.sendGfc(preOrOperational()); }
  /// The port hook of the safety service: true while the application may be in its working
  /// state (operational, SRDO configuration valid, no failure since operational was entered);
  /// poll it. Without features::kSafety always true.
  bool workingStateAllowed() const noexcept { return safety_.workingStateAllowed(); }

  // --- Views ----------------------------------------------------------------------------------
  od::ObjectDictionary& dictionary() noexcept { return dictionary_; }
  const od::ObjectDictionary& dictionary() const noexcept { return dictionary_; }
  /// Every counter of the node and its services. O(1).
  NodeStatistics statistics() const noexcept;
  const DeviceProfile& profile() const noexcept { return settings_.profile; }
  /// The error control services; a device applies its own error behaviour object through it.
  ErrorControl& errorControl() noexcept { return errorControl_; }
  const HeartbeatConsumerService& heartbeatConsumer() const noexcept {
    return errorControl_.heartbeatConsumer();
  }
  const LssSlaveService& lss() const noexcept { return lss_; }
  /// The SDO server (read-only: whether a transfer runs, consistency checks).
  const SdoServer& sdo() const noexcept { return sdo_; }
  /// The additional SDO servers (0x1201..0x127F; a stand-in without features::kSdoServers).
  const SdoServersChoice& sdoServers() const noexcept { return sdoServers_; }
  const PdoEngine& pdos() const noexcept { return pdos_; }
  /// The parameter store when the node has storage (laid out), else null.
  ParameterStore* parameterStore() noexcept { return stored_.store(); }
  /// The latest `now` the node was given.
  Microseconds now() const noexcept { return clock_.now; }

 protected:
  /// The constructor over `memory`: a NodeMemory, or a NodeInstance's buffers
  /// (detail::NodeBuffers: the same names, the capacities constants), with the dictionary's
  /// RAM block `values`. Out of line: the buffers' addresses are offsets from `memory`.
  template <typename Memory>
  [[gnu::noinline]] Node(const od::Definition& definition, void* values, Memory& memory,
                         CanTransmitter& can, const NodeSettings& settings) noexcept;

 private:
  Microseconds runDue() noexcept;
  void buildRoutes() noexcept;
  /// onFrame() for an 8-byte request to the SDO server, while its CAN-ID is
  /// FrameRouter::fastId().
  [[gnu::noinline]] void onSdoRequest(const CanFrame& frame, Microseconds now) noexcept;
  /// onFrame() for every other frame: the table's route.
  [[gnu::noinline]] void routeFrame(const CanFrame& frame, Microseconds now) noexcept;
  COSTA_HOT_INLINE bool route(const RouteEntry& entry, const CanFrame& frame) noexcept;
  /// The routes after `entry` of a CAN-ID with several (a SYNC that is also an RPDO, ...).
  bool routeFurther(const RouteEntry* entry, const CanFrame& frame) noexcept;
  /// route() out of line, for those further routes.
  [[gnu::noinline]] bool routeOne(const RouteEntry& entry, const CanFrame& frame) noexcept;
  /// A frame without a route: error control (other nodes' heartbeats, guarding requests).
  bool errorControlFrame(const CanFrame& frame) noexcept;
  void handleSync(const SyncEvent& sync) noexcept;
  /// What the heartbeat shows: the NMT state, or the profile's byte while an error is active.
  NmtState heartbeatState() const noexcept {
    const uint8_t whileError = settings_.profile.errorControl.heartbeatWhileError;
    return whileError != 0U && emcy_.errorRegister() != 0U ? static_cast<NmtState>(whileError)
                                                           : nmt_.state();
  }
  bool preOrOperational() const noexcept {  // operational first: the usual state
    return nmt_.state() == NmtState::kOperational || nmt_.state() == NmtState::kPreOperational;
  }

  // In the order of the smallest image on Cortex-M0+ (measured, and no padding on 32-bit
  // targets): the PDOs and the routing table, which the node's own functions reach most, at
  // short offsets; SYNC and safety last.
  // (A constructor may keep a reference to a member declared after its own, never read it.)
  NodeSettings settings_;
  od::ObjectDictionary dictionary_;
  NodeClock clock_;
  PdoEngine pdos_;
  FrameRouter router_;
  NodeListeners listeners_;
  TransmitPath tx_;
  HookRegistry hooks_;
  ObjectAccess access_;
  EmcyProducer emcy_;
  PdoContext pdoContext_;
  SdoServer sdo_;
  SdoServersChoice sdoServers_;
  TimeServiceChoice time_;
  EmcyConsumerChoice emcyConsumer_;
  StoredParametersChoice stored_;
  BitTimingSwitch bitTiming_;
  ErrorControl errorControl_;
  LssBridgeChoice lssBridge_;
  LssSlaveService lss_;
  HeartbeatProducer heartbeat_;
  NmtStateMachine nmt_;
  SafetyServiceChoice safety_;
  SyncService sync_;
  ServiceObjects services_;  ///< after the services it names; access_ refers to it
  uint32_t framesIgnored_ = 0;
  uint32_t hooksRefused_ = 0;
};

template <typename Memory>
Node::Node(const od::Definition& definition, void* values, Memory& memory, CanTransmitter& can,
           const NodeSettings& settings) noexcept
    : settings_(settings),
      dictionary_(definition, values),
      pdos_(pdoContext_, memory.rpdos, memory.rpdoCapacity, memory.tpdos, memory.tpdoCapacity),
      router_(memory.routes, memory.routeCapacity),
      tx_(can, memory.txSlots, memory.txCapacity),
      hooks_(memory.hookSlots, memory.hookCapacity),
      access_(dictionary_, hooks_, services_),
      emcy_(dictionary_, settings_.profile.emcy, clock_, memory.emcyConditions,
            memory.emcyConditionCapacity, memory.emcyQueue, memory.emcyQueueCapacity),
      pdoContext_{access_, tx_, settings_.profile.pdo, emcy_, listeners_, clock_, router_},
      sdo_(access_, tx_, settings_.profile.sdo, clock_, memory.sdoBuffer, memory.sdoBufferSize,
           settings_.sdoTimeout),
      sdoServers_(access_, tx_, settings_.profile.sdo, clock_, memory.sdoServerSlots,
                  memory.sdoServerBuffers, memory.sdoBufferSize, memory.sdoServerCount,
                  settings_.sdoTimeout, router_),
      time_(dictionary_, tx_, clock_, router_),
      emcyConsumer_(listeners_, router_),
      stored_(dictionary_, settings_, listeners_),
      bitTiming_(settings_.bitRateControl, settings_.bitTiming),
      errorControl_(dictionary_, settings_.profile.errorControl, tx_, clock_, nmt_,
                    memory.heartbeatMonitors, memory.heartbeatMonitorCapacity),
      lssBridge_(nmt_),
      lss_(tx_, lssBridge_),
      heartbeat_(dictionary_, tx_, clock_),
      nmt_(NmtStateMachine::Services{dictionary_, settings_, clock_, listeners_, tx_, sdo_,
                                     sdoServers_, heartbeat_, emcy_, sync_, time_, pdos_,
                                     errorControl_, stored_, bitTiming_, lss_, router_},
           settings_.nodeId),
      safety_(SafetyService::Services{access_, tx_, emcy_, listeners_, router_, nmt_, clock_,
                                      memory.srdoChannels, static_cast<uint8_t>(memory.srdoCount)}),
      sync_(dictionary_, tx_, emcy_, clock_, router_),
      services_(ServiceObjects::Hooks{&emcy_, &sync_, &errorControl_.guardingObjects(),
                                      &stored_.commands(), &errorControl_.consumerObjects(),
                                      &heartbeat_, serviceHook(time_), serviceHook(emcyConsumer_),
                                      serviceHook(safety_), &pdos_, serviceHook(sdoServers_)}) {
  if constexpr (features::kParameterStorage) {
    access_.setObserver(stored_.autoSave());  // (without storage, nothing observes writes)
  }
  pdos_.bind();
}

extern template Node::Node(const od::Definition& definition, void* values, const NodeMemory& memory,
                           CanTransmitter& can, const NodeSettings& settings) noexcept;

/// A node together with its storage, sized at compile time from the generated dictionary
/// (`Values`, `Capacity` of a `costa::gen::NAME` namespace) and `Extra`.
template <typename Values, typename DictionaryCapacity, typename Extra = DefaultNodeCapacity>
class NodeInstance : private detail::NodeBuffers<Values, DictionaryCapacity, Extra>, public Node {
  using Buffers = detail::NodeBuffers<Values, DictionaryCapacity, Extra>;

 public:
  NodeInstance(const od::Definition& definition, CanTransmitter& can,
               const NodeSettings& settings) noexcept
      : Buffers{},
        Node(definition, &this->Buffers::values, static_cast<Buffers&>(*this), can, settings) {}

  /// The dictionary's RAM block, typed.
  Values& values() noexcept { return this->Buffers::values; }
};

}  // namespace costa
