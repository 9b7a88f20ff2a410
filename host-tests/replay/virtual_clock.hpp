// The virtual clock every in-process bus of the tests drives a node with (the transcript
// replayer here, the unit tests' buses in host-tests/support), so that they all run a node with
// the same time semantics:
//   power on:  start(now), then process() until it asks for a later time
//   send:      onFrame(frame, now), then the same process() loop
//   wait:      every deadline on the way is run at its own time, then process() at the end
// process() may ask for an immediate call again (a deadline equal to now) up to
// kImmediateRunsAllowed times in a row; a deadline in the past, or more immediate calls, are a
// failure of the node. Times are compared as the stack compares them (costa/time.hpp), so a
// clock that starts just before the 32-bit wrap runs any test across it. Freestanding.
#pragma once

#include <stdint.h>

#include "costa/time.hpp"

namespace costa::replay {

class VirtualClock {
 public:
  static constexpr int kImmediateRunsAllowed = 1000;

  enum class Outcome : uint8_t {
    kOk,
    kPast,     ///< process() asked for a time before now (failedDeadline())
    kEndless,  ///< process() kept asking for an immediate call
  };

  explicit VirtualClock(Microseconds start) noexcept : now_(start) {}

  Microseconds now() const noexcept { return now_; }
  /// The deadline process() returned when it failed.
  Microseconds failedDeadline() const noexcept { return next_; }

  /// Calls process(now) now, again while it asks for an immediate call.
  template <typename Process>
  Outcome runProcess(Process&& process) {
    for (int run = 0;; ++run) {
      next_ = process(now_);
      if (next_ == kNever || before(now_, next_)) {
        return Outcome::kOk;
      }
      if (next_ != atOnce(now_)) {
        return Outcome::kPast;
      }
      if (run == kImmediateRunsAllowed) {
        return Outcome::kEndless;
      }
    }
  }

  /// Advances by `microseconds`, running process() at every deadline on the way and at the end.
  template <typename Process>
  Outcome advance(Microseconds microseconds, Process&& process) {
    const Microseconds end = now_ + microseconds;
    while (next_ != kNever && !before(end, next_)) {
      if (before(now_, next_)) {
        now_ = next_;
      }
      const Outcome outcome = runProcess(process);
      if (outcome != Outcome::kOk) {
        return outcome;
      }
    }
    now_ = end;
    return runProcess(process);
  }

 private:
  Microseconds now_;
  Microseconds next_ = kNever;
};

}  // namespace costa::replay
