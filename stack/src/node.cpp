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
      emcy_(dictionary_, settings_.profile.emcy, memory.emcyConditions, memory.emcyConditionCapacity,
            memory.emcyQueue, memory.emcyQueueCapacity),
      pdoContext_{access_, tx_,    settings_.profile.pdo,          emcy_,
                  events_, clock_, settings_.staticPdoMappings},
      sdo_(access_, tx_, settings_.profile.sdo, memory.sdoBuffer, memory.sdoBufferSize,
           settings.sdoTimeout),
      heartbeat_(dictionary_, tx_, clock_),
      heartbeatConsumer_(dictionary_, memory.heartbeatMonitors, memory.heartbeatMonitorCapacity),
      guarding_(dictionary_, tx_, clock_),
      sync_(dictionary_, tx_, emcy_, clock_),
      pdos_(pdoContext_, memory.rpdos, memory.rpdoCapacity, memory.tpdos, memory.tpdoCapacity),
      store_(dictionary_, settings.storage != nullptr ? *settings.storage : noStorage_,
             settings.storageSlotAlignment),
      storeCommands_(settings.storage != nullptr ? &store_ : nullptr, settings.storeAllGroups,
                     settings.restoreAllGroups),
      lssBridge_(*this),
      autoSave_(*this),
      lss_(tx_, lssBridge_),
      bitTiming_(settings.bitTiming),
      pendingBitTiming_(settings.bitTiming),
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
  hooks_.attach(StoreCommands::kStoreIndex, StoreCommands::kRestoreIndex, storeCommands_);
  storeCommands_.setRestoreAllListener(&lssBridge_);
  if constexpr (features::kParameterStorage) {
    if (settings_.saveParametersOnWrite) {
      access_.setObserver(&autoSave_);
    }
  }
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
  if (settings_.storage != nullptr) {
    store_.reserveRecord(kLssRecord, kLssRecordLength);
    storageReady_ = store_.layOut();
  }
  powerOn_ = true;
  resetNode();
}

void Node::loadLssConfiguration() noexcept {
  // Power-on values: the settings, replaced by a stored LSS configuration (at power-on only
  // when `storedNodeIdWins`: a node-id given by the integrator applies to the first start).
  pendingNodeId_ = settings_.nodeId;
  pendingBitTiming_ = settings_.bitTiming;
  if (!storageReady_) {
    return;
  }
  uint8_t record[kLssRecordLength] = {};
  size_t length = 0;
  const StoreResult result = store_.loadRecord(kLssRecord, record, sizeof(record), &length);
  if (result == StoreResult::kOk && length == sizeof(record)) {
    if (settings_.storedNodeIdWins || !powerOn_) {
      pendingNodeId_ = record[0];
    }
    pendingBitTiming_ = LssBitTiming{record[1], record[2]};
  } else if (result == StoreResult::kCorrupt || result == StoreResult::kIncompatible ||
             result == StoreResult::kMediumError) {
    invalid_.add(od::kGroupLss, result);
  }
}

void Node::loadGroups(uint32_t groups) noexcept {
  if (!storageReady_) {
    return;
  }
  for (uint8_t group = 1; group < 32U; ++group) {
    if ((groups & groupBit(group)) == 0U || !store_.hasGroup(group)) {
      continue;
    }
    const StoreResult result = store_.load(group);
    if (result == StoreResult::kCorrupt || result == StoreResult::kIncompatible ||
        result == StoreResult::kMediumError) {
      invalid_.add(group, result);
    }
  }
}

void Node::reportInvalidParameters() noexcept {
  for (size_t i = 0; i < invalid_.count; ++i) {
    if (events_ != nullptr) {
      events_->onStoredParametersInvalid(invalid_.groups[i], invalid_.results[i]);
    }
  }
  invalid_.count = 0;
}

void Node::resetNode() noexcept {
  setState(NmtState::kInitialising);
  loadLssConfiguration();  // reset node is a power-on reset of the application (CiA 301)
  powerOn_ = false;
  dictionary_.setNodeId(pendingNodeId_);
  dictionary_.restoreDefaults(kApplicationFirst, kApplicationLast);
  loadGroups(~(groupBit(od::kGroupCommunication) | groupBit(od::kGroupLss)));
  if (events_ != nullptr) {
    events_->onResetApplication();
  }
  reportInvalidParameters();
  resetCommunication();
}

