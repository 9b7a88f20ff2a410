// Replays a transcript against a slave reached through a TranscriptBus.
#pragma once

#include <stdint.h>

#include <string>

#include "costa/port/can_frame.hpp"
#include "transcript.hpp"

namespace costa::test {

/// The slave as a transcript sees it.
class TranscriptBus {
 public:
  virtual ~TranscriptBus() = default;
  /// A client frame to the slave.
  virtual void send(const CanFrame& frame) = 0;
  /// The next frame the slave sent; waits up to `timeoutMs` where time is real. False if none.
  virtual bool receive(CanFrame* frame, int timeoutMs) = 0;
  /// Lets `milliseconds` pass.
  virtual void wait(uint64_t milliseconds) = 0;
  /// Whether `silence` steps are checked (virtual time only).
  virtual bool checksTiming() const = 0;
  /// A command to the device's simulation; "" when done, else why not.
  virtual std::string simulate(const std::string& command) = 0;
};

/// Plays every step. Returns "" on success, else a report naming the step's line, the expected
/// and the actual frames.
std::string playTranscript(const Transcript& transcript, TranscriptBus& bus,
                           int receiveTimeoutMs = 0);

/// Parses `text` (transcript syntax, `device` line optional) and plays it.
std::string playText(const std::string& text, TranscriptBus& bus, int receiveTimeoutMs = 0);

}  // namespace costa::test
