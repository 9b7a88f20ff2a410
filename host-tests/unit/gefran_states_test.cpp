// The NMT state of a GRA chosen by its own objects: the error behaviour 0x4000 = 0 (manual lines
// 263-267, errata E29) and a saved automatic start 0x5000 = 0 (line 552, E16, E17), with every
// frame on the bus checked (no `ignore`).
#include <gtest/gtest.h>

#include "device_fixture.hpp"

namespace costa::test {
namespace {

class GraStates : public DeviceTest {
 protected:
  GraStates() : DeviceTest("gra", -1) {}  // the factory node-id 0x7F
};

TEST_F(GraStates, ErrorBehaviourZeroEntersPreOperationalOnAFault) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00     # operational by itself
    rx 67F [8] 2F 00 40 00 00 00 00 00     # 0x4000 = 0: pre-operational on a fault
    tx 5FF [8] 60 00 40 00 00 00 00 00
    wait 100
    tx 1FF [8] 00 00 00 00 FF FF FF 00     # still operational
    sim fault chip1 on
    tx 0FF [8] 00 10 00 01 00 FF FF FF     # EMCY: generic error, 0x4001 = 0x01
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
  EXPECT_TRANSCRIPT(R"(
    wait 1000
    silence                                # no TPDO in pre-operational
    rx 67F [8] 2B 17 10 00 64 00 00 00     # heartbeat 100 ms: the state on the wire
    tx 5FF [8] 60 17 10 00 00 00 00 00
    wait 100
    tx 77F [1] 7F                          # pre-operational
    rx 67F [8] 2B 17 10 00 00 00 00 00
    tx 5FF [8] 60 17 10 00 00 00 00 00
    rx 67F [8] 40 01 40 00 00 00 00 00
    tx 5FF [8] 4F 01 40 00 01 00 00 00     # 0x4001 = 0x01
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
}

TEST_F(GraStates, ErrorBehaviourOneKeepsTheNodeOperational) {
  // The factory 0x4000 = 1, against which the test above differs.
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    sim fault chip1 on
    tx 0FF [8] 00 10 00 01 00 FF FF FF
    wait 100
    tx 1FF [8] 00 00 00 00 FF FF FF 01
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
}

TEST_F(GraStates, ASavedAutomaticStartOfZeroKeepsTheNodePreOperationalAfterAReset) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00     # factory 0x5000 = 1: operational by itself
    rx 67F [8] 2F 00 50 00 00 00 00 00     # 0x5000 = 0
    tx 5FF [8] 60 00 50 00 00 00 00 00
    rx 67F [8] 23 10 10 01 73 61 76 65     # "save"
    tx 5FF [8] 60 10 10 01 00 00 00 00
    rx 000 [2] 81 7F                       # reset node
    tx 77F [1] 00                          # boot-up, and nothing after it
    wait 1000
    silence
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 82 7F                       # reset communication: the same
    tx 77F [1] 00
    wait 1000
    silence
    rx 000 [2] 01 7F                       # NMT start: the TPDO at once, then cyclic
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    wait 100
    tx 1FF [8] 00 00 00 00 FF FF FF 00
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
}

}  // namespace
}  // namespace costa::test
