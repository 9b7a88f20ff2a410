// One transcript replayed from scratch: its device built as costa-slave builds it, powered on
// at virtual time 0 on a fresh recorder, every step played, the device destroyed.
#pragma once

#include "fixed_text.hpp"
#include "frame_recorder.hpp"
#include "replay_script.hpp"

namespace costa::replay {

/// True when the slave did what `script` says; otherwise false with the mismatch in `verdict`.
/// `recorder` is reset first; its listener hears every frame the node sends.
bool replayScript(const Script& script, FrameRecorder& recorder, Text& verdict) noexcept;

}  // namespace costa::replay
