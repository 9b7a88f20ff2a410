// Node: received frames to services, timers, and the transmit path.
#include "costa/cob_ids.hpp"
#include "costa/nmt_slave.hpp"
#include "costa/node.hpp"

namespace costa {
namespace {

// The node-id an error control frame (0x701..0x77F) comes from or is addressed to.
uint8_t errorControlNodeId(const CanFrame& frame) noexcept {
  return static_cast<uint8_t>(frame.id - cob::kErrorControlBase);
}

}  // namespace

void Node::onFrame(const CanFrame& frame, Microseconds now) noexcept {
  advanceClock(now);
  if (frame.dlc > 8U || frame.extended) {
    ++statistics_.framesIgnored;
    return;
  }
  bool used = false;
  if (features::kLss && frame.id == cob::kLssFromMaster && settings_.lss) {
    used = lss_.onFrame(frame, clock_.now);
  } else if (nodeId_ == cob::kLssUnconfigured) {
    used = false;  // LSS only until the node has a node-id
  } else if (frame.id == cob::kNmt) {
    const NmtSlave::Decision decision = NmtSlave::decide(frame, nodeId_, state_);
    used = true;
    switch (decision.action) {
      case NmtSlave::Action::kEnterState: setState(decision.state); break;
      case NmtSlave::Action::kResetNode: resetNode(); break;
      case NmtSlave::Action::kResetCommunication: resetCommunication(); break;
      case NmtSlave::Action::kNone: break;
    }
  } else if (state_ != NmtState::kInitialising) {
    const bool preOrOperational =
        state_ == NmtState::kPreOperational || state_ == NmtState::kOperational;
    if (frame.id > cob::kErrorControlBase && frame.id <= cob::kErrorControlBase + 127U) {
      used = handleErrorControl(frame);
    } else if (preOrOperational && sync_.accepts(frame)) {
      SyncEvent sync;
      if (sync_.onFrame(frame, clock_.now, &sync)) {
        handleSync(sync);
      }
      used = true;
    } else if (preOrOperational && frame.id == cob::kSdoRxBase + nodeId_) {
      used = sdo_.onRequest(frame, clock_.now);
    } else if (state_ == NmtState::kOperational) {
      used = pdos_.onFrame(frame, clock_.now);
    }
  }
  if (!used) {
    ++statistics_.framesIgnored;
  }
  process(clock_.now);
}

bool Node::handleErrorControl(const CanFrame& frame) noexcept {
  if (frame.rtr) {
    if constexpr (!features::kNodeGuarding) {
      return false;  // a node without node guarding does not answer remote requests
    }
    if (!settings_.profile.errorControl.nodeGuarding) {
      return false;  // a device with heartbeat only does not either
    }
    if (errorControlNodeId(frame) == nodeId_) {
      const NodeGuarding::Event event = guarding_.onRequest(state_, clock_.now);
      if (event == NodeGuarding::Event::kResumed) {
        if (settings_.profile.errorControl.emcyForErrors) {
          emcy_.clear(kEmcyLifeGuardOrHeartbeat, 0);
        }
        if (events_ != nullptr) {
          events_->onLifeGuardingResumed();
        }
      }
    }
    return true;
  }
  if constexpr (!features::kHeartbeatConsumer) {
    return false;  // nobody here listens to heartbeats
  }
  const uint8_t producer = errorControlNodeId(frame);
  if (frame.dlc == 1U && producer != nodeId_) {
    handleHeartbeatEvent(heartbeatConsumer_.onHeartbeat(producer, frame.data[0], clock_.now));
  }
  return true;
}

void Node::handleHeartbeatEvent(const HeartbeatConsumer::Event& event) noexcept {
  if (event.kind == HeartbeatConsumer::EventKind::kTimeout) {
    const uint8_t producer[5] = {event.nodeId, 0, 0, 0, 0};
    if (settings_.profile.errorControl.emcyForErrors) {
      emcy_.raise(kEmcyLifeGuardOrHeartbeat, event.entry, kErrorCommunication, producer);
    }
    if (events_ != nullptr) {
      events_->onHeartbeatTimeout(event.nodeId);
    }
    onCommunicationError();
  } else if (event.kind == HeartbeatConsumer::EventKind::kResumed) {
    if (settings_.profile.errorControl.emcyForErrors) {
      emcy_.clear(kEmcyLifeGuardOrHeartbeat, event.entry);
    }
    if (events_ != nullptr) {
      events_->onHeartbeatResumed(event.nodeId);
    }
  }
}

void Node::handleSync(const SyncEvent& sync) noexcept {
  if (state_ == NmtState::kOperational) {
    pdos_.onSync(sync.counter, sync.time, sync.windowEnd);
  }
  if (events_ != nullptr) {
    events_->onSync(sync.counter);
  }
}

Microseconds Node::process(Microseconds now) noexcept {
  advanceClock(now);
  const Microseconds at = clock_.now;
  sdo_.process(at);
  lss_.process(at);
  if (state_ != NmtState::kInitialising) {
    heartbeat_.process(at, state_);
    if (guarding_.process(at) == NodeGuarding::Event::kLifeTimeExpired) {
      if (settings_.profile.errorControl.emcyForErrors) {
        emcy_.raise(kEmcyLifeGuardOrHeartbeat, 0, kErrorCommunication);
      }
      if (events_ != nullptr) {
        events_->onLifeGuardingExpired();
      }
      onCommunicationError();
    }
    for (;;) {
      const HeartbeatConsumer::Event event = heartbeatConsumer_.process(at);
      if (event.kind == HeartbeatConsumer::EventKind::kNone) {
        break;
      }
      handleHeartbeatEvent(event);
    }
    SyncEvent sync;
    const bool preOrOperational =
        state_ == NmtState::kPreOperational || state_ == NmtState::kOperational;
    if (sync_.process(at, preOrOperational, &sync)) {
      handleSync(sync);
    }
    pdos_.process(at);
    emcy_.process(at, state_, tx_);
  }
  flushTx();
  Microseconds next = earliest(sdo_.nextDeadline(), heartbeat_.nextDeadline());
  next = earliest(next, guarding_.nextDeadline());
  next = earliest(next, heartbeatConsumer_.nextDeadline());
  next = earliest(next, sync_.nextDeadline());
  next = earliest(next, pdos_.nextDeadline());
  next = earliest(next, emcy_.nextDeadline(state_));
  next = earliest(next, lss_.nextDeadline());
  return next;
}

void Node::flushTx() noexcept {
  while (!tx_.empty() && !busOff_ && !lss_.transmissionSuspended()) {
    const QueuedFrame& queued = tx_.front();
    if (queued.expiry != kNever && clock_.now > queued.expiry) {
      tx_.expireFront();
      continue;
    }
    if (!can_.tryTransmit(queued.frame)) {
      ++statistics_.txRefused;
      return;
    }
    tx_.pop();
  }
}

}  // namespace costa
