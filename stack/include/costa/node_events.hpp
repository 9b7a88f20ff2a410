// What a device application hears from its node.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/emcy_message.hpp"
#include "costa/lss_slave.hpp"
#include "costa/nmt_state.hpp"
#include "costa/parameter_store.hpp"
#include "costa/srdo_failure.hpp"

namespace costa {

/// What a listener hears from its node. Implemented by a device application, a profile layer
/// (CiA 402, say) or anything else that follows the node, and added with
/// `Node::addListener()`; every listener hears every event, in the order they were added.
/// Called synchronously from `Node::start()`, `onFrame()`, `process()` or an application call
/// into the node; must not block. Defaults do nothing.
class NodeEvents {
 public:
  /// The NMT state changed (also on the way through resets).
  virtual void onNmtStateChanged(NmtState previous, NmtState current) noexcept {
    (void)previous;
    (void)current;
  }
  /// Reset application (power-on or NMT reset node): the manufacturer and profile areas have just
  /// been set to their power-on values; re-initialise the device behind them.
  virtual void onResetApplication() noexcept {}
  /// Reset communication: the communication area (0x1000..0x1FFF) has just been set to its
  /// power-on values (the application may adjust them here, e.g. a serial number in 0x1018);
  /// the services start from them and the boot-up frame follows.
  virtual void onResetCommunication() noexcept {}
  /// An RPDO's entries are about to be written (at reception, or at the SYNC for a synchronous
  /// RPDO): every entry has passed its checks. onRpdoReceived() follows once all are written.
  virtual void onRpdoWriting(uint16_t communicationIndex) noexcept { (void)communicationIndex; }
  /// An RPDO's data has just been written into the dictionary, all of its entries. An RPDO that
  /// an entry's hook refuses is not written at all and does not reach this call
  /// (NodeStatistics::rpdosRefused counts it).
  virtual void onRpdoReceived(uint16_t communicationIndex) noexcept { (void)communicationIndex; }
  /// An RPDO with an event timer (deadline monitoring) did not arrive in time.
  virtual void onRpdoTimeout(uint16_t communicationIndex) noexcept { (void)communicationIndex; }
  /// A SYNC was received or produced (after synchronous PDOs were handled).
  virtual void onSync(uint8_t counter) noexcept { (void)counter; }
  /// An emergency message on a CAN-ID the EMCY consumer (0x1028) watches.
  virtual void onEmcyReceived(const EmcyMessage& emcy) noexcept { (void)emcy; }
  /// A global fail-safe command (GFC, CiA 304) was received: enter the safe state.
  virtual void onGlobalFailSafe() noexcept {}
  /// The safety service (CiA 304) entered the node's safe state: `failure` of SRDO `srdo`
  /// (1..64; 0 for a GFC). Once per stay in operational; Node::workingStateAllowed() is false.
  virtual void onSafeState(uint8_t srdo, SrdoFailure failure) noexcept {
    (void)srdo;
    (void)failure;
  }
  /// A monitored heartbeat (0x1016) stopped arriving / arrived again after a timeout.
  virtual void onHeartbeatTimeout(uint8_t nodeId) noexcept { (void)nodeId; }
  virtual void onHeartbeatResumed(uint8_t nodeId) noexcept { (void)nodeId; }
  /// The 0x1016 entry that had found `nodeId`'s heartbeat timed out got a new value: that error
  /// ends without the heartbeat, and monitoring starts over, as at reset communication (which
  /// ends every such error without this call: onResetCommunication).
  virtual void onHeartbeatWithdrawn(uint8_t nodeId) noexcept { (void)nodeId; }
  /// Life guarding: no node-guarding request within guard time x life time factor / requests
  /// arriving again.
  virtual void onLifeGuardingExpired() noexcept {}
  virtual void onLifeGuardingResumed() noexcept {}
  /// Stored parameters of `group` (or of the LSS configuration: group od::kGroupLss) could not
  /// be loaded at a reset: `result` is kCorrupt, kIncompatible or kMediumError. The defaults
  /// are in place. Called after onResetApplication / onResetCommunication.
  virtual void onStoredParametersInvalid(uint8_t group, StoreResult result) noexcept {
    (void)group;
    (void)result;
  }
  /// LSS activate bit timing, at the switch moment (after the first switch delay): the
  /// controller must run at `timing` (CiA 305 table) from now on. With a
  /// NodeSettings::bitRateControl the node has just asked it to (Node::bitTiming() shows whether
  /// it switched); without one, the application switches the controller here.
  virtual void onBitTimingActivation(LssBitTiming timing) noexcept { (void)timing; }
  /// The CAN controller went bus-off / recovered.
  virtual void onBusOff() noexcept {}
  virtual void onBusOffRecovered() noexcept {}

 protected:
  NodeEvents() = default;
  ~NodeEvents() = default;
  NodeEvents(const NodeEvents&) = default;
  NodeEvents& operator=(const NodeEvents&) = default;
  NodeEvents(NodeEvents&&) = default;
  NodeEvents& operator=(NodeEvents&&) = default;
};

/// The listeners of a node: a fixed number, no heap. Context: the one that runs the node.
class NodeListeners {
 public:
  static constexpr size_t kCapacity = 4;

  /// Adds `listener` after the others. False (and counted in refused()) when kCapacity
  /// listeners are there already, or when `listener` is one of them. O(kCapacity).
  [[nodiscard]] bool add(NodeEvents& listener) noexcept {
    for (size_t i = 0; i < count_; ++i) {
      if (listeners_[i] == &listener) {
        ++refused_;
        return false;
      }
    }
    if (count_ == kCapacity) {
      ++refused_;
      return false;
    }
    listeners_[count_++] = &listener;
    return true;
  }

  /// Calls `call(listener)` for every listener, in the order they were added. O(listeners).
  template <typename Call>
  void notify(Call call) const noexcept {
    for (size_t i = 0; i < count_; ++i) {
      call(*listeners_[i]);
    }
  }

  size_t size() const noexcept { return count_; }
  /// Listeners add() turned away, since construction.
  uint32_t refused() const noexcept { return refused_; }

 private:
  NodeEvents* listeners_[kCapacity] = {};
  size_t count_ = 0;
  uint32_t refused_ = 0;
};

}  // namespace costa
