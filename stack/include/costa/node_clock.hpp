// The node's notion of time: the timestamp of the call being handled, and the earliest time at
// which something may be due.
#pragma once

#include "costa/hot_path.hpp"
#include "costa/time.hpp"

namespace costa {

/// Advanced by the node at the start of every start()/onFrame()/process() call; read by services
/// that react to dictionary writes (which carry no timestamp of their own). Every service that
/// sets a deadline outside its process() (a frame, a write, an application call) calls
/// schedule() with it, so that Node::process() can return at once while nothing is due.
/// `next` is a lower bound: process() recomputes it exactly whenever it reaches it.
struct NodeClock {
  Microseconds now = 0;
  Microseconds next = kNever;

  /// The time of power-on: the clock starts there, whatever its previous value.
  void start(Microseconds time) noexcept { now = time; }
  /// The time of the call being handled; a time earlier than the last one (a caller whose
  /// clock went back) leaves it as it is.
  void advance(Microseconds time) noexcept {
    if (before(now, time)) {
      now = time;
    }
  }
  /// Something may be due at `deadline` (kNever: nothing). O(1).
  COSTA_SHARED_INLINE void schedule(Microseconds deadline) noexcept {
    next = earliest(next, deadline);
  }
  /// Something is due at once (atOnce(now): at the instant whose value is kNever's too).
  COSTA_SHARED_INLINE void scheduleNow() noexcept { schedule(atOnce(now)); }
  /// True when `next` has come: process() has work.
  bool due() const noexcept { return reached(now, next); }
};

}  // namespace costa
