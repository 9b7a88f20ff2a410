// How a device watches and is watched (node guarding, heartbeat consumer, controller events:
// ErrorControl). Every field defaults to CiA 301.
#pragma once

#include <stdint.h>

#include "costa/profile_choice.hpp"

namespace costa {

struct ErrorControlProfile {
  // Member names, also where COSTA_PROFILE_CHOICE makes the fields constants.
  // NOLINTBEGIN(readability-identifier-naming)
  /// The device answers node guarding (a remote request on 0x700 + node-id, CiA 301
  /// 7.2.8.3.2.1). false: a device with heartbeat only; such remote requests are ignored (and
  /// counted).
  COSTA_PROFILE_CHOICE bool nodeGuarding = true;
  /// Toggle bit of the first node-guarding reply after a reset communication (CiA 301: 0).
  COSTA_PROFILE_CHOICE uint8_t guardToggleStart = 0;
  /// The node reports life-guarding and heartbeat-consumer errors with EMCY 0x8130 itself; when
  /// false only the listeners hear of them and the device reports them its own way.
  COSTA_PROFILE_CHOICE bool emcyForErrors = true;
  /// The error behaviour (0x1029:01's values) of a device without object 0x1029: CiA 301's
  /// default 0 (operational -> pre-operational on a communication error); 1 keeps the NMT state.
  COSTA_PROFILE_CHOICE uint8_t errorBehaviourWithoutObject = 0;
  /// What a heartbeat carries while the error register (0x1001) is not 0: 0 (CiA 301) the NMT
  /// state as always; otherwise this byte (a device that shows an alarm in its heartbeat), the
  /// NMT state itself unchanged.
  COSTA_PROFILE_CHOICE uint8_t heartbeatWhileError = 0;
  // NOLINTEND(readability-identifier-naming)
};

}  // namespace costa
