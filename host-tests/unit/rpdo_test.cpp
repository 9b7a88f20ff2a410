// Receive PDOs: transmission types, length errors, deadline monitoring, dummy mapping, state.
// Example RPDO1: COB-ID 0x201, type 255, maps 0x2000 (UNSIGNED32) and 0x2004:02 (INTEGER8).
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Rpdo = ExampleNodeTest;

TEST_F(Rpdo, EventDrivenDataIsAppliedOnReception) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 F6        # setpoint 10000, offset -10
  )");
  EXPECT_EQ(value(0x2000, 0), 10000U);
  EXPECT_EQ(static_cast<int64_t>(value(0x2004, 2)), -10);
}

TEST_F(Rpdo, IgnoredOutsideOperational) {
  EXPECT_TRANSCRIPT("rx 201 [5] 10 27 00 00 F6");
  EXPECT_EQ(value(0x2000, 0), 1000U);
  EXPECT_TRANSCRIPT("rx 000 [2] 01 01\nrx 000 [2] 02 01\nrx 201 [5] 10 27 00 00 F6");
  EXPECT_EQ(value(0x2000, 0), 1000U);
}

TEST_F(Rpdo, TooShortIsNotAppliedAndRaisesEmcy8210) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [4] 10 27 00 00
    tx 081 [8] 10 82 11 00 00 00 00 00   # 0x8210, register: generic + communication
    rx 201 [4] 10 27 00 00               # still wrong: no second EMCY
    rx 201 [5] 20 4E 00 00 00            # right length: applied, error reset
    tx 081 [8] 00 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2000, 0), 20000U);
}

TEST_F(Rpdo, InvalidatingThePdoClearsItsLengthError) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [4] 10 27 00 00
    tx 081 [8] 10 82 11 00 00 00 00 00   # 0x8210
    rx 601 [8] 23 00 14 01 01 02 00 80   # invalidate RPDO1
    tx 581 [8] 60 00 14 01 00 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # the error of the old configuration no longer applies
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 00 00 00 00
  )");
}

TEST_F(Rpdo, TooLongIsAppliedAndRaisesEmcy8220) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [8] 10 27 00 00 05 AA BB CC
    tx 081 [8] 20 82 11 00 00 00 00 00
    rx 201 [5] 20 4E 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00
  )");
  EXPECT_EQ(value(0x2000, 0), 20000U);
  EXPECT_EQ(value(0x1001, 0), 0U);
}

TEST_F(Rpdo, ValueOutsideItsLimitsLeavesTheWholePdoUnapplied) {
  EXPECT_TRANSCRIPT("rx 000 [2] 01 01\nrx 201 [5] 05 00 00 00 07");  // setpoint 5 < 10
  EXPECT_EQ(value(0x2000, 0), 1000U);
  EXPECT_EQ(static_cast<int64_t>(value(0x2004, 2)), -5);
}

TEST_F(Rpdo, SynchronousDataWaitsForTheNextSync) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 14 02 01 00 00 00   # RPDO1 type 1
    tx 581 [8] 60 00 14 02 00 00 00 00
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 00
  )");
  EXPECT_EQ(value(0x2000, 0), 1000U);
  EXPECT_TRANSCRIPT("rx 201 [5] 20 4E 00 00 00");  // the latest data counts
  EXPECT_TRANSCRIPT("rx 080 [0]");
  EXPECT_EQ(value(0x2000, 0), 20000U);
  EXPECT_TRANSCRIPT("rx 080 [0]\nrx 201 [5] 30 75 00 00 00");
  EXPECT_EQ(value(0x2000, 0), 20000U);
  EXPECT_TRANSCRIPT("rx 080 [0]");
  EXPECT_EQ(value(0x2000, 0), 30000U);
}

// CiA 301, 0x1007: after the SYNC window, synchronous RPDOs are discarded until the next SYNC.
TEST_F(Rpdo, SynchronousDataAfterTheSyncWindowIsDiscarded) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 14 02 01 00 00 00   # RPDO1 type 1
    tx 581 [8] 60 00 14 02 00 00 00 00
    rx 601 [8] 23 07 10 00 E8 03 00 00   # SYNC window 1000 us
    tx 581 [8] 60 07 10 00 00 00 00 00
    rx 000 [2] 01 01
    rx 080 [0]
    rx 201 [5] 10 27 00 00 00            # within the window: held
    rx 080 [0]
  )");
  EXPECT_EQ(value(0x2000, 0), 10000U);
  EXPECT_TRANSCRIPT(R"(
    wait 2
    rx 201 [5] 20 4E 00 00 00            # 2 ms after the SYNC: discarded
    rx 080 [0]
  )");
  EXPECT_EQ(value(0x2000, 0), 10000U);
  EXPECT_TRANSCRIPT(R"(
    rx 201 [5] 30 75 00 00 00            # the next SYNC opened a window again
    rx 080 [0]
  )");
  EXPECT_EQ(value(0x2000, 0), 30000U);
}

