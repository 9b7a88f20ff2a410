// The freestanding transcript replayer (host-tests/replay) against the host's own transcript
// layer: its compiled tables hold every transcript as the host parser reads it, it sends the
// same frames as InProcessBus for every transcript, and its verdicts fail with the host
// player's words when the slave does not do what a script says.
#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "frame_recorder.hpp"
#include "frame_text.hpp"
#include "in_process_bus.hpp"
#include "script_replay.hpp"
#include "suites.hpp"
#include "transcript.hpp"
#include "transcript_player.hpp"
#include "virtual_bus.hpp"

namespace costa::test {
namespace {

using replay::Script;
using replay::Step;
using replay::StepKind;

std::string nameOf(const std::string& path) {
  return path.substr(std::string(COSTA_TRANSCRIPT_DIR).size() + 1U);
}

std::vector<const replay::Suite*> suites() {
  return std::vector<const replay::Suite*>(replay::kSuites, replay::kSuites + replay::kSuiteCount);
}

const Script* findScript(const std::string& name) {
  for (const replay::Suite* suite : suites()) {
    for (size_t i = 0; i < suite->scriptCount; ++i) {
      if (name == suite->scripts[i].name) {
        return &suite->scripts[i];
      }
    }
  }
  return nullptr;
}

/// Keeps every frame the replayed node sends.
class SentFrames final : public replay::FrameListener {
 public:
  void onSent(const CanFrame& frame) noexcept override { frames.push_back(frame); }
  std::vector<CanFrame> frames;
};

struct Replayed {
  bool passed;
  std::string verdict;
  std::vector<CanFrame> frames;
};

Replayed replayed(const Script& script) {
  SentFrames sent;
  replay::FrameRecorder recorder(&sent);
  replay::FixedText<320> verdict;
  const bool passed = replay::replayScript(script, recorder, verdict);
  return Replayed{passed, verdict.c_str(), sent.frames};
}

std::vector<std::string> texts(const std::vector<CanFrame>& frames) {
  std::vector<std::string> lines;
  for (const CanFrame& frame : frames) {
    lines.push_back(host::formatFrame(frame));
  }
  return lines;
}

TEST(TranscriptTables, HoldEveryTranscriptAndNothingElse) {
  const std::vector<std::string> paths = findTranscripts(COSTA_TRANSCRIPT_DIR);
  size_t scripts = 0;
  for (const replay::Suite* suite : suites()) {
    scripts += suite->scriptCount;
    for (size_t i = 0; i < suite->scriptCount; ++i) {
      EXPECT_EQ(std::string(suite->scripts[i].name).rfind(std::string(suite->name) + "/", 0), 0U)
          << suite->scripts[i].name;
    }
  }
  EXPECT_EQ(scripts, paths.size());
  for (const std::string& path : paths) {
    EXPECT_NE(findScript(nameOf(path)), nullptr) << path << " is in no suite (CMakeLists.txt)";
  }
}

class TranscriptReplay : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    std::string error;
    ASSERT_TRUE(loadTranscript(GetParam(), &transcript_, &error)) << error;
    script_ = findScript(nameOf(GetParam()));
    ASSERT_NE(script_, nullptr) << GetParam();
  }

  Transcript transcript_;
  const Script* script_ = nullptr;
};

