// Transmit PDOs: every transmission type, inhibit time, event timer, SYNC start value, SYNC
// window, remote requests, consistency. Example TPDO1: COB-ID 0x181, type 255, maps 0x2001
// (UNSIGNED32 uptime, 0 here) and 0x2011 (INTEGER16 temperature 215). TPDO3: invalid,
// COB-ID 0x381, maps 0x2000 (UNSIGNED32 setpoint 1000).
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Tpdo = ExampleNodeTest;

constexpr const char* kEnableTpdo3 = R"(
    rx 601 [8] 23 02 18 01 81 03 00 00   # TPDO3 COB-ID 0x381, valid
    tx 581 [8] 60 02 18 01 00 00 00 00
)";

constexpr const char* kTpdo3Type252 = R"(
    rx 601 [8] 2F 02 18 02 FC 00 00 00   # TPDO3 type 252 (synchronous, on RTR only)
    tx 581 [8] 60 02 18 02 00 00 00 00
)";

TEST_F(Tpdo, EventDrivenOnApplicationEvent) {
  EXPECT_TRANSCRIPT("rx 000 [2] 01 01\nsilence");
  withNode([](Node& node) { node.markChanged(0x2001, 0); });
  EXPECT_TRANSCRIPT("tx 181 [6] 00 00 00 00 D7 00");
  withNode([](Node& node) { node.markChanged(0x2000, 0); });  // mapped only by invalid TPDO3
  EXPECT_TRANSCRIPT("silence");
  withNode([](Node& node) {
    EXPECT_TRUE(node.requestTpdo(0x1801));
    EXPECT_TRUE(node.requestTpdo(0x1803));  // invalid: nothing is sent
    EXPECT_FALSE(node.requestTpdo(0x1900));
  });
  EXPECT_TRANSCRIPT("tx 281 [8] FF FF FF FF FF FF FF FF");
}

// An application event on a DOMAIN (0x2008, the scratch pad, which no PDO can map) signals no
// TPDO, even one that maps the value at the offset the DOMAIN's reference holds (0x1001, the
// first of the RAM block: TPDO1 remapped to it).
TEST_F(Tpdo, AnEventOnADomainSignalsNoTpdo) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 18 01 81 01 00 80   # TPDO1 not valid
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2F 00 1A 00 00 00 00 00   # its mapping disabled
    tx 581 [8] 60 00 1A 00 00 00 00 00
    rx 601 [8] 23 00 1A 01 08 00 01 10   # 0x1001:00, 8 bits
    tx 581 [8] 60 00 1A 01 00 00 00 00
    rx 601 [8] 2F 00 1A 00 01 00 00 00
    tx 581 [8] 60 00 1A 00 00 00 00 00
    rx 601 [8] 23 00 18 01 81 01 00 00   # valid again
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 000 [2] 01 01
    silence
  )");
  withNode([](Node& node) { node.markChanged(0x2008, 0); });
  EXPECT_TRANSCRIPT("silence");
  withNode([](Node& node) { node.markChanged(0x1001, 0); });
  EXPECT_TRANSCRIPT("tx 181 [1] 00");
}

TEST_F(Tpdo, NoTransmissionOutsideOperational) {
  withNode([](Node& node) { node.markChanged(0x2001, 0); });
  EXPECT_TRANSCRIPT(R"(
    rx 080 [0]
    rx 181 [0] RTR
    silence
    rx 000 [2] 01 01
    silence                              # the pre-operational event is not remembered
  )");
}

TEST_F(Tpdo, EventTimerSendsPeriodicallyUntilStopped) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 00 18 05 64 00 00 00   # event timer 100 ms
    tx 581 [8] 60 00 18 05 00 00 00 00
    wait 300
    silence
    rx 000 [2] 01 01
    wait 99
    silence
    wait 1
    tx 181 [6] 00 00 00 00 D7 00
    wait 100
    tx 181 [6] 00 00 00 00 D7 00
    rx 000 [2] 02 01                     # stopped: PDOs fall silent
    wait 1000
    silence
  )");
}

