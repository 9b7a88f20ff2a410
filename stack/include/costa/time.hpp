// Time as the stack sees it: a free-running 32-bit microsecond counter passed in by the caller.
//
// The counter wraps every 2^32 µs (71 min 35 s), as a hardware timer does; the stack compares
// times only through the functions below, which are right across the wrap as long as the two
// times are less than 2^31 µs (35 min 47 s) apart. Every deadline the stack keeps is closer
// than that to the time it was set at; the few CiA 301 periods that may be longer (the SYNC
// period 0x1006, a node guarding life time) are kept by LongTimer.
#pragma once

#include <stdint.h>

namespace costa {

/// Microseconds of a monotonic clock chosen by the caller, modulo 2^32.
using Microseconds = uint32_t;

/// "No deadline": returned when nothing is scheduled. No deadline the stack sets has this value
/// (at() skips it).
inline constexpr Microseconds kNever = UINT32_MAX;

/// The longest delay between two times that the comparisons below order correctly.
inline constexpr uint32_t kLongestDelay = 0x7FFFFFFFU;

inline constexpr Microseconds millisecondsToMicroseconds(uint32_t ms) noexcept {
  return ms * 1000U;
}

/// Unit of inhibit times (0x1015, PDO sub-index 3).
inline constexpr Microseconds kHundredMicroseconds = 100;

/// The deadline `delay` after `now` (delay <= kLongestDelay); never kNever.
inline constexpr Microseconds at(Microseconds now, uint32_t delay) noexcept {
  const Microseconds deadline = now + delay;
  return deadline == kNever ? 0U : deadline;
}

/// The deadline "at once" at `now`: `now` itself, or 1 µs earlier at the one instant that
/// has kNever's value (kNever is no deadline), so that work scheduled then is due, not never.
inline constexpr Microseconds atOnce(Microseconds now) noexcept {
  return now == kNever ? now - 1U : now;
}

/// True when `deadline` (not kNever) has come at `now`.
inline constexpr bool reached(Microseconds now, Microseconds deadline) noexcept {
  return deadline != kNever && static_cast<int32_t>(now - deadline) >= 0;
}

/// True when `a` is earlier than `b` (both real times, not kNever).
inline constexpr bool before(Microseconds a, Microseconds b) noexcept {
  return static_cast<int32_t>(a - b) < 0;
}

/// The earlier of two deadlines; kNever is later than any time.
inline constexpr Microseconds earliest(Microseconds a, Microseconds b) noexcept {
  if (a == kNever) {
    return b;
  }
  return b == kNever || !before(b, a) ? a : b;
}

/// A deadline that may lie further ahead than kLongestDelay (up to 2^32 - 1 µs times 2^16): it
/// waits in steps of at most kLongestDelay. next() is the step's end, which is what a clock
/// schedules; when process() says the step ended, the timer either fired or took its next step.
class LongTimer {
 public:
  /// Armed to fire `delay` µs after `now`.
  void start(Microseconds now, uint64_t delay) noexcept {
    remaining_ = delay;
    step(now);
  }
  void stop() noexcept { next_ = kNever; }
  bool running() const noexcept { return next_ != kNever; }
  Microseconds next() const noexcept { return next_; }
  /// True once when the whole delay has passed at `now` (the timer stops then; due() tells
  /// when it was due).
  bool fired(Microseconds now) noexcept {
    if (!reached(now, next_)) {
      return false;
    }
    if (remaining_ == 0U) {
      due_ = next_;
      next_ = kNever;
      return true;
    }
    step(next_);
    return false;
  }
  /// When the delay that last fired was over.
  Microseconds due() const noexcept { return due_; }

 private:
  void step(Microseconds from) noexcept {
    const uint64_t part = remaining_ < kLongestDelay ? remaining_ : kLongestDelay;
    remaining_ -= part;
    next_ = at(from, static_cast<uint32_t>(part));
  }

  Microseconds next_ = kNever;
  Microseconds due_ = 0;
  uint64_t remaining_ = 0;
};

}  // namespace costa