TEST_P(TranscriptReplay, TableIsWhatTheHostParserReads) {
  EXPECT_EQ(script_->device, transcript_.device);
  EXPECT_EQ(script_->nodeId, transcript_.nodeId);
  ASSERT_EQ(script_->ignoredCount, transcript_.ignored.size());
  for (size_t i = 0; i < script_->ignoredCount; ++i) {
    EXPECT_EQ(script_->ignored[i], transcript_.ignored[i]);
  }
  ASSERT_EQ(script_->stepCount, transcript_.steps.size());
  for (size_t i = 0; i < script_->stepCount; ++i) {
    const Step& step = script_->steps[i];
    const TranscriptStep& expected = transcript_.steps[i];
    SCOPED_TRACE("line " + std::to_string(expected.line));
    EXPECT_EQ(static_cast<int>(step.kind), static_cast<int>(expected.kind));
    EXPECT_EQ(step.line, static_cast<uint32_t>(expected.line));
    EXPECT_EQ(host::formatFrame(step.frame), host::formatFrame(expected.frame));
    EXPECT_EQ(step.frame.extended, expected.frame.extended);
    EXPECT_EQ(step.wildcards, expected.wildcards);
    EXPECT_EQ(step.milliseconds, expected.milliseconds);
    if (expected.kind == TranscriptStep::Kind::kSimulate) {
      ASSERT_NE(step.command, nullptr);
      EXPECT_EQ(step.command, expected.text);
    } else {
      EXPECT_EQ(step.command, nullptr);
    }
  }
}

TEST_P(TranscriptReplay, SendsWhatInProcessBusSends) {
  InProcessBus bus(transcript_.device, transcript_.nodeId);
  ASSERT_EQ(playTranscript(transcript_, bus), "");
  std::vector<CanFrame> host;
  for (size_t i = 0; i < bus.can().count(); ++i) {
    host.push_back(bus.can().at(i));
  }
  const Replayed result = replayed(*script_);
  EXPECT_TRUE(result.passed) << result.verdict;
  EXPECT_EQ(result.verdict, "");
  EXPECT_EQ(texts(result.frames), texts(host));
  EXPECT_FALSE(result.frames.empty());
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = nameOf(info.param);
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      c = '_';
    }
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(All, TranscriptReplay,
                         ::testing::ValuesIn(findTranscripts(COSTA_TRANSCRIPT_DIR)), testName);

// Hand-written tables, as the generator would write them, for scripts the slave does not follow.
constexpr CanFrame frame(uint32_t id, uint8_t dlc, uint8_t b0 = 0, uint8_t b1 = 0, uint8_t b2 = 0,
                         uint8_t b3 = 0, uint8_t b4 = 0, uint8_t b5 = 0) {
  return CanFrame{id, {b0, b1, b2, b3, b4, b5, 0, 0}, dlc, false, false};
}
constexpr Step tx(uint32_t line, const CanFrame& expected, uint8_t wildcards = 0) {
  return Step{StepKind::kTransmit, line, wildcards, expected, 0, nullptr};
}
constexpr Step rx(uint32_t line, const CanFrame& sent) {
  return Step{StepKind::kReceive, line, 0, sent, 0, nullptr};
}
constexpr Step wait(uint32_t line, uint64_t milliseconds) {
  return Step{StepKind::kWait, line, 0, CanFrame{}, milliseconds, nullptr};
}
constexpr Step silence(uint32_t line) {
  return Step{StepKind::kSilence, line, 0, CanFrame{}, 0, nullptr};
}
constexpr Step sim(uint32_t line, const char* command) {
  return Step{StepKind::kSimulate, line, 0, CanFrame{}, 0, command};
}

template <size_t N>
Script script(const char* device, uint8_t nodeId, const Step (&steps)[N],
              const uint32_t* ignored = nullptr, size_t ignoredCount = 0) {
  return Script{"wrong.transcript", device, nodeId, steps, N, ignored, ignoredCount};
}

/// The host player's verdict for the same steps written as text ("<inline>" for the path).
std::string hostVerdict(const std::string& device, int nodeId, const std::string& text) {
  InProcessBus bus(device, nodeId);
  std::string verdict = playText(text, bus);
  const std::string inlinePath = "<inline>";
  if (verdict.rfind(inlinePath, 0) == 0) {
    verdict.replace(0, inlinePath.size(), "wrong.transcript");
  }
  return verdict;
}

TEST(ReplayVerdict, NamesAnUnexpectedFrame) {
  static constexpr Step kSteps[] = {tx(2, frame(0x701, 1, 0x05))};
  const Replayed result = replayed(script("example", 1, kSteps));
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(result.verdict,
            "wrong.transcript:2: expected tx 701 [1] 05\n    but the slave sent 701 [1] 00");
  EXPECT_EQ(result.verdict, hostVerdict("example", 1, "\ntx 701 [1] 05"));
}

