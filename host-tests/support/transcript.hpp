// Transcripts: frame exchanges written as text, replayed against a node in-process, through
// SocketCAN against costa-slave, and on the firmware build (compiled into tables by
// host-tests/replay/transcripts_to_cpp.py, which follows this parser's rules).
//
//   # comment (also after a step)
//   device example          which device the slave runs
//   node-id 1               its node-id
//   tx 701 [1] 00           the slave must send this frame next (xx = any byte)
//   rx 601 [8] 40 08 10 00 00 00 00 00
//                           a client sends this frame to the slave
//   wait 1000               1000 ms pass (virtual time in-process, real time over SocketCAN)
//   silence                 the slave has sent nothing more so far (checked in-process only:
//                           over SocketCAN, timing is not asserted)
//   sim raw 12288 12288     a command to the device's simulation (its composition's control();
//                           over SocketCAN through costa-slave --control)
//   ignore 1FF              frames on this CAN-ID (one per line) that no `tx` step is waiting
//                           for are skipped, by `silence` and the end check too (periodic
//                           frames the transcript does not follow): a transcript cannot show
//                           that such a frame is absent
//
// Every frame the slave sends must be matched by a `tx` line, in order.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include "costa/port/can_frame.hpp"

namespace costa::test {

struct TranscriptStep {
  enum class Kind { kReceive, kTransmit, kWait, kSilence, kSimulate };
  Kind kind = Kind::kSilence;
  CanFrame frame;
  unsigned wildcards = 0;  ///< Data bytes written `xx` (kTransmit).
  uint64_t milliseconds = 0;
  int line = 0;
  std::string text;  ///< The step as written.
};

struct Transcript {
  std::string path;
  std::string device;
  int nodeId = 1;
  std::vector<TranscriptStep> steps;
  std::vector<uint32_t> ignored;  ///< CAN-IDs of `ignore` lines
};

/// Parses a transcript file. On error returns false with "path:line: message" in `error`.
bool loadTranscript(const std::string& path, Transcript* transcript, std::string* error);
bool parseTranscript(const std::string& text, const std::string& path, Transcript* transcript,
                     std::string* error);

/// All *.transcript files below `directory`, sorted.
std::vector<std::string> findTranscripts(const std::string& directory);

}  // namespace costa::test
