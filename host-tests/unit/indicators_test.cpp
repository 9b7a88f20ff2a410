// CiA 303-3 indicators edge by edge on the virtual clock: the example node (node-id 1) with
// Indicators over it; each LED change is recorded with its time in ms since the check began.
#include <string>
#include <vector>

#include "costa/indicators.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

/// Records each switch as "R1@200" (RUN on at 200 ms) or "E0@50"; fixed storage (the node's
/// context allocates nothing).
class RecordingOutputs final : public IndicatorOutputs {
 public:
  void setRun(bool on) noexcept override { add('R', on); }
  void setError(bool on) noexcept override { add('E', on); }
  void startAt(Microseconds origin) {
    origin_ = origin;
    count_ = 0;
  }
  void setNow(Microseconds now) { now_ = now; }
  std::vector<std::string> edges() const {
    std::vector<std::string> text;
    for (size_t i = 0; i < count_; ++i) {
      text.push_back(std::string(1, edges_[i].led) + (edges_[i].on ? "1@" : "0@") +
                     std::to_string(edges_[i].milliseconds));
    }
    return text;
  }

 private:
  struct Edge {
    char led;
    bool on;
    uint32_t milliseconds;
  };
  void add(char led, bool on) {
    if (count_ < kCapacity) {
      edges_[count_++] = Edge{led, on, (now_ - origin_) / 1000U};
    }
  }
  static constexpr size_t kCapacity = 64;
  Edge edges_[kCapacity] = {};
  size_t count_ = 0;
  Microseconds origin_ = 0;
  Microseconds now_ = 0;
};

class IndicatorsTest : public ExampleNodeTest {
 protected:
  IndicatorsTest() : indicators_(bus_.node(), outputs_) {}

  void SetUp() override {
    ExampleNodeTest::SetUp();
    ASSERT_TRUE(indicators_.attached());
    begin();
  }
  /// Starts a new record at the bus's time, after bringing the LEDs up to date.
  void begin() {
    outputs_.setNow(bus_.now());
    outputs_.startAt(bus_.now());
    step();
  }
  void step() {
    outputs_.setNow(bus_.now());
    (void)indicators_.process(bus_.now());
  }
  /// `milliseconds` pass, one at a time, the indicators following.
  std::vector<std::string> run(uint32_t milliseconds) {
    for (uint32_t i = 0; i < milliseconds; ++i) {
      bus_.advance(1000);
      step();
    }
    return outputs_.edges();
  }
  /// Plays `text`, then the indicators follow at once.
  void frames(const std::string& text) {
    EXPECT_EQ(play(text), "");
    step();
  }

  RecordingOutputs outputs_;
  Indicators indicators_;
};

using Edges = std::vector<std::string>;

TEST_F(IndicatorsTest, PreOperationalBlinksRun) {
  EXPECT_EQ(indicators_.run(), IndicatorState::kBlinking);
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
  EXPECT_EQ(run(850), (Edges{"R1@0", "R0@200", "R1@400", "R0@600", "R1@800"}));
}

TEST_F(IndicatorsTest, OperationalIsOnAndStoppedFlashesOnce) {
  run(100);  // blinking, on
  frames("rx 000 [2] 01 01");
  begin();
  EXPECT_EQ(indicators_.run(), IndicatorState::kOn);
  EXPECT_EQ(run(500), Edges{});  // already on: no edge
  frames("rx 000 [2] 02 01");
  EXPECT_EQ(indicators_.run(), IndicatorState::kSingleFlash);
  EXPECT_EQ(run(2500), (Edges{"R0@700", "R1@1700", "R0@1900", "R1@2900"}));
}

/// 0x1016:01 monitors node 5 within 100 ms, and node 5's first heartbeat arrives.
constexpr const char* kNode5Within100ms = R"(
    rx 601 [8] 23 16 10 01 64 00 05 00
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 705 [1] 05
)";

TEST_F(IndicatorsTest, AHeartbeatTimeoutDoubleFlashesErrorUntilItsProducerReturns) {
  frames(kNode5Within100ms);
  begin();
  run(99);
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
  bus_.advance(1000);  // the timeout: EMCY, and the error control event
  frames("tx 081 [8] 30 81 11 05 00 00 00 00");
  EXPECT_EQ(indicators_.error(), IndicatorState::kDoubleFlash);
  const Edges errorEdges = {"E1@100", "E0@300", "E1@500", "E0@700", "E1@1700", "E0@1900"};
  Edges seen;
  for (const std::string& edge : run(1850)) {
    if (edge[0] == 'E') {
      seen.push_back(edge);
    }
  }
  EXPECT_EQ(seen, errorEdges);
  frames("rx 705 [1] 05\ntx 081 [8] 00 00 00 00 00 00 00 00");
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
}

