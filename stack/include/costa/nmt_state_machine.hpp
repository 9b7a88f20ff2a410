// The NMT slave of a node (CiA 301 7.3.2): its state and node-id, the transitions NMT commands
// and the node itself ask for with their entry and exit actions, and the reset sequences
// (power-on, reset node, reset communication) that set every service up again.
//
//   transition                 actions
//   -> stopped                 the SDO server drops its transfer
//   operational ->             PDOs stop (held RPDO data, timers)
//   -> operational             PDOs start (SYNC counting, event timers, the profile's initial
//                              TPDOs)
//   every change               listeners hear of it; whatever the state allows becomes due
//
// Reset node: the application area (0x2000..0xFFFF) gets its defaults and stored values, the
// listeners hear onResetApplication, then reset communication. Reset communication: frames
// still queued are discarded, the communication area (0x1000..0x1FFF) gets its defaults and
// stored values, the node-id and bit timing configured by LSS (or stored) apply, listeners hear
// onResetCommunication, every service restarts, the boot-up frame goes out (it is never lost:
// the queue is empty) and the node is pre-operational; without a node-id it stays silent,
// waiting for LSS. A node with automatic start (NodeSettings::automaticStart) then enters
// operational at its next process().
//
// Context: the one that runs the node. No allocation. onCommand() and enter() are O(PDOs);
// the resets cost what loading stored parameters costs.
#pragma once

#include <stdint.h>

#include "costa/bit_timing_switch.hpp"
#include "costa/compiled_out.hpp"
#include "costa/emcy_producer.hpp"
#include "costa/features.hpp"
#include "costa/frame_router.hpp"
#include "costa/heartbeat_producer.hpp"
#include "costa/lss_slave.hpp"
#include "costa/nmt_state.hpp"
#include "costa/node_clock.hpp"
#include "costa/node_events.hpp"
#include "costa/node_settings.hpp"
#include "costa/pdo_engine.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/sdo_server.hpp"
#include "costa/sdo_servers.hpp"
#include "costa/stored_parameters.hpp"
#include "costa/sync_service.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class ErrorControl;

class NmtStateMachine {
 public:
  using LssSlaveService = ServiceIf<features::kLss, LssSlave, AbsentLssSlave>;

  /// The node's `Service` when it is compiled in; a compiled-out service's stand-in is
  /// stateless, so a copy of it does as well as the node's (and takes no reference).
  template <bool kCompiledIn, typename Service>
  using ServiceOf = ServiceIf<kCompiledIn, Service&, Service>;

  /// The services a reset sets up again and the state changes act on.
  struct Services {
    od::ObjectDictionary& dictionary;
    const NodeSettings& settings;
    NodeClock& clock;
    const NodeListeners& listeners;
    TransmitPath& tx;
    SdoServer& sdo;
    ServiceOf<features::kSdoServers, SdoServersChoice> sdoServers;
    HeartbeatProducer& heartbeat;
    EmcyProducer& emcy;
    SyncService& sync;
    ServiceOf<features::kTime, TimeServiceChoice> time;
    PdoEngine& pdos;
    ErrorControl& errorControl;
    StoredParametersChoice& stored;
    BitTimingSwitch& bitTiming;
    ServiceOf<features::kLss, LssSlaveService> lss;
    FrameRouter& router;
  };

  NmtStateMachine(const Services& services, uint8_t nodeId) noexcept
      : nodeId_(nodeId),
        pendingNodeId_(nodeId),
        automaticStart_(services.settings.automaticStart),
        services_(services) {}

  NmtState state() const noexcept { return state_; }
  /// The services it acts on (which the node's error control and LSS bridge act on too).
  const Services& services() const noexcept { return services_; }
  /// The node-id in use (1..127), or 0xFF: none yet.
  uint8_t nodeId() const noexcept { return nodeId_; }
  uint8_t pendingNodeId() const noexcept { return pendingNodeId_; }
  /// Node-id to use from the next reset communication on.
  void setPendingNodeId(uint8_t nodeId) noexcept { pendingNodeId_ = nodeId; }
  void setAutomaticStart(bool on) noexcept { automaticStart_ = on; }

  /// Power-on: the storage is laid out, then reset node.
  void powerOn() noexcept {
    services_.stored.layOut();
    powerOn_ = true;
    resetNode();
  }
  void resetNode() noexcept;
  void resetCommunication() noexcept;

  /// An NMT command (a frame on 0x000): acts on a well-formed command for this node or all
  /// nodes. Always true: every frame on 0x000 is the NMT's, so one that is malformed or for
  /// another node changes nothing and is not counted as ignored.
  [[nodiscard]] bool onCommand(const CanFrame& frame) noexcept;

  /// Changes the state with its exit and entry actions. Never into or out of initialising
  /// (only the resets go through it); a change to the current state does nothing.
  void enter(NmtState state) noexcept;

  /// Runs the automatic start when it is due.
  void process() noexcept {
    if (startPending_) {
      startPending_ = false;
      if (state_ == NmtState::kPreOperational) {
        setState(NmtState::kOperational);  // automatic start after the boot-up
      }
    }
  }
  Microseconds nextDeadline() const noexcept {
    return startPending_ ? services_.clock.now : kNever;
  }

 private:
  void setState(NmtState state) noexcept;
  LssIdentity identity() const noexcept;

  // The small fields first, within reach of Thumb-1's short offsets (the state is read on
  // every frame).
  NmtState state_ = NmtState::kInitialising;
  uint8_t nodeId_;
  uint8_t pendingNodeId_;
  bool powerOn_ = false;
  bool automaticStart_;
  bool startPending_ = false;
  Services services_;
};

}  // namespace costa
