// The CiA 402 power state machine (stack/cia402/power_state_machine.hpp) against CiA 402-2 alone:
// the command decoding of the control word, every transition 0..16 with its number, the state
// coding of the status word, and what does not change a state.
#include <gtest/gtest.h>

#include "costa/cia402/power_state_machine.hpp"

namespace costa::cia402 {
namespace {

using S = PowerState;

PowerTransition step(S state, uint16_t controlword, PowerInputs inputs = {},
                     PowerOptions options = {}) {
  return nextPowerState(state, controlword, inputs, options);
}

void expectTransition(S from, uint16_t controlword, S to, uint8_t number, PowerInputs inputs = {},
                      PowerOptions options = {}) {
  const PowerTransition t = step(from, controlword, inputs, options);
  EXPECT_EQ(t.state, to) << "from " << static_cast<int>(from) << " with 0x" << std::hex
                         << controlword;
  EXPECT_EQ(t.number, number) << "from " << static_cast<int>(from) << " with 0x" << std::hex
                              << controlword;
}

void expectStays(S state, uint16_t controlword, PowerInputs inputs = {},
                 PowerOptions options = {}) {
  expectTransition(state, controlword, state, kNoTransition, inputs, options);
}

TEST(Cia402Commands, DecodeBitsZeroToThree) {
  EXPECT_EQ(decodeCommand(0x0000), Command::kDisableVoltage);
  EXPECT_EQ(decodeCommand(0x000D), Command::kDisableVoltage);  // bit 1 clear
  EXPECT_EQ(decodeCommand(0x0002), Command::kQuickStop);
  EXPECT_EQ(decodeCommand(0x000B), Command::kQuickStop);
  EXPECT_EQ(decodeCommand(0x0006), Command::kShutdown);
  EXPECT_EQ(decodeCommand(0x000E), Command::kShutdown);  // bit 3 does not matter
  EXPECT_EQ(decodeCommand(0x0007), Command::kSwitchOn);
  EXPECT_EQ(decodeCommand(0x000F), Command::kEnableOperation);
  EXPECT_EQ(decodeCommand(0x01FF), Command::kEnableOperation);  // bits 4..8: modes, halt
}

TEST(Cia402Transitions, ZeroAndOneAreAutomatic) {
  expectTransition(S::kNotReadyToSwitchOn, 0x0000, S::kSwitchOnDisabled, 1);
  expectTransition(S::kNotReadyToSwitchOn, 0x000F, S::kSwitchOnDisabled, 1);
}

TEST(Cia402Transitions, TheWayUpTwoThreeFour) {
  expectTransition(S::kSwitchOnDisabled, 0x0006, S::kReadyToSwitchOn, 2);
  expectTransition(S::kReadyToSwitchOn, 0x0007, S::kSwitchedOn, 3);
  expectTransition(S::kSwitchedOn, 0x000F, S::kOperationEnabled, 4);
  // Switch on + enable operation from ready to switch on: 3 + 4.
  expectTransition(S::kReadyToSwitchOn, 0x000F, S::kOperationEnabled, 4);
}

TEST(Cia402Transitions, TheWayDown) {
  expectTransition(S::kOperationEnabled, 0x0007, S::kSwitchedOn, 5);
  expectTransition(S::kSwitchedOn, 0x0006, S::kReadyToSwitchOn, 6);
  expectTransition(S::kReadyToSwitchOn, 0x0000, S::kSwitchOnDisabled, 7);
  expectTransition(S::kReadyToSwitchOn, 0x0002, S::kSwitchOnDisabled, 7);
  expectTransition(S::kOperationEnabled, 0x0006, S::kReadyToSwitchOn, 8);
  expectTransition(S::kOperationEnabled, 0x0000, S::kSwitchOnDisabled, 9);
  expectTransition(S::kSwitchedOn, 0x0000, S::kSwitchOnDisabled, 10);
  expectTransition(S::kSwitchedOn, 0x0002, S::kSwitchOnDisabled, 10);
}

TEST(Cia402Transitions, QuickStopElevenTwelveSixteen) {
  expectTransition(S::kOperationEnabled, 0x000B, S::kQuickStopActive, 11);
  expectTransition(S::kOperationEnabled, 0x0002, S::kQuickStopActive, 11);
  // Option 2 (the default): switch on disabled once stopped; disable voltage at once.
  expectStays(S::kQuickStopActive, 0x000B);
  expectStays(S::kQuickStopActive, 0x000F);  // no 16 with option 2
  expectTransition(S::kQuickStopActive, 0x000B, S::kSwitchOnDisabled, 12, {false, false, true});
  expectTransition(S::kQuickStopActive, 0x0000, S::kSwitchOnDisabled, 12);
  PowerOptions stay;
  stay.quickStopOption = 6;
  expectStays(S::kQuickStopActive, 0x000B, {false, false, true}, stay);
  expectTransition(S::kQuickStopActive, 0x000F, S::kOperationEnabled, 16, {}, stay);
  expectTransition(S::kQuickStopActive, 0x0000, S::kSwitchOnDisabled, 12, {}, stay);
  PowerOptions disable;
  disable.quickStopOption = 0;
  expectTransition(S::kQuickStopActive, 0x000B, S::kSwitchOnDisabled, 12, {}, disable);
}

TEST(Cia402Transitions, FaultThirteenFourteenFifteen) {
  const PowerInputs fault{false, true, false};
  for (S state : {S::kSwitchOnDisabled, S::kReadyToSwitchOn, S::kSwitchedOn, S::kOperationEnabled,
                  S::kQuickStopActive}) {
    expectTransition(state, 0x000F, S::kFaultReactionActive, 13, fault);
  }
  expectStays(S::kFaultReactionActive, 0x000F, fault);
  expectTransition(S::kFaultReactionActive, 0x000F, S::kFault, 14, {false, true, true});
  // Fault reset: the rising edge of bit 7, and only once the fault is gone.
  expectStays(S::kFault, 0x0080, {true, true, true});
  expectStays(S::kFault, 0x0080, {false, false, true});
  expectTransition(S::kFault, 0x0080, S::kSwitchOnDisabled, 15, {true, false, true});
  expectStays(S::kFault, 0x000F, {false, false, true});  // no command leaves fault
}

TEST(Cia402Transitions, WhatDoesNotChangeAState) {
  expectStays(S::kSwitchOnDisabled, 0x0000);
  expectStays(S::kSwitchOnDisabled, 0x0007);  // switch on needs ready to switch on
  expectStays(S::kSwitchOnDisabled, 0x000F);  // CiA 402: only shutdown leaves it
  expectStays(S::kReadyToSwitchOn, 0x0006);
  expectStays(S::kSwitchedOn, 0x0007);
  expectStays(S::kOperationEnabled, 0x000F);
  expectStays(S::kOperationEnabled, 0x011F);  // halt and mode bits are not commands
  expectStays(S::kReadyToSwitchOn, 0x0086, {true, false, true});  // a fault reset outside fault
}

TEST(Cia402Transitions, EnableFromSwitchOnDisabledIsAnOption) {
  PowerOptions options;
  options.enableFromSwitchOnDisabled = true;
  expectTransition(S::kSwitchOnDisabled, 0x000F, S::kOperationEnabled, 4, {}, options);
  expectTransition(S::kSwitchOnDisabled, 0x002F, S::kOperationEnabled, 4, {}, options);
  expectStays(S::kSwitchOnDisabled, 0x0007, {}, options);
  // The standard way works as before.
  expectTransition(S::kSwitchOnDisabled, 0x0006, S::kReadyToSwitchOn, 2, {}, options);
}

TEST(Cia402StatusWord, StateCoding) {
  EXPECT_EQ(stateStatusBits(S::kNotReadyToSwitchOn), 0x0000);
  EXPECT_EQ(stateStatusBits(S::kSwitchOnDisabled), 0x0040);
  EXPECT_EQ(stateStatusBits(S::kReadyToSwitchOn), 0x0031);
  EXPECT_EQ(stateStatusBits(S::kSwitchedOn), 0x0033);
  EXPECT_EQ(stateStatusBits(S::kOperationEnabled), 0x0037);
  EXPECT_EQ(stateStatusBits(S::kQuickStopActive), 0x0017);
  EXPECT_EQ(stateStatusBits(S::kFaultReactionActive), 0x001F);
  EXPECT_EQ(stateStatusBits(S::kFault), 0x0008);
}

TEST(Cia402StatusWord, EveryStateReadsBackFromItsBits) {
  for (S state : {S::kNotReadyToSwitchOn, S::kSwitchOnDisabled, S::kReadyToSwitchOn, S::kSwitchedOn,
                  S::kOperationEnabled, S::kQuickStopActive, S::kFaultReactionActive, S::kFault}) {
    S shown = S::kFault;
    ASSERT_TRUE(stateOfStatusword(static_cast<uint16_t>(stateStatusBits(state) | 0x1400U), &shown));
    EXPECT_EQ(shown, state);
  }
  S shown = S::kFault;
  EXPECT_FALSE(stateOfStatusword(0x0404, &shown));  // bit 2 alone is no state
  EXPECT_FALSE(stateOfStatusword(0x0014, &shown));
}

}  // namespace
}  // namespace costa::cia402
