// A classic CAN 2.0 frame as the stack and every port see it.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// One classic CAN frame. Plain data: copyable, no invariants enforced by the type itself.
/// The stack ignores frames whose `dlc` exceeds 8. The payload follows the identifier so that
/// it is 4-byte aligned: its two halves are words.
struct CanFrame {
  uint32_t id = 0;  ///< 11-bit identifier, or 29-bit when `extended`.
  /// Payload; bytes at and after `dlc` are zero in frames the stack builds.
  alignas(4) uint8_t data[8] = {};
  uint8_t dlc = 0;        ///< Data length code, 0..8.
  bool rtr = false;       ///< Remote transmission request.
  bool extended = false;  ///< 29-bit identifier.
};

/// Exact equality of everything that goes on the wire (id, format, RTR, DLC and the first `dlc`
/// bytes).
inline bool sameOnWire(const CanFrame& a, const CanFrame& b) noexcept {
  if (a.id != b.id || a.dlc != b.dlc || a.rtr != b.rtr || a.extended != b.extended) {
    return false;
  }
  if (a.rtr) {
    return true;
  }
  for (size_t i = 0; i < a.dlc && i < 8U; ++i) {
    if (a.data[i] != b.data[i]) {
      return false;
    }
  }
  return true;
}

}  // namespace costa