TEST_F(Tpdo, InhibitTimeDelaysButKeepsEvents) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 18 03 F4 01 00 00   # inhibit while valid: refused
    tx 581 [8] 80 00 18 03 30 00 09 06
  )");
  EXPECT_TRANSCRIPT(kTpdo1Inhibit50ms);
  withNode([](Node& node) { node.markChanged(0x2011, 0); });
  EXPECT_TRANSCRIPT("tx 181 [6] 00 00 00 00 D7 00\nwait 10");
  withNode([](Node& node) { node.markChanged(0x2011, 0); });
  withNode([](Node& node) { node.markChanged(0x2011, 0); });  // merged with the previous event
  EXPECT_TRANSCRIPT(
      "silence\nwait 39\nsilence\nwait 1\ntx 181 [6] 00 00 00 00 D7 00\nwait 200\nsilence");
}

TEST_F(Tpdo, AnEventTimerThatExpiresWithinTheInhibitTimeSendsWhenItEnds) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 00 18 01 81 01 00 80   # invalidate
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2B 00 18 03 F4 01 00 00   # inhibit 500 x 100 us = 50 ms
    tx 581 [8] 60 00 18 03 00 00 00 00
    rx 601 [8] 2B 00 18 05 14 00 00 00   # event timer 20 ms, shorter
    tx 581 [8] 60 00 18 05 00 00 00 00
    rx 601 [8] 23 00 18 01 81 01 00 00   # valid again
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 000 [2] 01 01
    wait 19
    silence
    wait 1
    tx 181 [6] 00 00 00 00 D7 00         # the event timer; inhibited for 50 ms from here
    wait 49
    silence                              # the timer expired at 40 ms, within the inhibit time
    wait 1
    tx 181 [6] 00 00 00 00 D7 00         # at its end, the timer restarted
    wait 49
    silence
    wait 1
    tx 181 [6] 00 00 00 00 D7 00
  )");
  // Past the timer (20 ms on), within the inhibit time (50 ms): the next deadline is its end.
  withNode([](Node& node) {
    const Microseconds sent = node.now();
    EXPECT_EQ(node.process(sent + 30000U), sent + 50000U);
  });
}

// A parameter written while operational (the event timer may change while the PDO is valid)
// restarts the PDO's timers, but keeps its waiting event and its running inhibit time.
TEST_F(Tpdo, WritingTheEventTimerKeepsAWaitingEventAndTheInhibitTime) {
  EXPECT_TRANSCRIPT(kTpdo1Inhibit50ms);
  withNode([](Node& node) { ASSERT_TRUE(node.requestTpdo(0x1800)); });
  EXPECT_TRANSCRIPT(R"(
    tx 181 [6] xx xx xx xx D7 00         # at once; inhibited for 50 ms
    wait 10
  )");
  withNode([](Node& node) { ASSERT_TRUE(node.requestTpdo(0x1800)); });  // waits for its end
  EXPECT_TRANSCRIPT(R"(
    wait 10
    rx 601 [8] 2B 00 18 05 64 00 00 00   # event timer 100 ms, while valid
    tx 581 [8] 60 00 18 05 00 00 00 00
    silence                              # the inhibit time still runs
    wait 29
    silence
    wait 1
    tx 181 [6] xx xx xx xx D7 00         # 50 ms: the event that waited
  )");
}

TEST_F(Tpdo, WritingAParameterKeepsTheEventOfAnAcyclicSynchronousPdo) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 18 02 00 00 00 00   # type 0: at the SYNC after an event
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 000 [2] 01 01
  )");
  withNode([](Node& node) { ASSERT_TRUE(node.requestTpdo(0x1800)); });
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 00 18 05 64 00 00 00   # event timer 100 ms, while valid
    tx 581 [8] 60 00 18 05 00 00 00 00
    rx 080 [0]
    tx 181 [6] xx xx xx xx D7 00         # the event still counts
    rx 080 [0]
    silence
  )");
}

TEST_F(Tpdo, SynchronousCyclicEveryNthSync) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 18 02 03 00 00 00   # every 3rd SYNC
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 000 [2] 01 01
    rx 080 [0]
    rx 080 [0]
    silence
    rx 080 [0]
    tx 181 [6] 00 00 00 00 D7 00
    rx 080 [0]
    rx 080 [0]
    silence
    rx 080 [0]
    tx 181 [6] 00 00 00 00 D7 00
  )");
}

