// The M-series joint as a CiA 402 drive: a master that follows the standard (0x06, 0x07, 0x0F
// while reading 0x6041; 0x6060 written and 0x6061 read; fault reset by bit 7) drives it through
// every state and mode, and the manual's shortcuts work beside it (B1-B8): the joint's
// differences are additions, never replacements.
#include "mseries_fixture.hpp"

namespace costa::test {
namespace {

using JointAsCia402Drive = JointTest;

TEST_F(JointAsCia402Drive, TheStandardWayThroughTheStates) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 04 04 00 00   # pulse control (B7): no CiA 402 state yet
    rx 601 [8] 2B 40 60 00 06 00 00 00   # shutdown: 2
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 31 04 00 00   # ready to switch on
    rx 601 [8] 2B 40 60 00 07 00 00 00   # switch on: 3
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 33 04 00 00   # switched on
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # enable operation: 4
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 37 04 00 00   # operation enabled
    rx 601 [8] 2B 40 60 00 07 00 00 00   # disable operation: 5
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 33 04 00 00
    rx 601 [8] 2B 40 60 00 06 00 00 00   # shutdown: 6
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 31 04 00 00
    rx 601 [8] 2B 40 60 00 00 00 00 00   # disable voltage: 7
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 00 04 00 00   # switch on disabled, bit 6 unused (B6)
  )");
  EXPECT_EQ(joint().device().drive().state(), cia402::PowerState::kSwitchOnDisabled);
}

TEST_F(JointAsCia402Drive, ModesAreWrittenAndReadBack) {
  for (const char* mode : {"01", "03", "06", "07"}) {
    EXPECT_TRANSCRIPT(std::string("rx 601 [8] 2F 60 60 00 ") + mode + " 00 00 00\n" +
                      "tx 581 [8] 60 60 60 00 00 00 00 00\n" +
                      "rx 601 [8] 40 61 60 00 00 00 00 00\n" + "tx 581 [8] 4F 61 60 00 " + mode +
                      " 00 00 00\n");
  }
}

TEST_F(JointAsCia402Drive, ProfilePositionTheStandardWay) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 40 60 00 06 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # 3 + 4
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 01 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 23 7A 60 00 00 80 00 00   # one turn: 32768 counts
    tx 581 [8] 60 7A 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # new set-point
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00   # moving; no set-point acknowledge (bit 12, B6)
    tx 581 [8] 4B 41 60 00 37 00 00 00
    rx 601 [8] 40 40 60 00 00 00 00 00   # bit 4 cleared by the joint (B2)
    tx 581 [8] 4B 40 60 00 0F 00 00 00
    wait 200
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 37 04 00 00
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 00 80 00 00
  )");
}

TEST_F(JointAsCia402Drive, WithoutBit5ATargetWriteWaitsForBit4) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # B1
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 01 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 23 7A 60 00 00 80 00 00
    tx 581 [8] 60 7A 60 00 00 00 00 00
    wait 200
    rx 601 [8] 40 64 60 00 00 00 00 00   # no move
    tx 581 [8] 43 64 60 00 00 00 00 00
  )");
}

TEST_F(JointAsCia402Drive, HaltStopsAtOnceAndHolds) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 40 60 00 2F 00 00 00   # B1, B3
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 01 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 23 7A 60 00 A0 86 01 00   # 100000: moves at once
    tx 581 [8] 60 7A 60 00 00 00 00 00
    wait 50
    rx 601 [8] 2B 40 60 00 2F 01 00 00   # halt (B5)
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 6C 60 00 00 00 00 00   # 0 at once
    tx 581 [8] 43 6C 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00   # stopped: reached
    tx 581 [8] 4B 41 60 00 37 04 00 00
    rx 601 [8] 40 64 60 00 00 00 00 00   # 50 ms of ramp: 13926 counts
    tx 581 [8] 43 64 60 00 66 36 00 00
    wait 100
    rx 601 [8] 40 64 60 00 00 00 00 00   # held
    tx 581 [8] 43 64 60 00 66 36 00 00
    rx 601 [8] 2B 40 60 00 2F 00 00 00   # the halt ends: the move goes on
    tx 581 [8] 60 40 60 00 00 00 00 00
    wait 300
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 A0 86 01 00
  )");
}

TEST_F(JointAsCia402Drive, QuickStopEndsInSwitchOnDisabled) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 60 60 00 03 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 23 FF 60 00 E8 03 00 00
    tx 581 [8] 60 FF 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    wait 100
    rx 601 [8] 2B 40 60 00 0B 00 00 00   # quick stop: decelerates with 0x6083 (B14)
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00   # quick stop active
    tx 581 [8] 4B 41 60 00 17 00 00 00
    wait 100
    rx 601 [8] 40 41 60 00 00 00 00 00   # stopped: switch on disabled (no pulse control now)
    tx 581 [8] 4B 41 60 00 00 04 00 00
    rx 601 [8] 40 6C 60 00 00 00 00 00
    tx 581 [8] 43 6C 60 00 00 00 00 00
  )");
}

TEST_F(JointAsCia402Drive, AFaultAndItsReset) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    sim alarm 0x12                       # locked rotor (line 133): a fault
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 08 04 00 00   # fault (bit 3)
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 12 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # no command leaves fault
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 08 04 00 00
    rx 601 [8] 2B 40 60 00 80 00 00 00   # fault reset (bit 7 rising): 15
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 00 04 00 00   # switch on disabled
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00   # and enabled again (B1)
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 37 04 00 00
  )");
}

