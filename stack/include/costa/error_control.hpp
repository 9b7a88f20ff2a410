// Error control of a node (CiA 301 7.2.8): node guarding and life guarding, the heartbeat
// consumer, the CAN controller's events, the EMCY they raise, and the communication error
// behaviour of 0x1029. Public, so that a device whose own object selects an error behaviour
// (Gefran 0x4000) applies it the same way: applyErrorBehaviour().
//
// Context: the one that runs the node. No allocation. onFrame() and onControllerEvent() are
// O(consumer entries); process() O(consumer entries) per event it reports.
#pragma once

#include <stdint.h>

#include "costa/compiled_out.hpp"
#include "costa/emcy_producer.hpp"
#include "costa/error_control_profile.hpp"
#include "costa/features.hpp"
#include "costa/heartbeat_consumer.hpp"
#include "costa/node_clock.hpp"
#include "costa/node_events.hpp"
#include "costa/node_guarding.hpp"
#include "costa/port/can_controller_event.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class NmtStateMachine;

class ErrorControl {
 public:
  using NodeGuardingService = ServiceIf<features::kNodeGuarding, NodeGuarding, AbsentNodeGuarding>;
  using HeartbeatConsumerService =
      ServiceIf<features::kHeartbeatConsumer, HeartbeatConsumer, AbsentHeartbeatConsumer>;

  static constexpr uint16_t kErrorBehaviourIndex = 0x1029;
  static constexpr uint16_t kHeartbeatProducerIndex = 0x1017;
  static constexpr uint16_t kEmcyLifeGuardOrHeartbeat = 0x8130;
  static constexpr uint16_t kEmcyRxOverrun = 0x8110;
  static constexpr uint16_t kEmcyErrorPassive = 0x8120;
  static constexpr uint16_t kEmcyBusOffRecovered = 0x8140;

  /// Error behaviour values (0x1029 sub-index 1, CiA 301 7.5.2.32).
  enum Behaviour : uint8_t {
    kEnterPreOperational = 0,  ///< operational nodes change to pre-operational
    kNoStateChange = 1,
    kEnterStopped = 2,
  };

  /// Over the node's state machine `nmt`, through which it reaches the other services it acts
  /// on (EMCY, listeners, ...); `dictionary`, `tx` and `clock` go to node guarding and the
  /// heartbeat consumer.
  ErrorControl(od::ObjectDictionary& dictionary, const ErrorControlProfile& profile,
               TransmitPath& tx, NodeClock& clock, NmtStateMachine& nmt, HeartbeatMonitor* monitors,
               size_t monitorCapacity) noexcept
      : profile_(profile),
        nmt_(nmt),
        guarding_(dictionary, tx, clock),
        consumer_(dictionary, clock, monitors, monitorCapacity) {}

  /// Reset communication: node guarding restarts (toggle from the profile's start value, life
  /// guarding stopped until the first request), every heartbeat consumer entry starts over.
  void reset(uint8_t nodeId) noexcept;

  /// A frame on 0x701..0x77F: a node guarding request for this node (answered when node
  /// guarding is compiled in and the profile has it), or another node's heartbeat. False when
  /// the frame is for no service here.
  [[nodiscard]] bool onFrame(const CanFrame& frame, uint8_t nodeId) noexcept;

  /// Life guarding expiry and heartbeat timeouts that are due: EMCY 0x8130 (profile), the
  /// listeners, then the communication error behaviour.
  void process(Microseconds now) noexcept;
  Microseconds nextDeadline() const noexcept {
    return earliest(guarding_.nextDeadline(), consumer_.nextDeadline());
  }

  /// A condition the CAN controller's driver reports: an overrun (EMCY 0x8110), error passive
  /// (0x8120 until error active again), bus-off (transmission held, the error behaviour
  /// applies), recovery from bus-off (transmission resumes, EMCY 0x8140).
  void onControllerEvent(CanControllerEvent event) noexcept;
  bool busOff() const noexcept { return busOff_; }
  /// The controller reported error passive (kErrorPassive) and not yet error active again.
  bool errorPassive() const noexcept { return errorPassive_; }

  /// A communication error (life guarding, heartbeat, bus-off): 0x1029 sub-index 1 decides.
  void onCommunicationError() noexcept;
  /// Applies an error behaviour: the EMCY describing the error leaves first (a change to
  /// stopped would hold it), then operational goes to pre-operational (kEnterPreOperational)
  /// or any state but initialising to stopped (kEnterStopped); other values change nothing.
  void applyErrorBehaviour(uint8_t behaviour) noexcept;

  /// The hooks of 0x100C/0x100D and of 0x1016 (stand-ins answering 0x06020000 when compiled out).
  ObjectHook& guardingObjects() noexcept { return *serviceHook(guarding_); }
  ObjectHook& consumerObjects() noexcept { return *serviceHook(consumer_); }
  const HeartbeatConsumerService& heartbeatConsumer() const noexcept { return consumer_; }

  uint32_t rxOverruns() const noexcept { return rxOverruns_; }
  uint32_t busOffs() const noexcept { return busOffs_; }

 private:
  void onHeartbeatEvent(const HeartbeatConsumer::Event& event) noexcept;

  // The services it acts on, through nmt_ (its references are the node's, kept once).
  od::ObjectDictionary& dictionary() const noexcept;
  TransmitPath& tx() const noexcept;
  EmcyProducer& emcy() const noexcept;
  NodeClock& clock() const noexcept;
  const NodeListeners& listeners() const noexcept;

  const ErrorControlProfile& profile_;
  NmtStateMachine& nmt_;
  NodeGuardingService guarding_;
  HeartbeatConsumerService consumer_;
  bool busOff_ = false;
  bool errorPassive_ = false;
  uint32_t rxOverruns_ = 0;
  uint32_t busOffs_ = 0;
};

}  // namespace costa