TEST_F(Tpdo, SynchronousAcyclicOnlyAfterAnEvent) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 18 02 00 00 00 00   # type 0
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 000 [2] 01 01
    rx 080 [0]
    silence
  )");
  withNode([](Node& node) { node.markChanged(0x2001, 0); });
  EXPECT_TRANSCRIPT("silence\nrx 080 [0]\ntx 181 [6] 00 00 00 00 D7 00\nrx 080 [0]\nsilence");
}

TEST_F(Tpdo, SyncRtrOnlySendsWhatTheSyncSampled) {
  EXPECT_TRANSCRIPT(std::string(kTpdo3Type252) + kEnableTpdo3 + R"(
    rx 000 [2] 01 01
    rx 080 [0]                           # samples setpoint 1000
    silence
    rx 601 [8] 23 00 20 00 D0 07 00 00   # setpoint 2000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 381 [0] RTR
    tx 381 [4] E8 03 00 00
    rx 080 [0]
    rx 381 [0] RTR
    tx 381 [4] D0 07 00 00
  )");
}

// Until the first SYNC after entering operational has sampled it, a remote request sends the
// value as it is then, as type 253 does; entering operational again forgets an earlier sample.
TEST_F(Tpdo, SyncRtrOnlySendsTheCurrentValueUntilTheFirstSync) {
  EXPECT_TRANSCRIPT(std::string(kTpdo3Type252) + kEnableTpdo3 + R"(
    rx 000 [2] 01 01
    rx 381 [0] RTR                       # no SYNC yet: setpoint 1000 as it is now
    tx 381 [4] E8 03 00 00
    rx 601 [8] 23 00 20 00 D0 07 00 00   # setpoint 2000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 381 [0] RTR
    tx 381 [4] D0 07 00 00
    rx 080 [0]                           # samples 2000
    rx 601 [8] 23 00 20 00 B8 0B 00 00   # setpoint 3000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 381 [0] RTR
    tx 381 [4] D0 07 00 00
    rx 000 [2] 80 01                     # pre-operational, then operational again
    rx 000 [2] 01 01
    rx 381 [0] RTR                       # the sample of 2000 is gone: 3000
    tx 381 [4] B8 0B 00 00
  )");
}

TEST_F(Tpdo, RtrOnlySendsTheCurrentValue) {
  EXPECT_TRANSCRIPT(std::string(R"(
    rx 601 [8] 2F 02 18 02 FD 00 00 00   # TPDO3 type 253
    tx 581 [8] 60 02 18 02 00 00 00 00
  )") + kEnableTpdo3 +
                    R"(
    rx 000 [2] 01 01
    rx 080 [0]
    silence
    rx 381 [0] RTR
    tx 381 [4] E8 03 00 00
    rx 381 [4] RTR                       # DLC of a remote request does not matter
    tx 381 [4] E8 03 00 00
  )");
}

TEST_F(Tpdo, RemoteRequestsNeedTheCobIdAndTheTypeToAllowThem) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    rx 181 [0] RTR                       # type 255, RTR allowed (bit 30 = 0)
    tx 181 [6] 00 00 00 00 D7 00
    rx 601 [8] 23 00 18 01 81 01 00 40   # bit 30: no RTR
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 181 [0] RTR
    silence
    rx 601 [8] 23 00 18 01 81 01 00 00
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2F 00 18 02 01 00 00 00   # synchronous type: not answered (CiA 301)
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 181 [0] RTR
    silence
  )");
}

