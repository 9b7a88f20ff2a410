// Profile fields of a device without EMCY, with an alarm in its heartbeat, without 0x1029 and with
// TPDOs that answer its RPDOs (the M-series joint's wire, docs/errata-m-series.md W6-W10): each
// through exact frames, beside the example device's unchanged CiA 301 answer.
#include "dictionary_node_bus.hpp"
#include "example_fixture.hpp"
#include "mseries_od.hpp"

namespace costa::test {
namespace {

NodeSettings withoutEmcyFrames() {
  NodeSettings settings;
  settings.profile.emcy.sendFrames = false;
  return settings;
}

NodeSettings withAlarmHeartbeat() {
  NodeSettings settings = withoutEmcyFrames();
  settings.profile.errorControl.heartbeatWhileError = 0x04;
  return settings;
}

NodeSettings withAnsweringTpdos() {
  NodeSettings settings;
  settings.profile.pdo.tpdoAnswersRpdo = true;
  return settings;
}

// --- EmcyProfile::sendFrames

TEST_F(ExampleNodeTest, Cia301AnErrorSendsItsEmcy) {
  withNode([](Node& node) { node.raiseError(0x3210, kErrorVoltage); });
  EXPECT_TRANSCRIPT(R"(
    tx 081 [8] 10 32 05 00 00 00 00 00
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 05 00 00 00
  )");
}

class WithoutEmcyFrames : public ExampleNodeTest {
 protected:
  WithoutEmcyFrames() : ExampleNodeTest(withoutEmcyFrames()) {}
};

TEST_F(WithoutEmcyFrames, AnErrorSetsTheRegisterAndSendsNothing) {
  withNode([](Node& node) { node.raiseError(0x3210, kErrorVoltage); });
  EXPECT_TRANSCRIPT(R"(
    silence
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 05 00 00 00   # the register shows it
    rx 601 [8] 40 03 10 01 00 00 00 00
    tx 581 [8] 43 03 10 01 10 32 00 00   # and so does the history
  )");
  withNode([](Node& node) { node.clearError(0x3210); });
  EXPECT_TRANSCRIPT(R"(
    silence                              # no error reset EMCY either
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 00 00 00 00
  )");
}

TEST_F(WithoutEmcyFrames, CommunicationErrorsSendNothingEither) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [2] 10 27                     # RPDO1 too short: 0x8210 in the register only
    silence
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 11 00 00 00
  )");
}

// --- ErrorControlProfile::heartbeatWhileError

TEST_F(ExampleNodeTest, Cia301TheHeartbeatShowsTheStateWhileAnErrorIsActive) {
  withNode([](Node& node) { node.raiseError(0x3210, kErrorVoltage); });
  EXPECT_TRANSCRIPT(R"(
    tx 081 [8] 10 32 05 00 00 00 00 00
    rx 601 [8] 2B 17 10 00 64 00 00 00   # heartbeat 100 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 000 [2] 01 01
    wait 100
    tx 701 [1] 05
  )");
}

class AlarmHeartbeat : public ExampleNodeTest {
 protected:
  AlarmHeartbeat() : ExampleNodeTest(withAlarmHeartbeat()) {}
};

TEST_F(AlarmHeartbeat, TheHeartbeatCarries04WhileAnErrorIsActiveAndTheStateStays) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 17 10 00 64 00 00 00   # heartbeat 100 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 000 [2] 01 01
    wait 100
    tx 701 [1] 05
  )");
  withNode([](Node& node) { node.raiseError(0x3210, kErrorVoltage); });
  EXPECT_TRANSCRIPT(R"(
    wait 100
    tx 701 [1] 04                        # the alarm (the NMT state stays operational)
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
  withNode([](Node& node) { node.clearError(0x3210); });
  EXPECT_TRANSCRIPT(R"(
    wait 100
    tx 701 [1] 05
  )");
}

// --- ErrorControlProfile::errorBehaviourWithoutObject

