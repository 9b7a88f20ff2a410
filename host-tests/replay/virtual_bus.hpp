// A device on a virtual clock (virtual_clock.hpp), the clock of the host tests' InProcessBus
// too, so that a replay here sends what a replay there sends, frame for frame.
#pragma once

#include <stdint.h>

#include "costa/time.hpp"
#include "fixed_text.hpp"
#include "frame_recorder.hpp"
#include "replay_device.hpp"
#include "virtual_clock.hpp"

namespace costa::replay {

class VirtualBus {
 public:
  /// One second before the 32-bit microsecond clock wraps: every replay longer than a second
  /// crosses the wrap, which the node must not notice.
  static constexpr Microseconds kPowerOnTime = 0xFFFFFFFFU - 999999U;

  VirtualBus(ReplayDevice& device, FrameRecorder& recorder,
             Microseconds powerOnTime = kPowerOnTime) noexcept
      : device_(device), recorder_(recorder), clock_(powerOnTime) {}

  // Each returns false when the replay cannot go on; failure() then says why.
  bool powerOn() noexcept;
  bool send(const CanFrame& frame) noexcept;
  bool wait(uint64_t milliseconds) noexcept;
  /// A `sim` command to the device (which runs what it changes itself, as costa-slave's control
  /// does: no process() loop here). False with the device's reason in `why` when it refuses.
  bool simulate(const char* command, Text& why) noexcept;

  /// The next frame the slave sent that has not been read; false when none.
  bool receive(CanFrame* frame) noexcept { return recorder_.next(frame); }

  Microseconds now() const noexcept { return clock_.now(); }
  const char* failure() const noexcept { return failure_.c_str(); }

 private:
  /// Calls process() now, again while it asks for an immediate call.
  bool runProcess() noexcept;
  /// The device's process(), then whether the recorder kept up (a full recorder ends the loop).
  auto processAndRecord() noexcept {
    return [this](Microseconds now) {
      const Microseconds next = device_.process(now);
      return recorder_.overflowed() ? kNever : next;
    };
  }
  /// True for a clean outcome; else false with the failure.
  bool checked(VirtualClock::Outcome outcome) noexcept;
  /// False with a failure when the recorder had to refuse a frame.
  bool recorderKeptUp() noexcept;

  ReplayDevice& device_;
  FrameRecorder& recorder_;
  VirtualClock clock_;
  FixedText<96> failure_;
};

}  // namespace costa::replay