// CiA 301: the inhibit time is the least interval between transmissions of an event-driven
// TPDO, an answer to a remote request too: within it the answer waits for its end.
TEST_F(Tpdo, ARemoteRequestWithinTheInhibitTimeIsAnsweredWhenItEnds) {
  EXPECT_TRANSCRIPT(kTpdo1Inhibit50ms);
  EXPECT_TRANSCRIPT(R"(
    rx 181 [0] RTR
    tx 181 [6] 00 00 00 00 D7 00         # answered at once; inhibited for 50 ms
    wait 10
    rx 181 [0] RTR
    silence
    wait 39
    silence
    wait 1
    tx 181 [6] 00 00 00 00 D7 00         # 50 ms: the answer
    wait 50
    rx 181 [0] RTR                       # the inhibit time is over: at once
    tx 181 [6] 00 00 00 00 D7 00
  )");
}

TEST_F(Tpdo, SyncStartValueDelaysTheFirstTransmission) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 19 10 00 0A 00 00 00   # SYNC counter overflow 10
    tx 581 [8] 60 19 10 00 00 00 00 00
    rx 601 [8] 2F 02 18 02 02 00 00 00   # TPDO3 every 2nd SYNC
    tx 581 [8] 60 02 18 02 00 00 00 00
    rx 601 [8] 2F 02 18 06 F1 00 00 00   # 241..255 are reserved (CiA 301)
    tx 581 [8] 80 02 18 06 30 00 09 06
    rx 601 [8] 2F 02 18 06 FF 00 00 00
    tx 581 [8] 80 02 18 06 30 00 09 06
    rx 601 [8] 2F 02 18 06 F0 00 00 00   # 240, the highest
    tx 581 [8] 60 02 18 06 00 00 00 00
    rx 601 [8] 2F 02 18 06 03 00 00 00   # starting at counter 3
    tx 581 [8] 60 02 18 06 00 00 00 00
    rx 601 [8] 23 02 18 01 81 03 00 00
    tx 581 [8] 60 02 18 01 00 00 00 00
    rx 601 [8] 2F 02 18 06 04 00 00 00   # start value of a valid PDO: refused
    tx 581 [8] 80 02 18 06 30 00 09 06
    rx 000 [2] 01 01
    rx 080 [1] 01
    rx 080 [1] 02
    silence
    rx 080 [1] 03
    tx 381 [4] E8 03 00 00
    rx 080 [1] 04
    silence
    rx 080 [1] 05
    tx 381 [4] E8 03 00 00
    rx 080 [1] 06
    rx 080 [1] 07
    tx 381 [4] E8 03 00 00
  )");
}

// CiA 301, 0x1800 sub-index 6: without a counter in the SYNC (0x1019 = 0), the start value has
// nothing to match and is not used: the PDO counts its SYNCs from the first.
TEST_F(Tpdo, SyncStartValueIsNotUsedWhenTheSyncCarriesNoCounter) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 02 18 02 02 00 00 00   # TPDO3 every 2nd SYNC
    tx 581 [8] 60 02 18 02 00 00 00 00
    rx 601 [8] 2F 02 18 06 03 00 00 00   # starting at counter 3
    tx 581 [8] 60 02 18 06 00 00 00 00
    rx 601 [8] 23 02 18 01 81 03 00 00
    tx 581 [8] 60 02 18 01 00 00 00 00
    rx 000 [2] 01 01
    rx 080 [0]
    silence
    rx 080 [0]
    tx 381 [4] E8 03 00 00
    rx 080 [0]
    silence
    rx 080 [0]
    tx 381 [4] E8 03 00 00
  )");
}

TEST_F(Tpdo, SynchronousPdosAreDroppedWhenTheSyncWindowHasPassed) {
  EXPECT_TRANSCRIPT(std::string(R"(
    rx 601 [8] 23 07 10 00 E8 03 00 00   # window 1000 us
    tx 581 [8] 60 07 10 00 00 00 00 00
    rx 601 [8] 2F 02 18 02 01 00 00 00
    tx 581 [8] 60 02 18 02 00 00 00 00
  )") + kEnableTpdo3 +
                    "rx 000 [2] 01 01");
  bus_.can().setAccepting(false);
  EXPECT_TRANSCRIPT("rx 080 [0]\nwait 2");
  bus_.can().setAccepting(true);
  bus_.advance(0);
  EXPECT_TRANSCRIPT("silence");
  EXPECT_EQ(bus_.node().txExpired(), 1U);
  bus_.can().setAccepting(false);
  EXPECT_TRANSCRIPT("rx 080 [0]");
  bus_.advance(500);  // within the window
  bus_.can().setAccepting(true);
  bus_.advance(0);
  EXPECT_TRANSCRIPT("tx 381 [4] E8 03 00 00");
}

