#include "costa/nmt_slave.hpp"

namespace costa {

NmtSlave::Decision NmtSlave::decide(const CanFrame& frame, uint8_t nodeId,
                                    NmtState current) noexcept {
  Decision decision;
  if (frame.dlc != 2U || frame.rtr || frame.extended) {
    return decision;
  }
  const uint8_t target = frame.data[1];
  if (target != 0U && target != nodeId) {
    return decision;
  }
  NmtState next = current;
  switch (static_cast<NmtCommand>(frame.data[0])) {
    case NmtCommand::kStart: next = NmtState::kOperational; break;
    case NmtCommand::kStop: next = NmtState::kStopped; break;
    case NmtCommand::kEnterPreOperational: next = NmtState::kPreOperational; break;
    case NmtCommand::kResetNode: decision.action = Action::kResetNode; return decision;
    case NmtCommand::kResetCommunication:
      decision.action = Action::kResetCommunication;
      return decision;
    default: return decision;
  }
  if (next != current && current != NmtState::kInitialising) {
    decision.action = Action::kEnterState;
    decision.state = next;
  }
  return decision;
}

const char* describe(NmtState state) noexcept {
  switch (state) {
    case NmtState::kInitialising: return "initialising";
    case NmtState::kStopped: return "stopped";
    case NmtState::kOperational: return "operational";
    case NmtState::kPreOperational: return "pre-operational";
  }
  return "unknown";
}

}  // namespace costa