TEST_F(JointAsCia402Drive, OverVoltageStaysUntilTheSupplyIsBack) {
  EXPECT_TRANSCRIPT(R"(
    sim voltage 53                       # above 52 V (line 135)
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 08 04 00 00
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 15 00 00 00
    rx 601 [8] 40 01 10 00 00 00 00 00   # generic and voltage
    tx 581 [8] 4F 01 10 00 05 00 00 00
    rx 601 [8] 2B 40 60 00 80 00 00 00   # a fault reset while it lasts: still fault
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 08 04 00 00
    sim voltage 36
    rx 601 [8] 2B 40 60 00 00 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 80 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 04 04 00 00   # switch on disabled, still under pulse control
  )");
}

TEST_F(JointAsCia402Drive, OutputEnableClearsAStallToo) {
  EXPECT_TRANSCRIPT(R"(
    sim alarm 0x14                       # stall (line 134)
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 08 04 00 00
    rx 601 [8] 2B 01 26 00 01 00 00 00   # "EN enable 1" (B15): the alarm clears
    tx 581 [8] 60 01 26 00 00 00 00 00
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 80 00 00 00   # and a fault reset leaves fault
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 04 04 00 00
  )");
}

TEST_F(JointAsCia402Drive, OutputDisabledMeansNoMotion) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 01 26 00 00 00 00 00   # drive output forbidden (line 351)
    tx 581 [8] 60 01 26 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 03 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 23 FF 60 00 E8 03 00 00
    tx 581 [8] 60 FF 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    wait 100
    rx 601 [8] 40 6C 60 00 00 00 00 00
    tx 581 [8] 43 6C 60 00 00 00 00 00
    rx 601 [8] 2B 01 26 00 01 00 00 00   # enabled: it runs
    tx 581 [8] 60 01 26 00 00 00 00 00
    wait 100
    rx 601 [8] 40 6C 60 00 00 00 00 00
    tx 581 [8] 43 6C 60 00 E8 03 00 00
  )");
}

TEST_F(JointAsCia402Drive, HomingTheStandardWayShowsBit12) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 2F 98 60 00 12 00 00 00   # method 18: toward the positive limit on PU
    tx 581 [8] 60 98 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 06 00 00 00   # starts at once (B4)
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 37 00 00 00
    wait 10
    rx 601 [8] 40 64 60 00 00 00 00 00   # moving up at 100 r/min
    tx 581 [8] 43 64 60 00 22 02 00 00
    sim pu on
    rx 601 [8] 40 41 60 00 00 00 00 00   # attained (12), reached (10)
    tx 581 [8] 4B 41 60 00 37 14 00 00
    rx 601 [8] 2B 40 60 00 1F 00 00 00   # bit 4 starts it again (CiA 402): at once, PU is on
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 37 14 00 00
    rx 601 [8] 2F 60 60 00 01 00 00 00   # bit 12 belongs to homing only (B6)
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 37 04 00 00
  )");
}

TEST_F(JointAsCia402Drive, HomingMethodsSearchTheirWay) {
  // 19: the home switch on DIR, searched upward; 21: downward (CiA 402; the manual's figures
  // 19 and 21 read alike, D9). The speed: 0x6083's ones digit 5, 600 r/min (line 277, B10).
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 83 60 00 15 27 00 00   # 10005
    tx 581 [8] 60 83 60 00 00 00 00 00
    rx 601 [8] 2F 98 60 00 13 00 00 00   # 19
    tx 581 [8] 60 98 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 06 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    wait 10
    rx 601 [8] 40 64 60 00 00 00 00 00   # 10 ms at 600 r/min: +3276
    tx 581 [8] 43 64 60 00 CC 0C 00 00
    sim dir on
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 00 00 00 00
    sim dir off
    rx 601 [8] 2F 98 60 00 15 00 00 00   # 21
    tx 581 [8] 60 98 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 06 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    wait 10
    rx 601 [8] 40 64 60 00 00 00 00 00   # -3277
    tx 581 [8] 43 64 60 00 33 F3 FF FF
    rx 601 [8] 40 41 60 00 00 00 00 00   # under pulse control: the joint's word (B7)
    tx 581 [8] 4B 41 60 00 14 00 00 00
  )");
}

TEST_F(JointAsCia402Drive, InterpolationFollowsEachSync) {
  EXPECT_TRANSCRIPT(R"(
    rx 201 [7] 0F 00 07 00 00 00 00      # enable, mode 7
    tx 181 [6] 00 00 00 00 37 04
    rx 501 [4] 64 00 00 00               # 100 counts
    tx 481 [6] 00 00 00 00 37 04
    rx 080 [0]
    wait 2                               # within the 2 ms cycle (B8)
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 64 00 00 00
    rx 501 [4] C8 00 00 00               # 200
    tx 481 [6] 64 00 00 00 37 04
    wait 1
    rx 080 [0]
    wait 1
    rx 601 [8] 40 64 60 00 00 00 00 00   # half way after 1 ms
    tx 581 [8] 43 64 60 00 96 00 00 00
    wait 1
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 C8 00 00 00
  )");
}

}  // namespace
}  // namespace costa::test
