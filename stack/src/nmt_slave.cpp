#include "costa/nmt_slave.hpp"

namespace costa {

namespace {

/// What each NMT command asks for: a state to enter, or a reset.
struct CommandRow {
  NmtCommand command;
  NmtSlave::Action action;
  NmtState state;
};

constexpr CommandRow kCommands[] = {
    {NmtCommand::kStart, NmtSlave::Action::kEnterState, NmtState::kOperational},
    {NmtCommand::kStop, NmtSlave::Action::kEnterState, NmtState::kStopped},
    {NmtCommand::kEnterPreOperational, NmtSlave::Action::kEnterState, NmtState::kPreOperational},
    {NmtCommand::kResetNode, NmtSlave::Action::kResetNode, NmtState::kInitialising},
    {NmtCommand::kResetCommunication, NmtSlave::Action::kResetCommunication,
     NmtState::kInitialising},
};

}  // namespace

NmtSlave::Decision NmtSlave::decide(const CanFrame& frame, uint8_t nodeId,
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
