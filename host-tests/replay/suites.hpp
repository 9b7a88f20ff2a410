// The generated transcript tables: one suite per directory below host-tests/transcripts
// (CMakeLists.txt, costa_add_transcript_suite).
#pragma once

#include "replay_script.hpp"

namespace costa::replay {

extern const Suite kExampleSuite;
extern const Suite kSoloSuite;
extern const Suite kGefranSuite;

}  // namespace costa::replay
