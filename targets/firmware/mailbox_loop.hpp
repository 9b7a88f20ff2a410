// The main loop of an image on the mailbox stand-in controller (dummy_can.hpp): frames from the
// mailbox to the device, then the device's timers; the mailbox's tick count is the clock.
#pragma once

#include "costa/time.hpp"
#include "dummy_can.hpp"

namespace costa::firmware {

/// Starts `target` (a device composition: start, onFrame, process) and runs it for ever.
template <typename Target>
[[noreturn]] void runOnMailbox(Target& target, DummyCan& can, Mailbox& mailbox) noexcept {
  target.start(static_cast<Microseconds>(mailbox.ticks) * 1000U);
  for (;;) {
    const Microseconds now = static_cast<Microseconds>(mailbox.ticks) * 1000U;
    CanFrame frame;
    while (can.receive(&frame)) {
      target.onFrame(frame, now);
    }
    target.process(now);
  }
}

}  // namespace costa::firmware
