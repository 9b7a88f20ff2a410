// The simulation commands of a device composition (costa-slave --control, a transcript's `sim`
// line, the firmware replayer, the fuzzer), as every composition offers them:
//
//   bool control(const char* command, char* why, size_t whySize) noexcept;
//
// true when the command was done; otherwise false with one line saying why in `why`, written
// like snprintf (at most whySize - 1 characters and a NUL; `why` may be null when whySize is 0).
// Freestanding: firmware replays transcripts with their commands.
#pragma once

#include <stddef.h>

namespace costa {

/// The answer of a device that has no simulation commands.
inline constexpr const char* kNoSimulationCommands = "this device has no simulation commands";

/// Writes `reason` into `why` as control() does; returns false, for control() to return.
inline bool refuseControl(const char* reason, char* why, size_t whySize) noexcept {
  if (why == nullptr || whySize == 0U) {
    return false;
  }
  size_t length = 0;
  for (; reason[length] != '\0' && length + 1U < whySize; ++length) {
    why[length] = reason[length];
  }
  why[length] = '\0';
  return false;
}

}  // namespace costa
