// The generated transcript tables: one suite per directory below host-tests/transcripts
// (CMakeLists.txt, costa_add_transcript_suite), and the table of them all (costa_replay_suites).
#pragma once

#include <stddef.h>

#include "replay_script.hpp"

namespace costa::replay {

/// Every suite, sorted by name.
extern const Suite* const kSuites[];
extern const size_t kSuiteCount;

/// The suite of the directory `name`; null when there is none.
const Suite* findSuite(const char* name) noexcept;

}  // namespace costa::replay
