#include "transcript_player.hpp"

#include <chrono>

#include "frame_text.hpp"

namespace costa::test {
namespace {

bool ignored(const Transcript& transcript, const CanFrame& frame) {
  for (const uint32_t id : transcript.ignored) {
    if (!frame.extended && frame.id == id) {
      return true;
    }
  }
  return false;
}

/// The next frame that is not ignored; false when none (within about `timeoutMs` in total).
bool nextFrame(const Transcript& transcript, TranscriptBus& bus, CanFrame* frame, int timeoutMs) {
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
  while (bus.receive(frame, timeoutMs)) {
    if (!ignored(transcript, *frame)) {
      return true;
    }
    if (timeoutMs > 0 && std::chrono::steady_clock::now() > giveUp) {
      return false;
    }
  }
  return false;
}

}  // namespace

std::string playTranscript(const Transcript& transcript, TranscriptBus& bus, int receiveTimeoutMs) {
  const auto where = [&](const TranscriptStep& step) {
    return transcript.path + ":" + std::to_string(step.line) + ": ";
  };
  for (const TranscriptStep& step : transcript.steps) {
    switch (step.kind) {
      case TranscriptStep::Kind::kReceive: bus.send(step.frame); break;
      case TranscriptStep::Kind::kTransmit: {
        CanFrame actual;
        // Ignored frames may keep coming (a cyclic TPDO): give up after the timeout in total.
        const auto giveUp =
            std::chrono::steady_clock::now() + std::chrono::milliseconds(receiveTimeoutMs);
        for (;;) {
          if ((receiveTimeoutMs > 0 && std::chrono::steady_clock::now() > giveUp) ||
              !bus.receive(&actual, receiveTimeoutMs)) {
            return where(step) + "expected tx " + host::formatFrame(step.frame) +
                   " but the slave sent nothing";
          }
          if (host::matchesFrame(step.frame, step.wildcards, actual)) {
            break;
          }
          if (!ignored(transcript, actual)) {
            return where(step) + "expected tx " + host::formatFrame(step.frame) +
                   "\n    but the slave sent " + host::formatFrame(actual);
          }
        }
        break;
      }
      case TranscriptStep::Kind::kSimulate: {
        const std::string result = bus.simulate(step.text);
        if (!result.empty()) {
          return where(step) + "sim " + step.text + ": " + result;
        }
        break;
      }
      case TranscriptStep::Kind::kWait: bus.wait(step.milliseconds); break;
      case TranscriptStep::Kind::kSilence: {
        CanFrame extra;
        if (bus.checksTiming() && nextFrame(transcript, bus, &extra, 0)) {
          return where(step) + "expected silence but the slave sent " + host::formatFrame(extra);
        }
        break;
      }
    }
  }
  CanFrame extra;
  if (nextFrame(transcript, bus, &extra, bus.checksTiming() ? 0 : 100)) {
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
