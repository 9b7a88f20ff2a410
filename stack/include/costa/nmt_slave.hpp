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
  /// Inline: expanded into its one caller (NmtStateMachine::onCommand), the decision is not
  /// packed into a register and unpacked again.
  static Decision decide(const CanFrame& frame, uint8_t nodeId, NmtState current) noexcept;

 private:
  /// What an NMT command asks for: a state to enter, or a reset.
  struct CommandRow {
    NmtCommand command;
    Action action;
    NmtState state;
  };
  static constexpr CommandRow kCommands[] = {
      {NmtCommand::kStart, Action::kEnterState, NmtState::kOperational},
      {NmtCommand::kStop, Action::kEnterState, NmtState::kStopped},
      {NmtCommand::kEnterPreOperational, Action::kEnterState, NmtState::kPreOperational},
      {NmtCommand::kResetNode, Action::kResetNode, NmtState::kInitialising},
      {NmtCommand::kResetCommunication, Action::kResetCommunication, NmtState::kInitialising},
  };
};

inline NmtSlave::Decision NmtSlave::decide(const CanFrame& frame, uint8_t nodeId,
                                           NmtState current) noexcept {
  if (frame.dlc != 2U || frame.rtr || frame.extended) {
    return {};
  }
  const uint8_t target = frame.data[1];
  if (target != 0U && target != nodeId) {
    return {};
  }
  for (const CommandRow& row : kCommands) {
    if (frame.data[0] != static_cast<uint8_t>(row.command)) {
      continue;
    }
    if (row.action == Action::kEnterState &&
        (row.state == current || current == NmtState::kInitialising)) {
      return {};  // already there, or a reset still running: nothing to change
    }
    return {row.action, row.state};
  }
  return {};  // an unknown command
}

}  // namespace costa