LssIdentity Node::identity() const noexcept {
  LssIdentity id;
  id.vendorId = static_cast<uint32_t>(dictionary_.readUnsigned(0x1018, 1, 0));
  id.productCode = static_cast<uint32_t>(dictionary_.readUnsigned(0x1018, 2, 0));
  id.revisionNumber = static_cast<uint32_t>(dictionary_.readUnsigned(0x1018, 3, 0));
  id.serialNumber = static_cast<uint32_t>(dictionary_.readUnsigned(0x1018, 4, 0));
  return id;
}

void Node::resetCommunication() noexcept {
  setState(NmtState::kInitialising);
  sdo_.reset();
  heartbeat_.stop();
  if (features::kLss && settings_.lss && lss_.pendingNodeId() != lss_.activeNodeId()) {
    pendingNodeId_ = lss_.pendingNodeId();  // configured by LSS: applies now (CiA 305)
  }
  nodeId_ = cob::isValidNodeId(pendingNodeId_) ? pendingNodeId_ : cob::kLssUnconfigured;
  if (pendingBitTiming_ != bitTiming_) {
    switchBitTiming(pendingBitTiming_);  // before the boot-up frame, which uses the new rate
  }
  dictionary_.setNodeId(nodeId_);
  dictionary_.restoreDefaults(kCommunicationFirst, kCommunicationLast);
  loadGroups(groupBit(od::kGroupCommunication) | groupBit(od::kGroupLss));
  if (events_ != nullptr) {
    events_->onResetCommunication();  // the application may adjust the communication area
  }
  if constexpr (features::kLss) {
    lss_.reset(identity(), nodeId_, nodeId_, bitTiming_);
  }
  reportInvalidParameters();
  if (nodeId_ == cob::kLssUnconfigured) {
    flushTx();  // no node-id: the node waits, silent, for LSS to give it one (CiA 305)
    return;
  }
  sdo_.setNodeId(nodeId_);
  heartbeat_.setNodeId(nodeId_);
  emcy_.setNodeId(nodeId_);
  emcy_.onResetCommunication();
  guarding_.reset(nodeId_, settings_.profile.errorControl.guardToggleStart);
  heartbeatConsumer_.configure(true);
  sync_.configure(clock_.now);
  pdos_.configure();
  CanFrame bootUp;
  bootUp.id = cob::kErrorControlBase + nodeId_;
  bootUp.dlc = 1;
  bootUp.data[0] = static_cast<uint8_t>(NmtState::kInitialising);
  tx_.push(bootUp);
  setState(NmtState::kPreOperational);
  heartbeat_.restart(clock_.now);
  flushTx();
}

void Node::switchBitTiming(LssBitTiming timing) noexcept {
  // With a controller to re-time, the bit timing in use is the one the controller runs with: a
  // timing it refuses, or one without a CiA 305 bit rate, leaves it as it was (the pending one
  // is tried again at the next reset communication).
  CanBitRateControl* const control = settings_.bitRateControl;
  if (control != nullptr) {
    const uint32_t rate = bitRateOf(timing);
    if (rate == 0U || !control->setBitRate(rate)) {
      return;
    }
  }
  bitTiming_ = timing;
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

LssStoreResult Node::storeLssConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept {
  if (!storageReady_) {
    return LssStoreResult::kNotSupported;
  }
  const uint8_t record[kLssRecordLength] = {nodeId, timing.tableSelector, timing.tableIndex};
  return store_.saveRecord(kLssRecord, record, sizeof(record)) == StoreResult::kOk
             ? LssStoreResult::kStored
             : LssStoreResult::kStorageAccessError;
}

bool Node::LssBridge::bitTimingSupported(LssBitTiming timing) noexcept {
  return timing.tableSelector == 0U && timing.tableIndex < 16U &&
         (node_.settings_.lssBitRates & (1U << timing.tableIndex)) != 0U;
}

void Node::LssBridge::activateBitTiming(LssBitTiming timing) noexcept {
  node_.switchBitTiming(timing);  // the LSS slave suspends transmission until the switch ends
  node_.pendingBitTiming_ = timing;
  if (node_.events_ != nullptr) {
    node_.events_->onBitTimingActivation(timing);
  }
}

LssStoreResult Node::LssBridge::storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept {
  return node_.storeLssConfiguration(nodeId, timing);
}

void Node::LssBridge::requestResetCommunication() noexcept {
  node_.resetCommunication();
}

void Node::AutoSave::onWritten(const od::EntryRef& ref, bool changed) noexcept {
  if (changed && ref.group() != od::kGroupNone && node_.storageReady_) {
    node_.store_.save(ref.group());
  }
}

void Node::LssBridge::onRestoreAll() noexcept {
  if (node_.settings_.restoreAllIncludesLss && node_.storageReady_) {
    node_.store_.invalidateRecord(kLssRecord);
  }
}

}  // namespace costa
