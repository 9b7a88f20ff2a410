// The M-series joint's wire (docs/errata-m-series.md W1-W12), through exact frames: operational
// by itself, a heartbeat of 1000 ms carrying 04 while an alarm is active, no node guarding, no
// RTR, no EMCY, fixed PDOs whose TPDO n answers RPDO n and nothing else, the node-id of 0x2615
// after a save and a power cycle with the COB-IDs following it, 1 Mbit/s.
#include "mseries_fixture.hpp"

namespace costa::test {
namespace {

using JointWire = JointTest;

TEST_F(JointWire, OperationalByItselfAfterEveryBootUp) {
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
  EXPECT_TRANSCRIPT(R"(
    rx 201 [7] 00 00 00 00 00 00 00      # RPDO1 taken: operational without an NMT start
    tx 181 [6] 00 00 00 00 04 04
    rx 000 [2] 81 01                     # reset node
    tx 701 [1] 00
    rx 201 [7] 00 00 00 00 00 00 00      # operational again
    tx 181 [6] 00 00 00 00 04 04
    rx 000 [2] 80 01                     # a master may still send it to pre-operational
    rx 201 [7] 00 00 00 00 00 00 00
    silence
    wait 1000
    tx 701 [1] 7F
  )");
}

TEST_F(JointWire, HeartbeatCarries04WhileAnAlarmIsActive) {
  EXPECT_TRANSCRIPT(R"(
    wait 1000
    tx 701 [1] 05
    sim alarm 0x10                       # battery: the motor goes on (line 132)
    wait 1000
    tx 701 [1] 04                        # the alarm (line 752)
    rx 401 [7] 0F 00 03 64 00 00 00      # still operational: RPDO3 is taken and answered
    tx 381 [6] 00 00 00 00 37 00
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 10 00 00 00
    rx 601 [8] 40 01 10 00 00 00 00 00   # generic and manufacturer-specific
    tx 581 [8] 4F 01 10 00 81 00 00 00
    rx 601 [8] 2B 0A 26 00 66 EA 00 00   # the zero setting restores it (line 257): 60006
    tx 581 [8] 60 0A 26 00 00 00 00 00
    rx 601 [8] 2B 0A 26 00 70 EA 00 00   # 60016
    tx 581 [8] 60 0A 26 00 00 00 00 00
    wait 1000
    tx 701 [1] 05
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
}

// Reset node ends the communication alarm as reset communication does (the transcript
// heartbeat-consumer-starts-over): the consumer starts over, the drive no longer holds.
TEST_F(JointWire, ResetNodeEndsTheCommunicationAlarm) {
  EXPECT_TRANSCRIPT(R"(
    rx 77F [1] 05                        # the master's first heartbeat: monitoring starts
    wait 1000
    tx 701 [1] 05
    wait 1000
    tx 701 [1] 05                        # 2000 ms: the master has been silent that long
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 20 00 00 00   # 0x20: communication drop
    rx 000 [2] 81 01                     # reset node
    tx 701 [1] 00
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 00 00 00 00
    wait 1000
    tx 701 [1] 05                        # 05: no alarm
  )");
}

TEST_F(JointWire, NoNodeGuardingNoRemoteRequests) {
  EXPECT_TRANSCRIPT(R"(
    rx 701 [0] RTR                       # node guarding
    rx 181 [0] RTR                       # TPDO1 (COB-ID bit 30)
    rx 281 [0] RTR
    rx 381 [0] RTR
    rx 481 [0] RTR
    silence
  )");
}

TEST_F(JointWire, NoEmcyForAnRpdoOfTheWrongLength) {
  EXPECT_TRANSCRIPT(R"(
    rx 201 [4] 0F 00 01 00               # RPDO1 too short: not taken, not answered, no EMCY
    silence
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 11 00 00 00   # the register shows it
    wait 1000
    tx 701 [1] 04                        # and so does the heartbeat
    rx 201 [7] 00 00 00 00 00 00 00      # the right length clears it
    tx 181 [6] 00 00 00 00 04 04
    wait 1000
    tx 701 [1] 05
  )");
}

TEST_F(JointWire, TpdoNAnswersRpdoNAndNothingElse) {
  EXPECT_TRANSCRIPT(R"(
    rx 301 [8] 00 00 00 00 E8 03 00 00   # RPDO2 -> TPDO2
    tx 281 [6] 00 00 00 00 04 04
    rx 401 [7] 00 00 03 00 00 00 00      # RPDO3 -> TPDO3 (velocity, status)
    tx 381 [6] 00 00 00 00 04 04
    rx 501 [4] 00 00 00 00               # RPDO4 -> TPDO4, at reception
    tx 481 [6] 00 00 00 00 04 04
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # the status word changes: no TPDO
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 080 [0]                           # a SYNC: no TPDO
    wait 3000
    tx 701 [1] 05
    tx 701 [1] 05
    tx 701 [1] 05
    rx 201 [7] 0F 00 01 00 00 00 00      # RPDO1 -> TPDO1
    tx 181 [6] 00 00 00 00 37 04
  )");
}

TEST_F(JointWire, TheInhibitTimeSpacesAnswers) {
  EXPECT_TRANSCRIPT(R"(
    rx 301 [8] 00 00 00 00 E8 03 00 00
    tx 281 [6] 00 00 00 00 04 04
    rx 301 [8] 00 00 00 00 E8 03 00 00   # 0.3 ms later at the earliest (D7)
    silence
  )");
  bus_.advance(299);
  EXPECT_TRANSCRIPT("silence");
  bus_.advance(1);
  EXPECT_TRANSCRIPT("tx 281 [6] 00 00 00 00 04 04");
}

TEST_F(JointWire, OneMegabitPerSecond) {
  EXPECT_EQ(mseries::MSeriesTarget::settings().bitTiming.tableIndex, 0U);  // CiA 305: 1000 kbit/s
  EXPECT_EQ(bus_.node().bitTiming().tableIndex, 0U);
}

using JointNodeId = JointPowerCycle;

TEST_F(JointNodeId, Location0x2615TakesEffectAfterASaveAndAPowerCycle) {
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 15 26 00 05 00 00 00   # node-id 5
    tx 581 [8] 60 15 26 00 00 00 00 00
    rx 000 [2] 81 01                     # reset node without a save: still 1
    tx 701 [1] 00
    rx 601 [8] 40 15 26 00 00 00 00 00
    tx 581 [8] 4B 15 26 00 01 00 00 00
    rx 601 [8] 2B 15 26 00 05 00 00 00
    tx 581 [8] 60 15 26 00 00 00 00 00
    rx 601 [8] 2B 14 26 00 01 00 00 00   # save (line 271)
    tx 581 [8] 60 14 26 00 00 00 00 00
    rx 601 [8] 40 14 26 00 00 00 00 00   # then reads 2 (line 273)
    tx 581 [8] 4B 14 26 00 02 00 00 00
    rx 601 [8] 40 00 14 01 00 00 00 00   # still 1 until the power cycle (line 374)
    tx 581 [8] 43 00 14 01 01 02 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 705 [1] 00                        # node-id 5
    rx 605 [8] 40 00 14 01 00 00 00 00   # the COB-IDs follow it (lines 533, 547)
    tx 585 [8] 43 00 14 01 05 02 00 00
    rx 605 [8] 40 03 18 01 00 00 00 00
    tx 585 [8] 43 03 18 01 85 04 00 40
    rx 605 [8] 40 14 26 00 00 00 00 00   # the flag starts at 0 again
    tx 585 [8] 4B 14 26 00 00 00 00 00
    rx 205 [7] 0F 00 01 00 00 00 00      # RPDO1 on 0x205, TPDO1 on 0x185
    tx 185 [6] 00 00 00 00 37 04
    rx 201 [7] 0F 00 01 00 00 00 00      # 0x201 is no longer it
    silence
  )"),
            "");
}

TEST_F(JointNodeId, SavedParametersComeBackAfterAPowerCycle) {
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 17 10 00 F4 01 00 00   # heartbeat 500 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 601 [8] 23 83 60 00 15 27 00 00   # acceleration 10005
    tx 581 [8] 60 83 60 00 00 00 00 00
    rx 601 [8] 23 7A 60 00 10 27 00 00   # a target: a process value, not saved
    tx 581 [8] 60 7A 60 00 00 00 00 00
    rx 601 [8] 2B 14 26 00 01 00 00 00
    tx 581 [8] 60 14 26 00 00 00 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    wait 500
    tx 701 [1] 05                        # 500 ms
    rx 601 [8] 40 83 60 00 00 00 00 00
    tx 581 [8] 43 83 60 00 15 27 00 00
    rx 601 [8] 40 7A 60 00 00 00 00 00
    tx 581 [8] 43 7A 60 00 00 00 00 00
  )"),
            "");
}

TEST_F(JointNodeId, ASaveTheMemoryRefusesAborts08000020) {
  powerOn();
  memory_.cutPowerAfter(0);
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 14 26 00 01 00 00 00
    tx 581 [8] 80 14 26 00 20 00 00 08
    rx 601 [8] 40 14 26 00 00 00 00 00   # not saved: not 2
    tx 581 [8] 4B 14 26 00 00 00 00 00
  )"),
            "");
  memory_.restorePower();
}

TEST(JointCommandLine, AGivenNodeIdWinsOverTheStoredOne) {
  InProcessBus bus("m-series", 9);  // the public name, as costa-slave --node-id 9 m-series
  EXPECT_EQ(playText(R"(
    tx 709 [1] 00
    rx 609 [8] 40 15 26 00 00 00 00 00
    tx 589 [8] 4B 15 26 00 09 00 00 00
  )",
                     bus),
            "");
}

}  // namespace
}  // namespace costa::test
