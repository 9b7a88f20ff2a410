// NMT slave: every transition of CiA 301 figure "NMT state diagram", addressed and broadcast,
// resets and what they restore, and ignored commands.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Nmt = ExampleNodeTest;

TEST_F(Nmt, BootsIntoPreOperational) {
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
  EXPECT_EQ(bus_.node().nodeId(), 1U);
}

TEST_F(Nmt, EveryTransitionBetweenTheOperatingStates) {
  struct Step {
    const char* command;
    NmtState expected;
  };
  const Step steps[] = {
      {"rx 000 [2] 01 01", NmtState::kOperational},     // pre-op -> op
      {"rx 000 [2] 80 01", NmtState::kPreOperational},  // op -> pre-op
      {"rx 000 [2] 02 01", NmtState::kStopped},         // pre-op -> stopped
      {"rx 000 [2] 01 01", NmtState::kOperational},     // stopped -> op
      {"rx 000 [2] 02 01", NmtState::kStopped},         // op -> stopped
      {"rx 000 [2] 80 01", NmtState::kPreOperational},  // stopped -> pre-op
      {"rx 000 [2] 80 01", NmtState::kPreOperational},  // pre-op -> pre-op: no change
      {"rx 000 [2] 01 00", NmtState::kOperational},     // broadcast
      {"rx 000 [2] 01 00", NmtState::kOperational},    {"rx 000 [2] 02 00", NmtState::kStopped},
      {"rx 000 [2] 02 00", NmtState::kStopped},
  };
  for (const Step& step : steps) {
    ASSERT_EQ(play(step.command), "") << step.command;
    EXPECT_EQ(bus_.node().state(), step.expected) << step.command;
  }
  EXPECT_EQ(play("silence"), "");
}

TEST_F(Nmt, IgnoresOtherNodesMalformedAndUnknownCommands) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 02        # node 2
    rx 000 [1] 01           # DLC 1
    rx 000 [3] 01 01 00     # DLC 3
    rx 000 [2] 03 01        # no such command
    rx 000 [2] RTR
    silence
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
}

TEST_F(Nmt, ResetCommunicationRestoresOnlyTheCommunicationArea) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 64 00 00 00   # heartbeat 100 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 601 [8] 23 00 20 00 20 4E 00 00   # setpoint 20000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 000 [2] 01 01
    rx 000 [2] 82 01                     # reset communication
    tx 701 [1] 00                        # boot-up
    wait 500
    silence                              # heartbeat back to its default 0
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
  EXPECT_EQ(value(0x1017, 0), 0U);
  EXPECT_EQ(value(0x2000, 0), 20000U);
}

TEST_F(Nmt, ResetNodeRestoresTheWholeDictionary) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 64 00 00 00
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 601 [8] 23 00 20 00 20 4E 00 00
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 000 [2] 02 00
    rx 000 [2] 81 00                     # reset node, broadcast
    tx 701 [1] 00
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
  EXPECT_EQ(value(0x1017, 0), 0U);
  EXPECT_EQ(value(0x2000, 0), 1000U);
}

TEST_F(Nmt, ResetsWorkFromEveryState) {
  for (const char* state : {"01", "02", "80"}) {
    EXPECT_EQ(play(std::string("rx 000 [2] ") + state + " 01\n" +
                   "rx 000 [2] 82 01\ntx 701 [1] 00\nrx 000 [2] " + state +
                   " 00\nrx 000 [2] 81 01\ntx 701 [1] 00"),
              "")
        << state;
  }
}

TEST_F(Nmt, ResetAbandonsAnSdoTransfer) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    wait 3000
    silence
  )");
}

class RecordingEvents : public NodeEvents {
 public:
  void onNmtStateChanged(NmtState previous, NmtState current) noexcept override {
    (void)previous;
    last = current;
    ++changes;
  }
  NmtState last = NmtState::kInitialising;
  int changes = 0;
};

TEST_F(Nmt, ApplicationHearsStateChangesAndMayStartItself) {
  RecordingEvents events;
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_EQ(play("rx 000 [2] 01 01"), "");
  EXPECT_EQ(events.last, NmtState::kOperational);
  EXPECT_EQ(events.changes, 1);
  bus_.node().enterState(NmtState::kStopped);
  EXPECT_EQ(events.last, NmtState::kStopped);
  bus_.node().enterState(NmtState::kInitialising);  // not a local transition
  EXPECT_EQ(bus_.node().state(), NmtState::kStopped);
}

}  // namespace
}  // namespace costa::test