// The entry that timed out gets a new value: its error control event ends with it, and a
// timeout of the new producer is one event again, ended by that producer's return.
TEST_F(IndicatorsTest, ANewValueOfATimedOutEntryEndsItsErrorControlEvent) {
  frames(kNode5Within100ms);
  begin();
  bus_.advance(100000);
  frames("tx 081 [8] 30 81 11 05 00 00 00 00");
  EXPECT_EQ(indicators_.error(), IndicatorState::kDoubleFlash);
  frames(R"(
    rx 601 [8] 23 16 10 01 64 00 06 00   # node 6 instead
    tx 581 [8] 60 16 10 01 00 00 00 00
    tx 081 [8] 00 00 00 00 00 00 00 00   # the error is gone with the old value
  )");
  step();
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
  frames("rx 706 [1] 05");
  bus_.advance(100000);
  frames("tx 081 [8] 30 81 11 06 00 00 00 00");
  EXPECT_EQ(indicators_.error(), IndicatorState::kDoubleFlash);
  frames("rx 706 [1] 05\ntx 081 [8] 00 00 00 00 00 00 00 00");
  step();
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
}

TEST_F(IndicatorsTest, BusOffLightsErrorAboveEverythingElse) {
  bus_.node().onControllerEvent(CanControllerEvent::kErrorPassive, bus_.now());
  step();
  EXPECT_EQ(indicators_.error(), IndicatorState::kSingleFlash);
  bus_.node().onControllerEvent(CanControllerEvent::kBusOff, bus_.now());
  begin();
  EXPECT_EQ(indicators_.error(), IndicatorState::kOn);
  EXPECT_EQ(run(3000), (Edges{"R0@200", "R1@400", "R0@600", "R1@800", "R0@1000", "R1@1200",
                              "R0@1400", "R1@1600", "R0@1800", "R1@2000", "R0@2200", "R1@2400",
                              "R0@2600", "R1@2800", "R0@3000"}));  // RUN blinks; ERROR stays on
  bus_.node().onControllerEvent(CanControllerEvent::kBusOffRecovered, bus_.now());
  step();
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);  // recovery ends error passive too
}

TEST_F(IndicatorsTest, LssConfigurationFlickersBothInOppositePhase) {
  run(10);
  frames("rx 7E5 [8] 04 01 00 00 00 00 00 00");  // switch state global: configuration
  begin();
  EXPECT_EQ(indicators_.run(), IndicatorState::kFlickering);
  EXPECT_EQ(indicators_.error(), IndicatorState::kFlickering);
  EXPECT_EQ(run(160), (Edges{"R0@50", "E1@50", "R1@100", "E0@100", "R0@150", "E1@150"}));
  frames("rx 7E5 [8] 04 00 00 00 00 00 00 00");  // waiting state
  EXPECT_EQ(indicators_.run(), IndicatorState::kBlinking);
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
}

TEST_F(IndicatorsTest, AMissingSyncTripleFlashesErrorAfterOneAndAHalfPeriods) {
  frames(R"(
    rx 601 [8] 23 06 10 00 A0 86 01 00   # 0x1006 = 100 ms
    tx 581 [8] 60 06 10 00 00 00 00 00
    rx 080 [0]
  )");
  begin();
  run(149);
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
  frames("rx 080 [0]");  // in time: monitoring goes on from here
  begin();
  run(149);
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
  bus_.advance(1000);
  step();
  EXPECT_EQ(indicators_.error(), IndicatorState::kTripleFlash);
  Edges seen;
  for (const std::string& edge : run(2200)) {
    if (edge[0] == 'E') {
      seen.push_back(edge);
    }
  }
  EXPECT_EQ(seen, (Edges{"E1@150", "E0@350", "E1@550", "E0@750", "E1@950", "E0@1150", "E1@2150",
                         "E0@2350"}));
  frames("rx 080 [0]");
  EXPECT_EQ(indicators_.error(), IndicatorState::kOff);
}

TEST_F(IndicatorsTest, TheSyncTimeoutOfALongPeriodIsAtMostTheLongestDelay) {
  // 0x1006 = 0x55555554 µs: 1.5 times it is kLongestDelay - 1; 0xFFFFFFFF µs: beyond, so the
  // longest delay.
  const char* const periods[] = {"54 55 55 55", "FF FF FF FF"};
  const Microseconds timeouts[] = {kLongestDelay - 1U, kLongestDelay};
  for (int i = 0; i < 2; ++i) {
    frames(std::string("rx 601 [8] 23 06 10 00 ") + periods[i] + R"(
      tx 581 [8] 60 06 10 00 00 00 00 00
      rx 080 [0]
    )");
    begin();
    bus_.advance(timeouts[i] - 1U);
    step();
    EXPECT_EQ(indicators_.error(), IndicatorState::kOff) << i;
    bus_.advance(1);
    step();
    EXPECT_EQ(indicators_.error(), IndicatorState::kTripleFlash) << i;
  }
}

}  // namespace
}  // namespace costa::test
