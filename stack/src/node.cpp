// Node construction, NMT state and resets.
#include "costa/node.hpp"

#include "costa/cob_ids.hpp"

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
      emcy_(dictionary_, settings_.profile, memory.emcyConditions, memory.emcyConditionCapacity,
            memory.emcyQueue, memory.emcyQueueCapacity),
      pdoContext_{access_, tx_,    settings_.profile,          emcy_,
                  events_, clock_, settings_.staticPdoMappings},
      sdo_(access_, tx_, settings_.profile, memory.sdoBuffer, memory.sdoBufferSize,
           settings.sdoTimeout),
      heartbeat_(dictionary_, tx_, clock_),
      heartbeatConsumer_(dictionary_, memory.heartbeatMonitors, memory.heartbeatMonitorCapacity,
                         clock_),
      guarding_(dictionary_, tx_, clock_),
      sync_(dictionary_, tx_, emcy_, clock_),
      pdos_(pdoContext_, memory.rpdos, memory.rpdoCapacity, memory.tpdos, memory.tpdoCapacity),
      nodeId_(settings.nodeId),
      pendingNodeId_(settings.nodeId) {
  hooks_.attach(EmcyProducer::kErrorHistoryIndex, EmcyProducer::kErrorHistoryIndex, emcy_);
  hooks_.attach(NodeGuarding::kGuardTimeIndex, NodeGuarding::kLifeTimeFactorIndex, guarding_);
  hooks_.attach(EmcyProducer::kCobIdIndex, EmcyProducer::kCobIdIndex, emcy_);
  hooks_.attach(SyncService::kCobIdIndex, SyncService::kWindowIndex, sync_);
  hooks_.attach(SyncService::kOverflowIndex, SyncService::kOverflowIndex, sync_);
  hooks_.attach(HeartbeatConsumer::kIndex, HeartbeatConsumer::kIndex, heartbeatConsumer_);
  hooks_.attach(HeartbeatProducer::kIndex, HeartbeatProducer::kIndex, heartbeat_);
  hooks_.attach(PdoEngine::kFirst, PdoEngine::kLast, pdos_);
  pdos_.bind();
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
  emcy_.setNodeId(nodeId_);
  emcy_.onResetCommunication();
  guarding_.reset(nodeId_, settings_.profile.guardToggleStart);
  heartbeatConsumer_.configure(true);
  sync_.configure(clock_.now);
  pdos_.configure();
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
  if (previous == NmtState::kOperational) {
    pdos_.stop();
  }
  if (state == NmtState::kOperational) {
    pdos_.start(clock_.now);
  }
  if (events_ != nullptr) {
    events_->onNmtStateChanged(previous, state);
  }
}

bool Node::emcyAllowed() const noexcept {
  return state_ == NmtState::kPreOperational || state_ == NmtState::kOperational;
}

void Node::onCommunicationError() noexcept {
  // The EMCY describing the error goes out before a change to stopped would silence it.
  emcy_.process(clock_.now, state_, tx_);
  const uint64_t behaviour = dictionary_.readUnsigned(kErrorBehaviourIndex, 1, 0);
  if (behaviour == 0U && state_ == NmtState::kOperational) {
    setState(NmtState::kPreOperational);
  } else if (behaviour == 2U && state_ != NmtState::kInitialising) {
    setState(NmtState::kStopped);
  }
}

void Node::onControllerEvent(CanControllerEvent event, Microseconds now) noexcept {
  advanceClock(now);
  switch (event) {
    case CanControllerEvent::kRxOverrun:
      ++statistics_.rxOverruns;
      emcy_.signal(kEmcyRxOverrun, kErrorCommunication);
      break;
    case CanControllerEvent::kErrorPassive:
      emcy_.raise(kEmcyErrorPassive, 0, kErrorCommunication);
      break;
    case CanControllerEvent::kErrorActive: emcy_.clear(kEmcyErrorPassive, 0); break;
    case CanControllerEvent::kBusOff:
      if (!busOff_) {
        busOff_ = true;
        ++statistics_.busOffs;
        if (events_ != nullptr) {
          events_->onBusOff();
        }
        onCommunicationError();
      }
      break;
    case CanControllerEvent::kBusOffRecovered:
      if (busOff_) {
        busOff_ = false;
        emcy_.clear(kEmcyErrorPassive, 0);
        emcy_.signal(kEmcyBusOffRecovered, kErrorCommunication);
        if (events_ != nullptr) {
          events_->onBusOffRecovered();
        }
      }
      break;
  }
  process(clock_.now);
}

}  // namespace costa
