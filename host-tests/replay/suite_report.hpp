// The replay report of a suite: the same text from the host replayer and from the firmware
// images under QEMU, compared byte for byte by tools/firmware-replay.
//
//   transcript example/heartbeat-and-nmt.transcript (device example, node-id 1)
//   tx 701 [1] 00                        every frame the node sent, in order
//   tx 581 [8] 60 17 10 00 00 00 00 00
//   PASS                                 or "FAIL " and the mismatch (host transcript player's
//   words)
//   ...
//   suite example: 6 of 6 transcripts passed
#pragma once

#include <stddef.h>

#include "replay_script.hpp"

namespace costa::replay {

/// Where the report goes (stdout on the host, semihosting on firmware).
class ReportOutput {
 public:
  virtual void write(const char* text) noexcept { (void)text; }

 protected:
  ReportOutput() = default;
  ~ReportOutput() = default;
  ReportOutput(const ReportOutput&) = default;
  ReportOutput& operator=(const ReportOutput&) = default;
};

struct SuiteResult {
  size_t passed = 0;
  size_t failed = 0;
};

/// Replays every script of `suite` in order and writes the report to `output`.
SuiteResult replaySuite(const Suite& suite, ReportOutput& output) noexcept;

}  // namespace costa::replay
