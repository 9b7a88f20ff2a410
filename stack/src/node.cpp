#include "costa/node.hpp"

#include "costa/cob_ids.hpp"
#include "costa/nmt_slave.hpp"

namespace costa {
namespace {

constexpr uint16_t kCommunicationFirst = 0x1000;
constexpr uint16_t kCommunicationLast = 0x1FFF;
constexpr uint16_t kApplicationFirst = 0x2000;
constexpr uint16_t kApplicationLast = 0xFFFF;

}  // namespace

Node::Node(const od::Definition& definition, const NodeMemory& memory, CanTransmitter& can,
           const NodeSettings& settings) noexcept
    : settings_(settings),
      dictionary_(definition, memory.values),
      can_(can),
      tx_(memory.txSlots, memory.txCapacity),
      hooks_(memory.hookSlots, memory.hookCapacity),
      access_(dictionary_, hooks_),
      sdo_(access_, tx_, settings_.profile, memory.sdoBuffer, memory.sdoBufferSize,
           settings.sdoTimeout),
      heartbeat_(dictionary_, tx_, clock_),
      nodeId_(settings.nodeId),
      pendingNodeId_(settings.nodeId) {
  hooks_.attach(HeartbeatProducer::kIndex, HeartbeatProducer::kIndex, heartbeat_);
}

bool Node::attachHook(uint16_t first, uint16_t last, ObjectHook& hook) noexcept {
  return hooks_.attach(first, last, hook);
}

void Node::advanceClock(Microseconds now) noexcept {
  if (now > clock_.now) {
    clock_.now = now;
  }
}

void Node::start(Microseconds now) noexcept {
  advanceClock(now);
  resetNode();
}

void Node::resetNode() noexcept {
  setState(NmtState::kInitialising);
  dictionary_.setNodeId(pendingNodeId_);
  dictionary_.restoreDefaults(kApplicationFirst, kApplicationLast);
  if (events_ != nullptr) {
    events_->onResetApplication();
  }
  resetCommunication();
}

void Node::resetCommunication() noexcept {
  setState(NmtState::kInitialising);
  sdo_.reset();
  heartbeat_.stop();
  nodeId_ = pendingNodeId_;
  dictionary_.setNodeId(nodeId_);
  dictionary_.restoreDefaults(kCommunicationFirst, kCommunicationLast);
  sdo_.setNodeId(nodeId_);
  heartbeat_.setNodeId(nodeId_);
  if (events_ != nullptr) {
    events_->onResetCommunication();
  }
  CanFrame bootUp;
  bootUp.id = cob::kErrorControlBase + nodeId_;
  bootUp.dlc = 1;
  bootUp.data[0] = static_cast<uint8_t>(NmtState::kInitialising);
  tx_.push(bootUp);
  setState(NmtState::kPreOperational);
  heartbeat_.restart(clock_.now);
  flushTx();
}

void Node::enterState(NmtState state) noexcept {
  if (state_ == NmtState::kInitialising || state == NmtState::kInitialising) {
    return;
  }
  setState(state);
}

void Node::setState(NmtState state) noexcept {
  if (state == state_) {
    return;
  }
  const NmtState previous = state_;
  state_ = state;
  if (state == NmtState::kStopped) {
    sdo_.reset();
  }
  if (events_ != nullptr) {
    events_->onNmtStateChanged(previous, state);
  }
}

void Node::onFrame(const CanFrame& frame, Microseconds now) noexcept {
  advanceClock(now);
  if (frame.dlc > 8U || frame.extended) {
    ++statistics_.framesIgnored;
    return;
  }
  const bool sdoAllowed = state_ == NmtState::kPreOperational || state_ == NmtState::kOperational;
  if (frame.id == cob::kNmt) {
    const NmtSlave::Decision decision = NmtSlave::decide(frame, nodeId_, state_);
    switch (decision.action) {
      case NmtSlave::Action::kEnterState: setState(decision.state); break;
      case NmtSlave::Action::kResetNode: resetNode(); break;
      case NmtSlave::Action::kResetCommunication: resetCommunication(); break;
      case NmtSlave::Action::kNone: break;
    }
  } else if (frame.id == cob::kSdoRxBase + nodeId_ && sdoAllowed) {
    if (!sdo_.onRequest(frame, clock_.now)) {
      ++statistics_.framesIgnored;
    }
  } else {
    ++statistics_.framesIgnored;
  }
  flushTx();
}

Microseconds Node::process(Microseconds now) noexcept {
  advanceClock(now);
  sdo_.process(clock_.now);
  if (state_ != NmtState::kInitialising) {
    heartbeat_.process(clock_.now, state_);
  }
  flushTx();
  return earliest(sdo_.nextDeadline(), heartbeat_.nextDeadline());
}

void Node::flushTx() noexcept {
  while (!tx_.empty()) {
    if (!can_.tryTransmit(tx_.front())) {
      ++statistics_.txRefused;
      return;
    }
    tx_.pop();
  }
}

}  // namespace costa
