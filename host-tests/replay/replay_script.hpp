// A transcript as compiled data (host-tests/replay/transcripts_to_cpp.py writes the tables at
// build time): what the replayer plays on the host and on firmware, where there is no file
// system and no parser. Field for field what host-tests/support/transcript.hpp holds.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/can_frame.hpp"

namespace costa::replay {

enum class StepKind : uint8_t {
  kReceive,   ///< rx: a client frame to the slave
  kTransmit,  ///< tx: the slave must send this frame next
  kWait,      ///< wait: time passes
  kSilence,   ///< silence: the slave has sent nothing more so far
  kSimulate,  ///< sim: a command to the device's simulation
};

struct Step {
  StepKind kind;
  uint32_t line;          ///< line in the transcript file
  uint8_t wildcards;      ///< kTransmit: bit i set when data byte i is written `xx`
  CanFrame frame;         ///< kReceive, kTransmit
  uint64_t milliseconds;  ///< kWait
  const char* command;    ///< kSimulate: the command text; otherwise null
};

struct Script {
  const char* name;    ///< path below host-tests/transcripts, e.g. "example/sdo-aborts.transcript"
  const char* device;  ///< the `device` line: a name of the device list (targets/devices.hpp)
  uint8_t nodeId;
  const Step* steps;
  size_t stepCount;
  const uint32_t* ignored;  ///< CAN-IDs of `ignore` lines
  size_t ignoredCount;
};

/// The transcripts of one directory below host-tests/transcripts.
struct Suite {
  const char* name;  ///< the directory, e.g. "gefran"
  const Script* scripts;
  size_t scriptCount;
};

}  // namespace costa::replay