TEST_F(Rpdo, HeldDataIsDroppedWhenLeavingOperational) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 14 02 00 00 00 00   # type 0
    tx 581 [8] 60 00 14 02 00 00 00 00
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 00
    rx 000 [2] 80 01
    rx 000 [2] 01 01
    rx 080 [0]
  )");
  EXPECT_EQ(value(0x2000, 0), 1000U);
}

TEST_F(Rpdo, EventTimerMonitorsTheDeadlineWithEmcy8250) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 00 14 05 64 00 00 00   # event timer 100 ms
    tx 581 [8] 60 00 14 05 00 00 00 00
    rx 000 [2] 01 01
    wait 500
    silence                              # monitoring starts at the first PDO
    rx 201 [5] 10 27 00 00 00
    wait 99
    silence
    rx 201 [5] 10 27 00 00 00            # in time: the deadline moves
    wait 99
    silence
    wait 1
    tx 081 [8] 50 82 11 00 00 00 00 00
    wait 1000
    silence
    rx 201 [5] 10 27 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00
  )");
}

// The missed deadline stays an error while the node is not operational, until a PDO comes.
TEST_F(Rpdo, AMissedDeadlineOutlivesLeavingOperationalUntilAPdoArrives) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 00 14 05 64 00 00 00   # event timer 100 ms
    tx 581 [8] 60 00 14 05 00 00 00 00
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 00
    wait 100
    tx 081 [8] 50 82 11 00 00 00 00 00
    rx 000 [2] 80 01                     # pre-operational
    rx 000 [2] 01 01                     # operational again
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 11 00 00 00   # still an error
    rx 201 [5] 10 27 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # the PDO came: no error left
  )");
}

// Reset communication configures the PDO again (its event timer back to 0): the errors its old
// parameters raised no longer apply.
TEST_F(Rpdo, ResetCommunicationClearsTheErrorsOfTheOldParameters) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 00 14 05 64 00 00 00   # event timer 100 ms
    tx 581 [8] 60 00 14 05 00 00 00 00
    rx 000 [2] 01 01
    rx 201 [6] 10 27 00 00 00 00         # too long: EMCY 0x8220
    tx 081 [8] 20 82 11 00 00 00 00 00
    wait 100
    tx 081 [8] 50 82 11 00 00 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # after the boot-up: both errors gone
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 00 00 00 00
  )");
}

TEST_F(Rpdo, DummyEntriesSkipBytes) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 02 16 00 00 00 00 00   # RPDO3 mapping: disable
    tx 581 [8] 60 02 16 00 00 00 00 00
    rx 601 [8] 23 02 16 01 08 00 05 00   # dummy UNSIGNED8
    tx 581 [8] 60 02 16 01 00 00 00 00
    rx 601 [8] 23 02 16 02 08 01 04 20   # 0x2004:01 BOOLEAN
    tx 581 [8] 60 02 16 02 00 00 00 00
    rx 601 [8] 2F 02 16 00 02 00 00 00
    tx 581 [8] 60 02 16 00 00 00 00 00
    rx 601 [8] 23 02 14 01 01 04 00 00   # COB-ID 0x401, valid
    tx 581 [8] 60 02 14 01 00 00 00 00
    rx 000 [2] 01 01
    rx 401 [2] FF 01
  )");
  EXPECT_EQ(value(0x2004, 1), 1U);
}

class RecordingRpdoEvents : public NodeEvents {
 public:
  void onRpdoReceived(uint16_t index) noexcept override { last = index; }
  void onRpdoTimeout(uint16_t index) noexcept override { timeout = index; }
  uint16_t last = 0;
  uint16_t timeout = 0;
};

TEST_F(Rpdo, TheApplicationHearsOfReceivedAndMissingPdos) {
  RecordingRpdoEvents events;
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 01 14 05 0A 00 00 00   # RPDO2 event timer 10 ms
    tx 581 [8] 60 01 14 05 00 00 00 00
    rx 000 [2] 01 01
    rx 301 [8] 01 00 00 00 02 00 03 00
  )");
  EXPECT_EQ(events.last, 0x1401U);
  EXPECT_EQ(static_cast<int64_t>(value(0x2004, 3)), 1);
  EXPECT_EQ(value(0x2005, 2), 3U);
  EXPECT_TRANSCRIPT("wait 10\ntx 081 [8] 50 82 11 00 00 00 00 00");
  EXPECT_EQ(events.timeout, 0x1401U);
}

}  // namespace
}  // namespace costa::test
