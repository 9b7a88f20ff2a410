// SYNC consumer and producer: 0x1005, 0x1006, 0x1007, 0x1019.
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Sync = ExampleNodeTest;

/// This node produces SYNC every 10 ms, with a counter 1..3.
constexpr const char* kProducerCounting1To3Every10ms = R"(
    rx 601 [8] 2F 19 10 00 03 00 00 00   # counter 1..3
    tx 581 [8] 60 19 10 00 00 00 00 00
    rx 601 [8] 23 06 10 00 10 27 00 00   # period 10000 us
    tx 581 [8] 60 06 10 00 00 00 00 00
    rx 601 [8] 23 05 10 00 80 00 00 40   # bit 30: this node produces
    tx 581 [8] 60 05 10 00 00 00 00 00
)";

constexpr const char* kTpdo1EverySync = R"(
    rx 601 [8] 2F 00 18 02 01 00 00 00
    tx 581 [8] 60 00 18 02 00 00 00 00
)";

TEST_F(Sync, ALengthThatDoesNotMatchTheCounterSettingRaisesEmcy8240) {
  EXPECT_TRANSCRIPT(std::string(kTpdo1EverySync) + R"(
    rx 000 [2] 01 01
    rx 080 [1] 05                        # counter byte, but 0x1019 = 0
    tx 081 [8] 40 82 11 00 00 00 00 00
    rx 080 [0]                           # the right length: handled, then the error reset
    tx 181 [6] 00 00 00 00 D7 00
    tx 081 [8] 00 00 00 00 00 00 00 00
  )");
}

// The length error belonged to the old 0x1019 value: a write of 0x1019 ends it, and so does
// reset communication, without a SYNC of the right length (the master may have stopped SYNC).
TEST_F(Sync, ALengthErrorEndsWithANew1019OrResetCommunication) {
  EXPECT_TRANSCRIPT(R"(
    rx 080 [1] 05                        # counter byte, but 0x1019 = 0
    tx 081 [8] 40 82 11 00 00 00 00 00
    rx 601 [8] 2F 19 10 00 04 00 00 00   # now with a counter: the error is gone
    tx 581 [8] 60 19 10 00 00 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00
    rx 080 [0]                           # without one
    tx 081 [8] 40 82 11 00 00 00 00 00
    rx 000 [2] 82 01                     # reset communication
    tx 701 [1] 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # the error reset, once the boot-up is out
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 00 00 00 00   # no error left
  )");
}

TEST_F(Sync, CounterSettingExpectsOneByte) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 19 10 00 04 00 00 00
    tx 581 [8] 60 19 10 00 00 00 00 00
    rx 080 [0]
    tx 081 [8] 40 82 11 00 00 00 00 00
  )");
}

TEST_F(Sync, ProducerSendsEveryPeriodWithItsCounter) {
  EXPECT_TRANSCRIPT(kProducerCounting1To3Every10ms);
  EXPECT_TRANSCRIPT(R"(
    wait 9
    silence
    wait 1
    tx 080 [1] 01
    wait 10
    tx 080 [1] 02
    wait 10
    tx 080 [1] 03
    wait 10
    tx 080 [1] 01
    rx 000 [2] 02 01                     # stopped: no SYNC production
    wait 50
    silence
  )");
}

// A new window (0x1007) changes nothing of the cycle: the next SYNC comes on time with the next
// counter. A new period (0x1006) counts from the write, the counter going on.
TEST_F(Sync, NewParametersKeepTheCounterGoing) {
  EXPECT_TRANSCRIPT(kProducerCounting1To3Every10ms);
  EXPECT_TRANSCRIPT(R"(
    wait 10
    tx 080 [1] 01
    wait 5
    rx 601 [8] 23 07 10 00 E8 03 00 00   # window 1 ms
    tx 581 [8] 60 07 10 00 00 00 00 00
    wait 5
    tx 080 [1] 02                        # 20 ms: on time
    wait 5
    rx 601 [8] 23 06 10 00 20 4E 00 00   # period 20 ms from here
    tx 581 [8] 60 06 10 00 00 00 00 00
    wait 19
    silence
    wait 1
    tx 080 [1] 03                        # the counter goes on
    wait 20
    tx 080 [1] 01
  )");
}

TEST_F(Sync, TheProducersCounterStartsOverAfterStopped) {
  EXPECT_TRANSCRIPT(kProducerCounting1To3Every10ms);
  EXPECT_TRANSCRIPT(R"(
    wait 10
    tx 080 [1] 01
    wait 10
    tx 080 [1] 02
    rx 000 [2] 02 01                     # stopped before the next one is due
    rx 000 [2] 80 01                     # pre-operational
    wait 10
    tx 080 [1] 01                        # from 1 again, not 3
  )");
}

// A write that stops production (period 0) and one that starts it again: the counter starts
// over, as it does after any stop.
TEST_F(Sync, TheProducersCounterStartsOverAfterAWriteStoppedIt) {
  EXPECT_TRANSCRIPT(kProducerCounting1To3Every10ms);
  EXPECT_TRANSCRIPT(R"(
    wait 10
    tx 080 [1] 01
    wait 10
    tx 080 [1] 02
    rx 601 [8] 23 06 10 00 00 00 00 00   # period 0: no production
    tx 581 [8] 60 06 10 00 00 00 00 00
    wait 30
    silence
    rx 601 [8] 23 06 10 00 10 27 00 00   # 10 ms again
    tx 581 [8] 60 06 10 00 00 00 00 00
    wait 10
    tx 080 [1] 01                        # from 1 again, not 3
    wait 10
    tx 080 [1] 02
  )");
}

TEST_F(Sync, TheProducersOwnSyncDrivesItsSynchronousPdos) {
  EXPECT_TRANSCRIPT(std::string(kTpdo1EverySync) + R"(
    rx 601 [8] 23 06 10 00 10 27 00 00
    tx 581 [8] 60 06 10 00 00 00 00 00
    rx 601 [8] 23 05 10 00 80 00 00 40
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 000 [2] 01 01
    wait 10
    tx 080 [0]
    tx 181 [6] 00 00 00 00 D7 00
  )");
}

TEST_F(Sync, ParameterRules) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 19 10 00 01 00 00 00   # overflow value 1 is not allowed
    tx 581 [8] 80 19 10 00 30 00 09 06
    rx 601 [8] 2F 19 10 00 F1 00 00 00   # nor above 240
    tx 581 [8] 80 19 10 00 30 00 09 06
    rx 601 [8] 23 05 10 00 80 00 00 20   # 29-bit SYNC
    tx 581 [8] 80 05 10 00 30 00 09 06
    rx 601 [8] 23 06 10 00 10 27 00 00
    tx 581 [8] 60 06 10 00 00 00 00 00
    rx 601 [8] 2F 19 10 00 02 00 00 00   # overflow only while the period is 0
    tx 581 [8] 80 19 10 00 22 00 00 08
    rx 601 [8] 23 05 10 00 80 00 00 40
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 601 [8] 23 05 10 00 81 00 00 40   # another CAN-ID while producing
    tx 581 [8] 80 05 10 00 30 00 09 06
  )");
}

TEST_F(Sync, ConsumerFollowsTheConfiguredCobId) {
  EXPECT_TRANSCRIPT(std::string(kTpdo1EverySync) + R"(
    rx 601 [8] 23 05 10 00 90 00 00 00   # SYNC on 0x090
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 000 [2] 01 01
    rx 080 [0]
    silence
    rx 090 [0]
    tx 181 [6] 00 00 00 00 D7 00
  )");
}

}  // namespace
}  // namespace costa::test
