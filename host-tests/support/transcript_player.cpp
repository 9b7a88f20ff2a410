#include "transcript_player.hpp"

#include "frame_text.hpp"

namespace costa::test {

std::string playTranscript(const Transcript& transcript, TranscriptBus& bus, int receiveTimeoutMs) {
  const auto where = [&](const TranscriptStep& step) {
    return transcript.path + ":" + std::to_string(step.line) + ": ";
  };
  for (const TranscriptStep& step : transcript.steps) {
    switch (step.kind) {
      case TranscriptStep::Kind::kReceive: bus.send(step.frame); break;
      case TranscriptStep::Kind::kTransmit: {
        CanFrame actual;
        if (!bus.receive(&actual, receiveTimeoutMs)) {
          return where(step) + "expected tx " + host::formatFrame(step.frame) +
                 " but the slave sent nothing";
        }
        if (!host::matchesFrame(step.frame, step.wildcards, actual)) {
          return where(step) + "expected tx " + host::formatFrame(step.frame) +
                 "\n    but the slave sent " + host::formatFrame(actual);
        }
        break;
      }
      case TranscriptStep::Kind::kWait: bus.wait(step.milliseconds); break;
      case TranscriptStep::Kind::kSilence: {
        CanFrame extra;
        if (bus.checksTiming() && bus.receive(&extra, 0)) {
          return where(step) + "expected silence but the slave sent " + host::formatFrame(extra);
        }
        break;
      }
    }
  }
  CanFrame extra;
  if (bus.receive(&extra, bus.checksTiming() ? 0 : 100)) {
    return transcript.path + ": after the last step the slave also sent " +
           host::formatFrame(extra);
  }
  return "";
}

std::string playText(const std::string& text, TranscriptBus& bus, int receiveTimeoutMs) {
  Transcript transcript;
  std::string error;
  // The device line goes last so that line numbers in reports match `text`.
  if (!parseTranscript(text + "\ndevice inline\n", "<inline>", &transcript, &error)) {
    return error;
  }
  return playTranscript(transcript, bus, receiveTimeoutMs);
}

}  // namespace costa::test
