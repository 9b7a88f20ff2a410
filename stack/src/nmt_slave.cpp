#include "costa/nmt_slave.hpp"

namespace costa {

const char* describe(NmtState state) noexcept {
  switch (state) {
    case NmtState::kInitialising: return "initialising";
    case NmtState::kStopped: return "stopped";
    case NmtState::kOperational: return "operational";
    case NmtState::kPreOperational: return "pre-operational";
  }
  return "unknown";
}

}  // namespace costa
