// The node's notion of "now": the timestamp of the call being handled.
#pragma once

#include "costa/time.hpp"

namespace costa {

/// Updated by the node at the start of every onFrame()/process() call, read by services that
/// react to dictionary writes (which carry no timestamp of their own).
struct NodeClock {
  Microseconds now = 0;
};

}  // namespace costa
