// NMT slave (CiA 301 7.3.2): decodes NMT commands addressed to this node into state
// transitions and resets.
#pragma once

#include <stdint.h>

#include "costa/nmt_state.hpp"
#include "costa/port/can_frame.hpp"

namespace costa {

class NmtSlave {
 public:
  enum class Action : uint8_t { kNone, kEnterState, kResetNode, kResetCommunication };

  struct Decision {
    Action action = Action::kNone;
    NmtState state = NmtState::kInitialising;  ///< Target state for kEnterState.
  };

  /// Decides what a frame received on COB-ID 0x000 asks of node `nodeId` in state `current`.
  /// Ignored (kNone): DLC other than 2, RTR, another node's id, unknown command, and a
  /// transition to the state the node is already in. Node-id 0 addresses every node. O(1).
  static Decision decide(const CanFrame& frame, uint8_t nodeId, NmtState current) noexcept;
};

}  // namespace costa
