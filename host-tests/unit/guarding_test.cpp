// Node guarding and life guarding (0x100C, 0x100D), and the error behaviour (0x1029).
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Guarding = ExampleNodeTest;

/// Guard time 100 ms, life time factor 3: a life time of 300 ms.
constexpr const char* kLifeTime300Ms = R"(
    rx 601 [8] 2B 0C 10 00 64 00 00 00   # guard time 100 ms
    tx 581 [8] 60 0C 10 00 00 00 00 00
    rx 601 [8] 2F 0D 10 00 03 00 00 00   # life time factor 3: life time 300 ms
    tx 581 [8] 60 0D 10 00 00 00 00 00
)";
/// After kLifeTime300Ms: a request starts life guarding, then the heartbeat producer starts.
constexpr const char* kGuardedThenHeartbeat200Ms = R"(
    rx 701 [0] RTR
    tx 701 [1] 7F                        # life guarding runs
    rx 601 [8] 2B 17 10 00 C8 00 00 00   # heartbeat every 200 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
)";

TEST_F(Guarding, RepliesWithStateAndAlternatingToggleStartingAtZero) {
  EXPECT_TRANSCRIPT(R"(
    rx 701 [0] RTR
    tx 701 [1] 7F
    rx 701 [0] RTR
    tx 701 [1] FF
    rx 701 [1] RTR                       # a request with DLC 1 is a request too
    tx 701 [1] 7F
    rx 000 [2] 01 01
    rx 701 [0] RTR
    tx 701 [1] 85
    rx 000 [2] 02 01
    rx 701 [0] RTR
    tx 701 [1] 04
    rx 702 [0] RTR                       # another node's request
    silence
    rx 000 [2] 82 01                     # reset communication: toggle starts over
    tx 701 [1] 00
    rx 701 [0] RTR
    tx 701 [1] 7F
  )");
}

class RecordingGuardEvents : public NodeEvents {
 public:
  void onLifeGuardingExpired() noexcept override { ++expired; }
  void onLifeGuardingResumed() noexcept override { ++resumed; }
  int expired = 0;
  int resumed = 0;
};

TEST_F(Guarding, LifeTimeExpiryRaisesEmcy8130AndEntersPreOperational) {
  RecordingGuardEvents events;
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_TRANSCRIPT(kLifeTime300Ms);
  EXPECT_TRANSCRIPT(R"(
    rx 000 [2] 01 01
    wait 1000
    silence                              # life guarding starts with the first request
    rx 701 [0] RTR
    tx 701 [1] 05
    wait 299
    silence
    wait 1
    tx 081 [8] 30 81 11 00 00 00 00 00
  )");
  EXPECT_EQ(events.expired, 1);
  EXPECT_EQ(bus_.node().state(), NmtState::kPreOperational);  // 0x1029:01 = 0
  EXPECT_TRANSCRIPT(R"(
    wait 1000
    silence                              # one EMCY per event
    rx 701 [0] RTR
    tx 701 [1] FF
    tx 081 [8] 00 00 00 00 00 00 00 00   # guarding resumed: error reset
  )");
  EXPECT_EQ(events.resumed, 1);
}

TEST_F(Guarding, ResetCommunicationClearsALifeGuardingError) {
  EXPECT_TRANSCRIPT(kLifeTime300Ms);
  EXPECT_TRANSCRIPT(R"(
    rx 701 [0] RTR
    tx 701 [1] 7F
    wait 300
    tx 081 [8] 30 81 11 00 00 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # life guarding starts over: no error left
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 4F 01 10 00 00 00 00 00
  )");
}

// CiA 301 7.2.8.3.2: with a heartbeat producer time the heartbeat protocol is used; a guarding
// request is not answered and starts no life guarding.
TEST_F(Guarding, NoGuardingWhileTheHeartbeatProducerRuns) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 0C 10 00 64 00 00 00   # guard time 100 ms
    tx 581 [8] 60 0C 10 00 00 00 00 00
    rx 601 [8] 2F 0D 10 00 03 00 00 00   # life time factor 3
    tx 581 [8] 60 0D 10 00 00 00 00 00
    rx 601 [8] 2B 17 10 00 E8 03 00 00   # heartbeat every 1000 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 701 [0] RTR
    silence                              # not answered
    wait 999
    silence                              # no life guarding either
    wait 1
    tx 701 [1] 7F                        # the heartbeat
    rx 601 [8] 2B 17 10 00 00 00 00 00   # heartbeat off: guarding again
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 701 [0] RTR
    tx 701 [1] 7F
  )");
}