TEST_F(Tpdo, NeverMixesTwoWritesOfAMappedEntry) {
  // TPDO2 maps 0x2004:05 (INTEGER64, -1). A segmented download of a new value is in progress
  // while SYNCs trigger the PDO: it carries the old value until the download completes.
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 01 18 02 01 00 00 00
    tx 581 [8] 60 01 18 02 00 00 00 00
    rx 000 [2] 01 01
    rx 601 [8] 21 04 20 05 08 00 00 00
    tx 581 [8] 60 04 20 05 00 00 00 00
    rx 601 [8] 00 11 22 33 44 55 66 77
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 080 [0]
    tx 281 [8] FF FF FF FF FF FF FF FF
    rx 601 [8] 1D 08 00 00 00 00 00 00
    tx 581 [8] 30 00 00 00 00 00 00 00
    rx 080 [0]
    tx 281 [8] 11 22 33 44 55 66 77 08
  )");
}

TEST_F(Tpdo, Type254IsEventDrivenLike255) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 00 18 02 FE 00 00 00
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 000 [2] 01 01
    rx 080 [0]
    silence
    rx 181 [0] RTR
    tx 181 [6] 00 00 00 00 D7 00
  )");
  withNode([](Node& node) { node.markChanged(0x2011, 0); });
  EXPECT_TRANSCRIPT("tx 181 [6] 00 00 00 00 D7 00");
}

class TpdoSoloStyle : public ExampleNodeTest {
 public:
  static NodeSettings settings() {
    NodeSettings settings;
    settings.profile.pdo.tpdoRtrTypes = TpdoRtrTypes::kAllTypes;
    settings.profile.pdo.tpdoType0 = TpdoType0::kEverySync;
    settings.profile.pdo.tpdoOnEnteringOperational = true;
    return settings;
  }

 protected:
  TpdoSoloStyle() : ExampleNodeTest(settings()) {}
};

TEST_F(TpdoSoloStyle, ProfileSelectsRtrTypesTypeZeroAndStartTransmission) {
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    tx 181 [6] 00 00 00 00 D7 00         # event-driven PDOs once on entering operational
    tx 281 [8] FF FF FF FF FF FF FF FF
    rx 601 [8] 2F 00 18 02 00 00 00 00   # type 0: every SYNC
    tx 581 [8] 60 00 18 02 00 00 00 00
    rx 080 [0]
    tx 181 [6] 00 00 00 00 D7 00
    rx 080 [0]
    tx 181 [6] 00 00 00 00 D7 00
    rx 181 [0] RTR                       # and on RTR
    tx 181 [6] 00 00 00 00 D7 00
  )");
}

class TpdoAutomaticStart : public ExampleNodeTest {
 protected:
  static NodeSettings settings() {
    NodeSettings settings = TpdoSoloStyle::settings();
    settings.automaticStart = true;
    return settings;
  }
  TpdoAutomaticStart() : ExampleNodeTest(settings()) {}
  void SetUp() override {}  // the boot-up is the test's first line
};

TEST_F(TpdoAutomaticStart, EnteringOperationalByItselfSendsThePdosInTheSameCycle) {
  // After every boot-up, also one long after power-on: the start and its PDOs come at once.
  EXPECT_TRANSCRIPT(R"(
    tx 701 [1] 00
    tx 181 [6] 00 00 00 00 D7 00
    tx 281 [8] FF FF FF FF FF FF FF FF
    wait 1500
    rx 000 [2] 81 01
    tx 701 [1] 00
    tx 181 [6] 00 00 00 00 D7 00
    tx 281 [8] FF FF FF FF FF FF FF FF
    wait 700
    rx 000 [2] 82 01
    tx 701 [1] 00
    tx 181 [6] 00 00 00 00 D7 00
    tx 281 [8] FF FF FF FF FF FF FF FF
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
}

}  // namespace
}  // namespace costa::test
