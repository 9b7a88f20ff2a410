// The node's side of its LSS slave (LssSlaveHost): which bit timings the controller can take,
// the switch at the LSS switch moment, store configuration, and the reset communication that
// gives a device without a node-id the one LSS configured.
//
// Context: the one that runs the node, from within LssSlave::onFrame()/process(). No allocation.
#pragma once

#include <stdint.h>

#include "costa/bit_timing_switch.hpp"
#include "costa/compiled_out.hpp"
#include "costa/features.hpp"
#include "costa/lss_slave.hpp"
#include "costa/node_events.hpp"
#include "costa/node_settings.hpp"
#include "costa/stored_parameters.hpp"

namespace costa {

class NmtStateMachine;

class LssBridge final : public LssSlaveHost {
 public:
  /// Over the node's state machine `nmt`, through which it reaches the services it acts on
  /// (settings, bit timing, stored parameters, listeners: NmtStateMachine::Services).
  explicit LssBridge(NmtStateMachine& nmt) noexcept : nmt_(nmt) {}

  /// Table selector 0 and an index of NodeSettings::lssBitRates.
  bool bitTimingSupported(LssBitTiming timing) noexcept override;
  /// Re-times the controller (the slave holds transmission until its second delay has passed),
  /// makes `timing` the pending one, and tells the listeners.
  void activateBitTiming(LssBitTiming timing) noexcept override;
  LssStoreResult storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept override;
  void requestResetCommunication() noexcept override;

 private:
  NmtStateMachine& nmt_;
};

/// The node's bridge: only the LSS slave calls it, so without LSS (features::kLss) the node
/// holds none and none of its code is linked.
using LssBridgeChoice = ServiceIf<features::kLss, LssBridge, CompiledOut>;

}  // namespace costa