// Guarding that ran before the heartbeat producer started stops with it: the requests are no
// longer answered, so the life time would otherwise expire under a master that moved to
// heartbeats (docs/manual-errata.md).
TEST_F(Guarding, LifeGuardingThatRanStopsWhenTheHeartbeatStarts) {
  RecordingGuardEvents events;
  ASSERT_TRUE(bus_.node().addListener(events));
  EXPECT_TRANSCRIPT(kLifeTime300Ms);
  EXPECT_TRANSCRIPT(kGuardedThenHeartbeat200Ms);
  EXPECT_TRANSCRIPT(R"(
    wait 200
    tx 701 [1] 7F
    wait 200
    tx 701 [1] 7F                        # 400 ms after the request: no EMCY 0x8130
    wait 200
    tx 701 [1] 7F
    rx 601 [8] 2B 17 10 00 00 00 00 00   # heartbeat off: guarding again, from the next request
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 1000
    silence
    rx 701 [0] RTR
    tx 701 [1] FF                        # the toggle goes on from the last reply
    wait 299
    silence
    wait 1
    tx 081 [8] 30 81 11 00 00 00 00 00   # and its life time counts again
  )");
  EXPECT_EQ(events.expired, 1);
  EXPECT_EQ(events.resumed, 0);
}

// A request that comes while the heartbeat runs is not answered, and the life guarding it
// would have fed stops at once: a heartbeat that ends before the life time does not leave it
// to expire.
TEST_F(Guarding, AnUnansweredRequestStopsLifeGuarding) {
  EXPECT_TRANSCRIPT(kLifeTime300Ms);
  EXPECT_TRANSCRIPT(kGuardedThenHeartbeat200Ms);
  EXPECT_TRANSCRIPT(R"(
    wait 100
    rx 701 [0] RTR
    silence                              # not answered
    rx 601 [8] 2B 17 10 00 00 00 00 00   # heartbeat off before the life time ends
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 1000
    silence                              # no EMCY 0x8130
    rx 701 [0] RTR
    tx 701 [1] FF                        # guarding again
  )");
}

TEST_F(Guarding, ErrorBehaviourNoChangeOrStopped) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 0C 10 00 0A 00 00 00
    tx 581 [8] 60 0C 10 00 00 00 00 00
    rx 601 [8] 2F 0D 10 00 01 00 00 00
    tx 581 [8] 60 0D 10 00 00 00 00 00
    rx 601 [8] 2F 29 10 01 01 00 00 00   # no state change
    tx 581 [8] 60 29 10 01 00 00 00 00
    rx 601 [8] 2F 29 10 01 03 00 00 00   # 3 is outside 0..2
    tx 581 [8] 80 29 10 01 31 00 09 06
    rx 000 [2] 01 01
    rx 701 [0] RTR
    tx 701 [1] 05
    wait 10
    tx 081 [8] 30 81 11 00 00 00 00 00
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 29 10 01 02 00 00 00   # stopped
    tx 581 [8] 60 29 10 01 00 00 00 00
    rx 701 [0] RTR
    tx 701 [1] 85
    tx 081 [8] 00 00 00 00 00 00 00 00
    wait 10
    tx 081 [8] 30 81 11 00 00 00 00 00   # the EMCY leaves before the node stops
    rx 701 [0] RTR
    tx 701 [1] 04
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kStopped);
}

TEST_F(Guarding, NoLifeGuardingWithoutGuardTime) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 0D 10 00 03 00 00 00
    tx 581 [8] 60 0D 10 00 00 00 00 00
    rx 701 [0] RTR
    tx 701 [1] 7F
    wait 10000
    silence
  )");
}

class GuardingToggleStartsAtOne : public ExampleNodeTest {
 protected:
  static NodeSettings settings() {
    NodeSettings settings;
    settings.profile.errorControl.guardToggleStart = 1;
    return settings;
  }
  GuardingToggleStartsAtOne() : ExampleNodeTest(settings()) {}
};

TEST_F(GuardingToggleStartsAtOne, FirstReplyHasTheToggleBitSet) {
  EXPECT_TRANSCRIPT(R"(
    rx 701 [0] RTR
    tx 701 [1] FF
    rx 701 [0] RTR
    tx 701 [1] 7F
    rx 701 [0] RTR
    tx 701 [1] FF
  )");
}

class HeartbeatOnlyDevice : public ExampleNodeTest {
 protected:
  static NodeSettings settings() {
    NodeSettings settings;
    settings.profile.errorControl.nodeGuarding = false;
    return settings;
  }
  HeartbeatOnlyDevice() : ExampleNodeTest(settings()) {}
};

TEST_F(HeartbeatOnlyDevice, IgnoresGuardingRequestsAndCountsThem) {
  const uint32_t ignoredBefore = bus_.node().statistics().framesIgnored;
  EXPECT_TRANSCRIPT(R"(
    rx 701 [0] RTR
    silence
    rx 000 [2] 01 01
    rx 701 [0] RTR
    silence
    rx 601 [8] 2B 17 10 00 64 00 00 00   # its heartbeat works as ever
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 100
    tx 701 [1] 05
  )");
  EXPECT_EQ(bus_.node().statistics().framesIgnored, ignoredBefore + 2U);
}

}  // namespace
}  // namespace costa::test
