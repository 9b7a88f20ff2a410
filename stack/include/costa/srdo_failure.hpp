// Why the safety service (CiA 304) put the node in its safe state.
#pragma once

#include <stdint.h>

namespace costa {

enum class SrdoFailure : uint8_t {
  kNone = 0,
  kCycleTime = 1,             ///< no new pair within SCT (a late or missing normal frame)
  kValidationTime = 2,        ///< the inverted frame did not follow within SRVT
  kNotInverted = 3,           ///< the inverted data is not the bitwise NOT of the normal data
  kSequence = 4,              ///< a normal frame where the inverted one was due, or the reverse
  kLength = 5,                ///< a frame whose length is not the mapping's
  kSignature = 6,             ///< entering operational: a signature (0x13FF) does not match
  kConfigurationChanged = 7,  ///< an SRDO's configuration changed while operational
  kGlobalFailSafe = 8,        ///< a global fail-safe command (GFC) was received
};

}  // namespace costa
