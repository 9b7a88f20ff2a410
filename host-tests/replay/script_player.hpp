// Plays a compiled transcript against a device on a VirtualBus and judges it exactly as the
// host's transcript player does (host-tests/support/transcript_player.cpp, virtual time):
//   tx       the next frame that matches, `xx` bytes being any; frames on `ignore` CAN-IDs
//            that do not match are skipped, any other frame is a mismatch
//   silence  no frame (other than ignored ones) since the last step
//   after the last step, no frame other than ignored ones
// Mismatch messages are the host's, with the script's name for the path.
#pragma once

#include "fixed_text.hpp"
#include "replay_script.hpp"
#include "virtual_bus.hpp"

namespace costa::replay {

/// Powers the device on and plays every step. True when the slave did what the script says;
/// otherwise false with "NAME:LINE: what happened" in `verdict`.
bool playScript(const Script& script, VirtualBus& bus, Text& verdict) noexcept;

}  // namespace costa::replay
