#include "costa/error_control.hpp"

#include "costa/cob_ids.hpp"
#include "costa/nmt_state_machine.hpp"

namespace costa {

void ErrorControl::reset(uint8_t nodeId) noexcept {
  // Monitoring starts over: the errors it had found are gone with it (EMCY 0x8130 cleared).
  if (profile_.emcyForErrors) {
    if (guarding_.expired()) {
      emcy_.clear(kEmcyLifeGuardOrHeartbeat, 0);
    }
    for (uint8_t entry = 1;; ++entry) {
      const HeartbeatMonitor* monitor = consumer_.monitor(entry);
      if (monitor == nullptr) {
        break;  // past the last entry of 0x1016
      }
      if (monitor->timedOut || monitor->withdrawnFrom != 0U) {
        emcy_.clear(kEmcyLifeGuardOrHeartbeat, entry);
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
    if (dictionary_.readUnsigned32(kHeartbeatProducerIndex, 0, 0) != 0U) {
      guarding_.ignoreRequest();
    } else if (guarding_.onRequest(nmt_.state(), clock_.now) == NodeGuarding::Event::kResumed) {
      if (profile_.emcyForErrors) {
        emcy_.clear(kEmcyLifeGuardOrHeartbeat, 0);
      }
      listeners_.notify([](NodeEvents& listener) { listener.onLifeGuardingResumed(); });
    }
    return true;
  }
  if constexpr (!features::kHeartbeatConsumer) {
    return false;  // nobody here listens to heartbeats
  }
  if (frame.dlc == 1U && frame.id != cob::kErrorControlBase + nodeId) {
    const auto from = static_cast<uint8_t>(frame.id - cob::kErrorControlBase);
    onHeartbeatEvent(consumer_.onHeartbeat(from, frame.data[0], clock_.now));
    clock_.schedule(consumer_.nextDeadline());
  }
  return true;
}

void ErrorControl::process(Microseconds now) noexcept {
  if (guarding_.process(now) == NodeGuarding::Event::kLifeTimeExpired) {
    if (profile_.emcyForErrors) {
      emcy_.raise(kEmcyLifeGuardOrHeartbeat, 0, kErrorCommunication);
    }
    listeners_.notify([](NodeEvents& listener) { listener.onLifeGuardingExpired(); });
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
      emcy_.raise(kEmcyLifeGuardOrHeartbeat, event.entry, kErrorCommunication, producer);
    }
    listeners_.notify(
        [&event](NodeEvents& listener) { listener.onHeartbeatTimeout(event.nodeId); });
    onCommunicationError();
  } else if (event.kind != HeartbeatConsumer::EventKind::kNone) {
    // kResumed (the heartbeat is back) or kWithdrawn (the entry's new value starts monitoring
    // over, as reset communication does, reset()): either ends the error the entry had found.
    if (profile_.emcyForErrors) {
      emcy_.clear(kEmcyLifeGuardOrHeartbeat, event.entry);
    }
    const bool resumed = event.kind == HeartbeatConsumer::EventKind::kResumed;
    listeners_.notify([&event, resumed](NodeEvents& listener) {
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
      dictionary_.readUnsigned32(kErrorBehaviourIndex, 1, profile_.errorBehaviourWithoutObject)));
}

void ErrorControl::applyErrorBehaviour(uint8_t behaviour) noexcept {
  emcy_.process(clock_.now, nmt_.state(), tx_);
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
      emcy_.signal(kEmcyRxOverrun, kErrorCommunication);
      break;
    case CanControllerEvent::kErrorPassive:
      errorPassive_ = true;
      emcy_.raise(kEmcyErrorPassive, 0, kErrorCommunication);
      break;
    case CanControllerEvent::kErrorActive:
      errorPassive_ = false;
      emcy_.clear(kEmcyErrorPassive, 0);
      break;
    case CanControllerEvent::kBusOff:
      if (!busOff_) {
        busOff_ = true;
        ++busOffs_;
        tx_.setGate(TransmitPath::kBusOff, true);
        listeners_.notify([](NodeEvents& listener) { listener.onBusOff(); });
        onCommunicationError();
      }
      break;
    case CanControllerEvent::kBusOffRecovered:
      if (busOff_) {
        busOff_ = false;
        errorPassive_ = false;
        tx_.setGate(TransmitPath::kBusOff, false);
        emcy_.clear(kEmcyErrorPassive, 0);
        emcy_.signal(kEmcyBusOffRecovered, kErrorCommunication);
        listeners_.notify([](NodeEvents& listener) { listener.onBusOffRecovered(); });
      }
      break;
  }
}

}  // namespace costa
