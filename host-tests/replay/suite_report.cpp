#include "suite_report.hpp"

#include "fixed_text.hpp"
#include "frame_recorder.hpp"
#include "script_replay.hpp"

namespace costa::replay {
namespace {

/// Writes "tx <frame>" for every frame the node sends.
class SentFrameLines final : public FrameListener {
 public:
  void onSent(const CanFrame& frame) noexcept override {
    if (output_ == nullptr) {
      return;
    }
    FixedText<48> line;
    line.append("tx ").appendFrame(frame).append("\n");
    output_->write(line.c_str());
  }
  void setOutput(ReportOutput* output) noexcept { output_ = output; }

 private:
  ReportOutput* output_ = nullptr;
};

// In static storage: the recorder's frames would crowd a firmware stack.
SentFrameLines sentFrameLines;
FrameRecorder recorder(&sentFrameLines);

}  // namespace

SuiteResult replaySuite(const Suite& suite, ReportOutput& output) noexcept {
  sentFrameLines.setOutput(&output);
  SuiteResult result;
  for (size_t i = 0; i < suite.scriptCount; ++i) {
    const Script& script = suite.scripts[i];
    FixedText<128> heading;
    heading.append("transcript ").append(script.name).append(" (device ");
    heading.append(script.device).append(", node-id ");
    heading.appendDecimal(script.nodeId).append(")\n");
    output.write(heading.c_str());
    FixedText<320> verdict;
    if (replayScript(script, recorder, verdict)) {
      ++result.passed;
      output.write("PASS\n");
    } else {
      ++result.failed;
      output.write("FAIL ");
      output.write(verdict.c_str());
      output.write("\n");
    }
  }
  sentFrameLines.setOutput(nullptr);
  FixedText<96> summary;
  summary.append("suite ").append(suite.name).append(": ").appendDecimal(result.passed);
  summary.append(" of ").appendDecimal(suite.scriptCount).append(" transcripts passed\n");
  output.write(summary.c_str());
  return result;
}

}  // namespace costa::replay
