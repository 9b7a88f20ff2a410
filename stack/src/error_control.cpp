#include "costa/error_control.hpp"

#include "costa/cob_ids.hpp"
#include "costa/nmt_state_machine.hpp"

namespace costa {

// The services error control acts on, which are the state machine's (NmtStateMachine::Services).
od::ObjectDictionary& ErrorControl::dictionary() const noexcept {
  return nmt_.services().dictionary;
}
TransmitPath& ErrorControl::tx() const noexcept {
  return nmt_.services().tx;
}
EmcyProducer& ErrorControl::emcy() const noexcept {
  return nmt_.services().emcy;
}
NodeClock& ErrorControl::clock() const noexcept {
  return nmt_.services().clock;
}
const NodeListeners& ErrorControl::listeners() const noexcept {
  return nmt_.services().listeners;
}

void ErrorControl::reset(uint8_t nodeId) noexcept {
  // Monitoring starts over: the errors it had found are gone with it (EMCY 0x8130 cleared).
  if (profile_.emcyForErrors) {
    if (guarding_.expired()) {
      emcy().clear(kEmcyLifeGuardOrHeartbeat, 0);
    }
    for (uint8_t entry = 1;; ++entry) {
      const HeartbeatMonitor* monitor = consumer_.monitor(entry);
      if (monitor == nullptr) {
        break;  // past the last entry of 0x1016
      }
      if (monitor->timedOut || monitor->withdrawnFrom != 0U) {
        emcy().clear(kEmcyLifeGuardOrHeartbeat, entry);
      }
    }
  }
  guarding_.reset(nodeId, profile_.guardToggleStart);
  consumer_.configure(true);
}

bool ErrorControl::onFrame(const CanFrame& frame, uint8_t nodeId) noexcept {
  if (frame.rtr) {
    if (!features::kNodeGuarding || !profile_.nodeGuarding) {
      return false;  // a node without node guarding does not answer remote requests
    }
    if (frame.id != cob::kErrorControlBase + nodeId) {
      return true;
    }
    // CiA 301 7.2.8.3.2: with a heartbeat producer time, the heartbeat protocol is used, not
    // node guarding: a request is not answered, and the life guarding it would feed stops.
    if (dictionary().readUnsigned32(kHeartbeatProducerIndex, 0, 0) != 0U) {
      guarding_.ignoreRequest();
    } else if (guarding_.onRequest(nmt_.state(), clock().now) == NodeGuarding::Event::kResumed) {
      if (profile_.emcyForErrors) {
        emcy().clear(kEmcyLifeGuardOrHeartbeat, 0);
      }
      listeners().notify([](NodeEvents& listener) { listener.onLifeGuardingResumed(); });
    }
    return true;
  }
  if constexpr (!features::kHeartbeatConsumer) {
    return false;  // nobody here listens to heartbeats
  }
  if (frame.dlc == 1U && frame.id != cob::kErrorControlBase + nodeId) {
    const auto from = static_cast<uint8_t>(frame.id - cob::kErrorControlBase);
    onHeartbeatEvent(consumer_.onHeartbeat(from, frame.data[0], clock().now));
    clock().schedule(consumer_.nextDeadline());
  }
  return true;
}

void ErrorControl::process(Microseconds now) noexcept {
  if (guarding_.process(now) == NodeGuarding::Event::kLifeTimeExpired) {
    if (profile_.emcyForErrors) {
      emcy().raise(kEmcyLifeGuardOrHeartbeat, 0, kErrorCommunication);
    }
    listeners().notify([](NodeEvents& listener) { listener.onLifeGuardingExpired(); });
    onCommunicationError();
  }
  for (;;) {
    const HeartbeatConsumer::Event event = consumer_.process(now);
    if (event.kind == HeartbeatConsumer::EventKind::kNone) {
      break;
    }
    onHeartbeatEvent(event);
  }
}

void ErrorControl::onHeartbeatEvent(const HeartbeatConsumer::Event& event) noexcept {
  if (event.kind == HeartbeatConsumer::EventKind::kTimeout) {
    const uint8_t producer[5] = {event.nodeId, 0, 0, 0, 0};
    if (profile_.emcyForErrors) {
      emcy().raise(kEmcyLifeGuardOrHeartbeat, event.entry, kErrorCommunication, producer);
    }
    listeners().notify(
        [&event](NodeEvents& listener) { listener.onHeartbeatTimeout(event.nodeId); });
    onCommunicationError();
  } else if (event.kind != HeartbeatConsumer::EventKind::kNone) {
    // kResumed (the heartbeat is back) or kWithdrawn (the entry's new value starts monitoring
    // over, as reset communication does, reset()): either ends the error the entry had found.
    if (profile_.emcyForErrors) {
      emcy().clear(kEmcyLifeGuardOrHeartbeat, event.entry);
    }
    const bool resumed = event.kind == HeartbeatConsumer::EventKind::kResumed;
    listeners().notify([&event, resumed](NodeEvents& listener) {
      if (resumed) {
        listener.onHeartbeatResumed(event.nodeId);
      } else {
        listener.onHeartbeatWithdrawn(event.nodeId);
      }
    });
  }
}

void ErrorControl::onCommunicationError() noexcept {
  applyErrorBehaviour(static_cast<uint8_t>(
      dictionary().readUnsigned32(kErrorBehaviourIndex, 1, profile_.errorBehaviourWithoutObject)));
}

void ErrorControl::applyErrorBehaviour(uint8_t behaviour) noexcept {
  emcy().process(clock().now, nmt_.state(), tx());
  const NmtState state = nmt_.state();
  if (behaviour == kEnterPreOperational && state == NmtState::kOperational) {
    nmt_.enter(NmtState::kPreOperational);
  } else if (behaviour == kEnterStopped && state != NmtState::kInitialising) {
    nmt_.enter(NmtState::kStopped);
  }
}

void ErrorControl::onControllerEvent(CanControllerEvent event) noexcept {
  switch (event) {
    case CanControllerEvent::kRxOverrun:
      ++rxOverruns_;
      emcy().signal(kEmcyRxOverrun, kErrorCommunication);
      break;
    case CanControllerEvent::kErrorPassive:
      errorPassive_ = true;
      emcy().raise(kEmcyErrorPassive, 0, kErrorCommunication);
      break;
    case CanControllerEvent::kErrorActive:
      errorPassive_ = false;
      emcy().clear(kEmcyErrorPassive, 0);
      break;
    case CanControllerEvent::kBusOff:
      if (!busOff_) {
        busOff_ = true;
        ++busOffs_;
        tx().setGate(TransmitPath::kBusOff, true);
        listeners().notify([](NodeEvents& listener) { listener.onBusOff(); });
        onCommunicationError();
      }
      break;
    case CanControllerEvent::kBusOffRecovered:
      if (busOff_) {
        busOff_ = false;
        errorPassive_ = false;
        tx().setGate(TransmitPath::kBusOff, false);
        emcy().clear(kEmcyErrorPassive, 0);
        emcy().signal(kEmcyBusOffRecovered, kErrorCommunication);
        listeners().notify([](NodeEvents& listener) { listener.onBusOffRecovered(); });
      }
      break;
  }
}

}  // namespace costa
