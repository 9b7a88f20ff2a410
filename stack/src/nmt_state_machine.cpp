#include "costa/nmt_state_machine.hpp"

#include "costa/cob_ids.hpp"
#include "costa/error_control.hpp"
#include "costa/nmt_slave.hpp"

namespace costa {
namespace {

constexpr uint16_t kCommunicationFirst = 0x1000;
constexpr uint16_t kCommunicationLast = 0x1FFF;
constexpr uint16_t kApplicationFirst = 0x2000;
constexpr uint16_t kApplicationLast = 0xFFFF;

}  // namespace

void NmtStateMachine::resetNode() noexcept {
  setState(NmtState::kInitialising);
  // Reset node is a power-on reset of the application (CiA 301): the LSS configuration is read
  // again.
  LssBitTiming timing;
  services_.stored.loadLssConfiguration(powerOn_, &pendingNodeId_, &timing);
  services_.bitTiming.setPending(timing);
  powerOn_ = false;
  od::ObjectDictionary& dictionary = services_.dictionary;
  dictionary.setNodeId(pendingNodeId_);
  dictionary.restoreDefaults(kApplicationFirst, kApplicationLast);
  services_.stored.loadGroups(~(groupBit(od::kGroupCommunication) | groupBit(od::kGroupLss)));
  services_.listeners.notify([](NodeEvents& listener) { listener.onResetApplication(); });
  services_.stored.reportInvalid();
  resetCommunication();
}

LssIdentity NmtStateMachine::identity() const noexcept {
  const od::ObjectDictionary& dictionary = services_.dictionary;
  LssIdentity id;
  id.vendorId = dictionary.readUnsigned32(0x1018, 1, 0);
  id.productCode = dictionary.readUnsigned32(0x1018, 2, 0);
  id.revisionNumber = dictionary.readUnsigned32(0x1018, 3, 0);
  id.serialNumber = dictionary.readUnsigned32(0x1018, 4, 0);
  return id;
}

void NmtStateMachine::resetCommunication() noexcept {
  setState(NmtState::kInitialising);
  startPending_ = false;
  services_.sdo.reset();
  services_.sdoServers.reset();
  services_.heartbeat.stop();
  services_.tx.discardQueued();  // what waited belongs to the state the node leaves
  auto& lss = services_.lss;
  if (features::kLss && services_.settings.lss && lss.pendingNodeId() != lss.activeNodeId()) {
    pendingNodeId_ = lss.pendingNodeId();  // configured by LSS: applies now (CiA 305)
  }
  nodeId_ = cob::isValidNodeId(pendingNodeId_) ? pendingNodeId_ : cob::kLssUnconfigured;
  // Before the boot-up frame, which uses the new rate.
  services_.bitTiming.applyPending(services_.settings.manufacturerBitRates);
  od::ObjectDictionary& dictionary = services_.dictionary;
  dictionary.setNodeId(nodeId_);
  dictionary.restoreDefaults(kCommunicationFirst, kCommunicationLast);
  services_.stored.loadGroups(groupBit(od::kGroupCommunication) | groupBit(od::kGroupLss));
  services_.listeners.notify([](NodeEvents& listener) { listener.onResetCommunication(); });
  if constexpr (features::kLss) {
    lss.reset(identity(), nodeId_, nodeId_, services_.bitTiming.inUse());
  }
  services_.tx.setGate(TransmitPath::kBitTiming, false);
  services_.stored.reportInvalid();
  services_.router.invalidate();
  if (nodeId_ == cob::kLssUnconfigured) {
    return;  // no node-id: the node waits, silent, for LSS to give it one (CiA 305)
  }
  services_.sdo.setNodeId(nodeId_);
  services_.heartbeat.setNodeId(nodeId_);
  services_.emcy.setNodeId(nodeId_);
  services_.emcy.onResetCommunication();
  // cppcheck-suppress knownConditionTrueFalse ; two independent switches that may agree
  if constexpr (features::kHeartbeatConsumer || features::kNodeGuarding) {
    services_.errorControl.reset(nodeId_);  // (without them, error control has nothing to reset)
  }
  services_.sync.configure(services_.clock.now);
  services_.time.configure();
  services_.pdos.configure();
  services_.heartbeat.send(NmtState::kInitialising);  // the boot-up frame
  setState(NmtState::kPreOperational);
  services_.heartbeat.restart(services_.clock.now);
  if (automaticStart_) {
    startPending_ = true;  // at the next process(), after the device has run
    services_.clock.scheduleNow();
  }
}

bool NmtStateMachine::onCommand(const CanFrame& frame) noexcept {
  const NmtSlave::Decision decision = NmtSlave::decide(frame, nodeId_, state_);
  switch (decision.action) {
    // (decide() asks for no state change while initialising, nor for initialising itself)
    case NmtSlave::Action::kEnterState: setState(decision.state); break;
    case NmtSlave::Action::kResetNode: resetNode(); break;
    case NmtSlave::Action::kResetCommunication: resetCommunication(); break;
    case NmtSlave::Action::kNone: break;
  }
  return true;
}

void NmtStateMachine::enter(NmtState state) noexcept {
  if (state_ == NmtState::kInitialising || state == NmtState::kInitialising) {
    return;
  }
  setState(state);
}

void NmtStateMachine::setState(NmtState state) noexcept {
  if (state == state_) {
    return;
  }
  const NmtState previous = state_;
  state_ = state;
  if (state == NmtState::kStopped) {
    services_.sdo.reset();
    services_.sdoServers.reset();
    services_.sync.restartCounter();
  }
  if (previous == NmtState::kOperational) {
    services_.pdos.stop();
  } else if (state == NmtState::kOperational) {  // a change: not from operational
    services_.pdos.start(services_.clock.now);
  }
  services_.clock.scheduleNow();  // what the new state allows may be due
  services_.listeners.notify(
      [previous, state](NodeEvents& listener) { listener.onNmtStateChanged(previous, state); });
}

}  // namespace costa