TEST(ReplayVerdict, NamesAFrameThatNeverCame) {
  static constexpr Step kSteps[] = {tx(1, frame(0x701, 1)), tx(2, frame(0x701, 1, 0x7F))};
  const Replayed result = replayed(script("example", 1, kSteps));
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(result.verdict,
            "wrong.transcript:2: expected tx 701 [1] 7F but the slave sent nothing");
  EXPECT_EQ(result.verdict, hostVerdict("example", 1, "tx 701 [1] 00\ntx 701 [1] 7F"));
}

TEST(ReplayVerdict, BreaksSilenceOnTheHeartbeat) {
  static constexpr Step kSteps[] = {
      tx(1, frame(0x701, 1)), rx(2, frame(0x601, 8, 0x2B, 0x17, 0x10, 0x00, 0xF4, 0x01)),
      tx(3, frame(0x581, 8, 0x60, 0x17, 0x10)), wait(4, 500), silence(5)};
  const Replayed result = replayed(script("example", 1, kSteps));
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(result.verdict, "wrong.transcript:5: expected silence but the slave sent 701 [1] 7F");
  EXPECT_EQ(result.verdict, hostVerdict("example", 1,
                                        "tx 701 [1] 00\n"
                                        "rx 601 [8] 2B 17 10 00 F4 01 00 00\n"
                                        "tx 581 [8] 60 17 10 00 00 00 00 00\n"
                                        "wait 500\n"
                                        "silence"));
  // The frame sent at 500 ms was recorded all the same; nothing was sent before it.
  EXPECT_EQ(
      texts(result.frames),
      (std::vector<std::string>{"701 [1] 00", "581 [8] 60 17 10 00 00 00 00 00", "701 [1] 7F"}));
}

TEST(ReplayVerdict, NamesAFrameAfterTheLastStep) {
  static constexpr Step kSteps[] = {wait(1, 1)};
  const Replayed result = replayed(script("solo", 5, kSteps));
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(result.verdict, "wrong.transcript: after the last step the slave also sent 705 [1] 00");
  EXPECT_EQ(result.verdict, hostVerdict("solo", 5, "wait 1"));
}

TEST(ReplayVerdict, SkipsIgnoredFramesAndMatchesWildcards) {
  // GRA node 2: boot-up, then the cyclic TPDO 0x182 every 100 ms, which the script ignores
  // except where a step waits for it.
  static constexpr uint32_t kIgnored[] = {0x182};
  static constexpr Step kSteps[] = {tx(1, frame(0x702, 1)),
                                    wait(2, 350),
                                    rx(3, frame(0x602, 8, 0x40, 0x00, 0x10)),
                                    tx(4, frame(0x582, 8, 0x43, 0x00, 0x10), 0xF0),
                                    wait(5, 50),
                                    tx(6, frame(0x182, 8, 0, 0, 0, 0, 0xFF), 0xE0)};
  const Replayed result = replayed(script("gra", 2, kSteps, kIgnored, 1));
  EXPECT_TRUE(result.passed) << result.verdict;
  EXPECT_EQ(result.frames.size(), 7U);  // boot-up, TPDO at 0..400 ms, SDO response
  const Replayed strict = replayed(script("gra", 2, kSteps));
  EXPECT_FALSE(strict.passed);
  EXPECT_EQ(strict.verdict,
            "wrong.transcript:4: expected tx 582 [8] 43 00 10 00 00 00 00 00\n"
            "    but the slave sent 182 [8] 00 00 00 00 FF FF FF 00");
}

