// A device on a virtual clock, with exactly the time semantics of the host tests' InProcessBus
// (host-tests/support/in_process_bus.cpp), so that a replay here sends what a replay there
// sends, frame for frame:
//   power on:  start(0), then process() until it asks for a later time
//   send:      onFrame(frame, now), then the same process() loop
//   wait:      every deadline on the way is run at its own time, then process() at the end
// process() may ask for an immediate call again (a deadline equal to now) up to 1000 times in
// a row; a deadline in the past, or more immediate calls, fail the replay.
#pragma once

#include <stdint.h>

#include "costa/time.hpp"
#include "fixed_text.hpp"
#include "frame_recorder.hpp"
#include "replay_device.hpp"

namespace costa::replay {

class VirtualBus {
 public:
  VirtualBus(ReplayDevice& device, FrameRecorder& recorder) noexcept
      : device_(device), recorder_(recorder) {}

  // Each returns false when the replay cannot go on; failure() then says why.
  bool powerOn() noexcept;
  bool send(const CanFrame& frame) noexcept;
  bool wait(uint64_t milliseconds) noexcept;
  /// A `sim` command to the device (which runs what it changes itself, as costa-slave's control
  /// does: no process() loop here). False with the device's reason in `why` when it refuses.
  bool simulate(const char* command, Text& why) noexcept;

  /// The next frame the slave sent that has not been read; false when none.
  bool receive(CanFrame* frame) noexcept { return recorder_.next(frame); }

  Microseconds now() const noexcept { return now_; }
  const char* failure() const noexcept { return failure_.c_str(); }

 private:
  /// Calls process() now, again while it asks for an immediate call.
  bool runProcess() noexcept;
  /// Advances virtual time by `microseconds`, running every deadline on the way.
  bool advance(Microseconds microseconds) noexcept;
  /// False with a failure when the recorder had to refuse a frame.
  bool recorderKeptUp() noexcept;

  ReplayDevice& device_;
  FrameRecorder& recorder_;
  Microseconds now_ = 0;
  Microseconds nextDeadline_ = 0;
  FixedText<96> failure_;
};

}  // namespace costa::replay
