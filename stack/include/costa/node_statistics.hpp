// Counters of events that are nobody's fault but worth seeing (Node::statistics()).
#pragma once

#include <stdint.h>

namespace costa {

/// Every counter counts since construction and saturates at UINT32_MAX only in theory.
struct NodeStatistics {
  uint32_t framesIgnored = 0;  ///< Frames addressed to nobody here, or malformed.
  uint32_t txRefused = 0;      ///< Times the controller refused a frame (kept and offered again).
  uint32_t txDropped = 0;      ///< Frames lost to a full transmit queue.
  uint32_t txExpired = 0;      ///< Synchronous PDOs that missed their SYNC window in the queue.
  uint32_t txDiscarded = 0;    ///< Queued frames discarded by a reset communication.
  uint32_t rxOverruns = 0;     ///< Overruns reported by the controller.
  uint32_t busOffs = 0;
  uint32_t emcyLost = 0;              ///< EMCY frames lost to a full EMCY queue.
  uint32_t emcyConditionsFull = 0;    ///< Errors raised while the condition table was full.
  uint32_t rpdosRefused = 0;          ///< RPDOs not written because an entry was refused.
  uint32_t unresolvableMappings = 0;  ///< PDO mappings that could not be resolved (PDO empty).
  uint32_t hooksRefused = 0;          ///< attachHook() calls refused: hook table full.
  uint32_t listenersRefused = 0;      ///< addListener() calls refused: listener table full.
  uint32_t timeFramesIgnored = 0;     ///< TIME frames not 6 bytes long, or past midnight.
  uint32_t emcyFramesIgnored = 0;     ///< Consumed EMCY frames not 8 bytes long, or RTR.
};

}  // namespace costa
