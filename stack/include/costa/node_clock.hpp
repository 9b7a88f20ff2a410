// The node's notion of time: the timestamp of the call being handled, and the earliest time at
// which something may be due.
#pragma once

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

  void advance(Microseconds time) noexcept {
    if (time > now) {
      now = time;
    }
  }
  /// Something may be due at `at` (kNever: nothing). O(1).
  void schedule(Microseconds at) noexcept {
    if (at < next) {
      next = at;
    }
  }
};

}  // namespace costa
