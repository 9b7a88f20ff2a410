// An acceptance filter for standard (11-bit) CAN frames, as a controller's filter banks take
// them: a frame passes when its identifier agrees with `id` in every bit set in `mask`.
//
// The node lists the filters it needs (Node::receiveFilters()); a port programs them into its
// controller's filter banks so that frames nobody listens to never reach the receive FIFO.
#pragma once

#include <stdint.h>

namespace costa {

struct CanIdFilter {
  static constexpr uint16_t kExact = 0x7FF;  ///< mask: every identifier bit must agree

  uint16_t id = 0;
  uint16_t mask = kExact;

  /// A standard data or remote frame with identifier `canId` passes.
  constexpr bool accepts(uint32_t canId) const noexcept {
    return canId <= 0x7FFU && ((canId ^ id) & mask) == 0U;
  }
};

}  // namespace costa