using JointDictionaryBus = DictionaryNodeBus<gen::mseries::Values, gen::mseries::Capacity>;

// The M-series dictionary has no 0x1029; its 0x1016:01 monitors node 0x7F with 2000 ms and its
// 0x1017 is 1000 ms. A node with it and the stack's defaults (CiA 301) goes pre-operational on a
// heartbeat timeout.
TEST(ErrorBehaviourWithoutObject, Cia301DefaultEntersPreOperational) {
  JointDictionaryBus bus(gen::mseries::kDefinition, NodeSettings{});
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 000 [2] 01 01
    rx 77F [1] 05
    wait 1000
    tx 701 [1] 05
    wait 1000
    tx 701 [1] 05
    tx 081 [8] 30 81 11 7F 00 00 00 00   # heartbeat error, producer 0x7F
    wait 1000
    tx 701 [1] 7F                        # pre-operational
  )",
                     bus),
            "");
}

TEST(ErrorBehaviourWithoutObject, OneKeepsTheState) {
  NodeSettings settings;
  settings.profile.errorControl.errorBehaviourWithoutObject = 1;
  JointDictionaryBus bus(gen::mseries::kDefinition, settings);
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 000 [2] 01 01
    rx 77F [1] 05
    wait 2000
    tx 701 [1] 05
    tx 701 [1] 05
    tx 081 [8] 30 81 11 7F 00 00 00 00
    wait 1000
    tx 701 [1] 05                        # still operational
  )",
                     bus),
            "");
}

TEST(ErrorBehaviourWithoutObject, TheObjectWinsOverTheField) {
  NodeSettings settings;
  settings.profile.errorControl.errorBehaviourWithoutObject = 1;
  InProcessBus bus(exampleWith(settings));
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 23 16 10 01 64 00 05 00   # node 5, 100 ms
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 000 [2] 01 01
    rx 705 [1] 05
    wait 100
    tx 081 [8] 30 81 11 05 00 00 00 00
    rx 701 [0] RTR                       # 0x1029:01 = 0: pre-operational
    tx 701 [1] 7F
  )",
                     bus),
            "");
}

// --- PdoProfile::tpdoAnswersRpdo

TEST_F(ExampleNodeTest, Cia301AnRpdoIsNotAnswered) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 F6
    silence
  )");
  EXPECT_EQ(value(0x2000, 0), 10000U);
}

class AnsweringTpdos : public ExampleNodeTest {
 protected:
  AnsweringTpdos() : ExampleNodeTest(withAnsweringTpdos()) {}
};

TEST_F(AnsweringTpdos, TpdoNAnswersEachRpdoN) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 F6            # RPDO1
    tx 181 [6] xx xx xx xx D7 00         # TPDO1 (uptime, temperature)
    rx 201 [5] 20 4E 00 00 F6
    tx 181 [6] xx xx xx xx D7 00
    silence
  )");
  EXPECT_EQ(value(0x2000, 0), 20000U);
}

TEST_F(AnsweringTpdos, ASynchronousRpdoIsAnsweredAtReception) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 14 02 01 00 00 00   # RPDO1 synchronous
    tx 581 [8] 60 00 14 02 00 00 00 00
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 F6
    tx 181 [6] xx xx xx xx D7 00         # at reception
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 E8 03 00 00   # the data waits for the SYNC: 1000 still
    rx 080 [0]
    silence                              # no answer at the SYNC
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 10 27 00 00
  )");
}

TEST_F(AnsweringTpdos, AnRpdoNotAcceptedIsNotAnswered) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [4] 10 27 00 00               # too short: not processed (EMCY 0x8210)
    tx 081 [8] 10 82 11 00 00 00 00 00
    rx 201 [6] 10 27 00 00 F6 00         # too long: processed (EMCY 0x8220), answered
    tx 181 [6] xx xx xx xx D7 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # 0x8210 gone
    tx 081 [8] 20 82 11 00 00 00 00 00
    rx 201 [5] 10 27 00 00 F6            # the right length again: answered
    tx 181 [6] xx xx xx xx D7 00
    tx 081 [8] 00 00 00 00 00 00 00 00
  )");
}

