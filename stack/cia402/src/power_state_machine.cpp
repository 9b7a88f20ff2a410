#include "costa/cia402/power_state_machine.hpp"

namespace costa::cia402 {
namespace {

constexpr PowerTransition to(PowerState state, uint8_t number) noexcept {
  return PowerTransition{state, number};
}

/// Quick stop option codes 5..8 stay in quick stop active.
constexpr bool staysInQuickStop(int16_t option) noexcept {
  return option >= 5 && option <= 8;
}

PowerTransition fromQuickStop(Command command, const PowerInputs& inputs,
                              const PowerOptions& options) noexcept {
  if (command == Command::kDisableVoltage) {
    return to(PowerState::kSwitchOnDisabled, 12);
  }
  if (staysInQuickStop(options.quickStopOption)) {
    return command == Command::kEnableOperation ? to(PowerState::kOperationEnabled, 16)
                                                : to(PowerState::kQuickStopActive, kNoTransition);
  }
  if (options.quickStopOption == 0 || inputs.stopped) {
    return to(PowerState::kSwitchOnDisabled, 12);
  }
  return to(PowerState::kQuickStopActive, kNoTransition);
}

}  // namespace

PowerTransition nextPowerState(PowerState state, uint16_t controlword, const PowerInputs& inputs,
                               const PowerOptions& options) noexcept {
  if (state == PowerState::kNotReadyToSwitchOn) {
    return to(PowerState::kSwitchOnDisabled, 1);
  }
  if (inputs.fault && state != PowerState::kFaultReactionActive && state != PowerState::kFault) {
    return to(PowerState::kFaultReactionActive, 13);
  }
  const Command command = decodeCommand(controlword);
  const PowerTransition none = to(state, kNoTransition);
  switch (state) {
    case PowerState::kSwitchOnDisabled:
      if (command == Command::kShutdown) {
        return to(PowerState::kReadyToSwitchOn, 2);
      }
      if (command == Command::kEnableOperation && options.enableFromSwitchOnDisabled) {
        return to(PowerState::kOperationEnabled, 4);  // 2, 3 and 4 at once
      }
      return none;
    case PowerState::kReadyToSwitchOn:
      switch (command) {
        case Command::kSwitchOn: return to(PowerState::kSwitchedOn, 3);
        case Command::kEnableOperation: return to(PowerState::kOperationEnabled, 4);  // 3 + 4
        case Command::kDisableVoltage:
        case Command::kQuickStop: return to(PowerState::kSwitchOnDisabled, 7);
        case Command::kShutdown: return none;
      }
      return none;
    case PowerState::kSwitchedOn:
      switch (command) {
        case Command::kEnableOperation: return to(PowerState::kOperationEnabled, 4);
        case Command::kShutdown: return to(PowerState::kReadyToSwitchOn, 6);
        case Command::kDisableVoltage:
        case Command::kQuickStop: return to(PowerState::kSwitchOnDisabled, 10);
        case Command::kSwitchOn: return none;
      }
      return none;
    case PowerState::kOperationEnabled:
      switch (command) {
        case Command::kSwitchOn: return to(PowerState::kSwitchedOn, 5);
        case Command::kShutdown: return to(PowerState::kReadyToSwitchOn, 8);
        case Command::kDisableVoltage: return to(PowerState::kSwitchOnDisabled, 9);
        case Command::kQuickStop: return to(PowerState::kQuickStopActive, 11);
        case Command::kEnableOperation: return none;
      }
      return none;
    case PowerState::kQuickStopActive: return fromQuickStop(command, inputs, options);
    case PowerState::kFaultReactionActive:
      return inputs.stopped ? to(PowerState::kFault, 14) : none;
    case PowerState::kFault:
      return inputs.faultReset && !inputs.fault ? to(PowerState::kSwitchOnDisabled, 15) : none;
    case PowerState::kNotReadyToSwitchOn: break;
  }
  return none;
}

uint16_t stateStatusBits(PowerState state) noexcept {
  using namespace status;
  switch (state) {
    case PowerState::kNotReadyToSwitchOn: return 0;
    case PowerState::kSwitchOnDisabled: return kSwitchOnDisabled;
    case PowerState::kReadyToSwitchOn: return kReadyToSwitchOn | kQuickStop | kVoltageEnabled;
    case PowerState::kSwitchedOn:
      return kReadyToSwitchOn | kSwitchedOn | kQuickStop | kVoltageEnabled;
    case PowerState::kOperationEnabled:
      return kReadyToSwitchOn | kSwitchedOn | kOperationEnabled | kQuickStop | kVoltageEnabled;
    case PowerState::kQuickStopActive:
      return kReadyToSwitchOn | kSwitchedOn | kOperationEnabled | kVoltageEnabled;
    case PowerState::kFaultReactionActive:
      return kReadyToSwitchOn | kSwitchedOn | kOperationEnabled | kFault | kVoltageEnabled;
    case PowerState::kFault: return kFault;
  }
  return 0;
}

bool stateOfStatusword(uint16_t statusword, PowerState* state) noexcept {
  const auto low = static_cast<uint16_t>(statusword & 0x4FU);
  const auto withQuickStop = static_cast<uint16_t>(statusword & 0x6FU);
  if (low == 0x00U) {
    *state = PowerState::kNotReadyToSwitchOn;
  } else if (low == 0x40U) {
    *state = PowerState::kSwitchOnDisabled;
  } else if (withQuickStop == 0x21U) {
    *state = PowerState::kReadyToSwitchOn;
  } else if (withQuickStop == 0x23U) {
    *state = PowerState::kSwitchedOn;
  } else if (withQuickStop == 0x27U) {
    *state = PowerState::kOperationEnabled;
  } else if (withQuickStop == 0x07U) {
    *state = PowerState::kQuickStopActive;
  } else if (low == 0x0FU) {
    *state = PowerState::kFaultReactionActive;
  } else if (low == 0x08U) {
    *state = PowerState::kFault;
  } else {
    return false;
  }
  return true;
}

}  // namespace costa::cia402