TEST(ReplayVerdict, PassesOnTheSimulationsWordsWhenACommandIsRefused) {
  static constexpr Step kSteps[] = {tx(2, frame(0x703, 1)), sim(3, "angle ninety")};
  static constexpr uint32_t kIgnored[] = {0x183};
  const Replayed gra = replayed(script("gra", 3, kSteps, kIgnored, 1));
  EXPECT_FALSE(gra.passed);
  EXPECT_EQ(gra.verdict, "wrong.transcript:3: sim angle ninety: usage: angle DEGREES");
  EXPECT_EQ(gra.verdict, hostVerdict("gra", 3, "ignore 183\ntx 703 [1] 00\nsim angle ninety"));
  static constexpr Step kExampleSteps[] = {tx(1, frame(0x701, 1)), sim(2, "angle 90")};
  const Replayed example = replayed(script("example", 1, kExampleSteps));
  EXPECT_EQ(example.verdict,
            "wrong.transcript:2: sim angle 90: this device has no simulation commands");
  EXPECT_EQ(example.verdict, hostVerdict("example", 1, "tx 701 [1] 00\nsim angle 90"));
}

TEST(ReplayVerdict, FailsWhenTheRecorderWouldRefuseAFrame) {
  // 30 s of an unread cyclic TPDO every 100 ms: more frames than the recorder keeps unread.
  static constexpr Step kSteps[] = {wait(1, 30000)};
  const Replayed result = replayed(script("gra", 2, kSteps));
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(result.verdict,
            "wrong.transcript:1: the slave sent more than 256 frames that no step read (the "
            "replay's recorder is full)");
  EXPECT_EQ(result.frames.size(), replay::FrameRecorder::kCapacity);
}

/// A device whose process() follows a list of deadlines; it logs the times it is called at.
class ScriptedDeadlines final : public replay::ReplayDevice {
 public:
  explicit ScriptedDeadlines(std::vector<Microseconds> deadlines)
      : deadlines_(std::move(deadlines)) {}
  void start(Microseconds now) noexcept override {
    calls.push_back("start " + std::to_string(now));
  }
  Microseconds process(Microseconds now) noexcept override {
    calls.push_back("process " + std::to_string(now));
    if (next_ == deadlines_.size()) {
      return kNever;
    }
    return deadlines_[next_++];
  }
  std::vector<std::string> calls;

 private:
  std::vector<Microseconds> deadlines_;
  size_t next_ = 0;
};

TEST(VirtualBus, RunsEveryDeadlineOnTheWayAtItsTime) {
  ScriptedDeadlines device({100000, 100000, 200000, 400000});
  replay::FrameRecorder recorder;
  replay::VirtualBus bus(device, recorder, 0);
  ASSERT_TRUE(bus.powerOn());  // asks for 100 ms
  ASSERT_TRUE(bus.wait(250));  // 100 ms (asks for 100 ms again: immediate), 200 ms, then 250 ms
  EXPECT_EQ(bus.now(), 250000U);
  EXPECT_EQ(device.calls,
            (std::vector<std::string>{"start 0", "process 0", "process 100000", "process 100000",
                                      "process 200000", "process 250000"}));
}

TEST(VirtualBus, FailsOnADeadlineInThePast) {
  ScriptedDeadlines device({100000, 50000});
  replay::FrameRecorder recorder;
  replay::VirtualBus bus(device, recorder, 0);
  ASSERT_TRUE(bus.powerOn());
  EXPECT_FALSE(bus.wait(100));
  EXPECT_STREQ(bus.failure(),
               "process() asked to run again at 50000 us, not after now (100000 us)");
}

TEST(VirtualBus, FailsOnEndlessImmediateDeadlines) {
  ScriptedDeadlines device(std::vector<Microseconds>(1001, 0));
  replay::FrameRecorder recorder;
  replay::VirtualBus bus(device, recorder, 0);
  EXPECT_FALSE(bus.powerOn());
  EXPECT_STREQ(bus.failure(), "process() asked to run again at 0 us, not after now (0 us)");
  EXPECT_EQ(device.calls.size(), 1002U);  // start, then 1 + 1000 immediate runs
}

}  // namespace
}  // namespace costa::test