// Refuses every value of 0x2000 (RPDO1's first entry): RPDO1 is refused whole.
class RefusingHook : public ObjectHook {
 public:
  AbortCode check(od::ObjectDictionary&, const od::EntryRef&, const uint8_t*,
                  size_t) noexcept override {
    return AbortCode::kValueTooHigh;
  }
};

// TPDO1 with an inhibit time of 50 ms and an event timer of 20 ms, operational from 0 ms: sent by
// its timer at 20 ms, inhibited until 70 ms; the timer expires again at 40 ms, within it.
constexpr const char* kTimedTpdo1 = R"(
    rx 601 [8] 23 00 18 01 81 01 00 80   # invalidate
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2B 00 18 03 F4 01 00 00   # inhibit 500 x 100 us = 50 ms
    tx 581 [8] 60 00 18 03 00 00 00 00
    rx 601 [8] 2B 00 18 05 14 00 00 00   # event timer 20 ms
    tx 581 [8] 60 00 18 05 00 00 00 00
    rx 601 [8] 23 00 18 01 81 01 00 00   # valid again
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 000 [2] 01 01
    wait 20
    tx 181 [6] xx xx xx xx D7 00         # the event timer; inhibited until 70 ms
  )";

TEST_F(AnsweringTpdos, ARefusedRpdoIsNotAnswered) {
  static RefusingHook refusing;
  withNode([](Node& node) { ASSERT_TRUE(node.attachHook(0x2000, 0x2000, refusing)); });
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 F6            # of the right length, then refused: no answer
    silence
  )");
  EXPECT_EQ(value(0x2000, 0), 1000U);  // nothing written
}

TEST_F(AnsweringTpdos, ARefusedRpdoDoesNotTakeBackTheEventTimersTransmission) {
  static RefusingHook refusing;
  withNode([](Node& node) { ASSERT_TRUE(node.attachHook(0x2000, 0x2000, refusing)); });
  EXPECT_TRANSCRIPT(kTimedTpdo1);
  EXPECT_TRANSCRIPT(R"(
    wait 30                              # 50 ms: the timer expired at 40 ms
    rx 201 [5] 10 27 00 00 F6            # refused: its answer is taken back, not the timer's
    silence
    wait 19
    silence
    wait 1
    tx 181 [6] xx xx xx xx D7 00         # 70 ms: the end of the inhibit time
  )");
  EXPECT_EQ(value(0x2000, 0), 1000U);  // nothing written
}

TEST_F(AnsweringTpdos, ARefusedRpdoDoesNotTakeBackAnApplicationsEvent) {
  static RefusingHook refusing;
  withNode([](Node& node) { ASSERT_TRUE(node.attachHook(0x2000, 0x2000, refusing)); });
  EXPECT_TRANSCRIPT(kTpdo1Inhibit50ms);  // no event timer
  withNode([](Node& node) { ASSERT_TRUE(node.requestTpdo(0x1800)); });
  EXPECT_TRANSCRIPT(R"(
    tx 181 [6] xx xx xx xx D7 00         # at once; inhibited for 50 ms
    wait 10
  )");
  withNode([](Node& node) { ASSERT_TRUE(node.requestTpdo(0x1800)); });  // waits for its end
  EXPECT_TRANSCRIPT(R"(
    wait 10
    rx 201 [5] 10 27 00 00 F6            # refused: its answer is taken back, not that event
    silence
    wait 29
    silence
    wait 1
    tx 181 [6] xx xx xx xx D7 00         # 50 ms: the end of the inhibit time
  )");
}

TEST_F(AnsweringTpdos, NothingIsAnsweredOutsideOperational) {
  EXPECT_TRANSCRIPT(R"(
    rx 201 [5] 10 27 00 00 F6            # pre-operational: no PDO at all
    silence
  )");
}

}  // namespace
}  // namespace costa::test
