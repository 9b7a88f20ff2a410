// The CAN controller's bit rate as the stack may change it: LSS "activate bit timing" (CiA 305)
// and a bit timing that becomes active at reset communication; and the CiA 305 standard bit
// timing table, the one mapping between table entries and bit rates in Costa (LSS, drivers).
#pragma once

#include <stdint.h>

namespace costa {

/// Bit rate of an entry of the CiA 305 standard bit timing table, in bit/s; 0 for index 5
/// (reserved) and for indices beyond 8 (9 is automatic bit rate detection).
constexpr uint32_t cia305BitRate(uint8_t tableIndex) noexcept {
  switch (tableIndex) {
    case 0: return 1000000;
    case 1: return 800000;
    case 2: return 500000;
    case 3: return 250000;
    case 4: return 125000;
    case 6: return 50000;
    case 7: return 20000;
    case 8: return 10000;
    default: return 0;
  }
}

/// Index of `bitsPerSecond` in the CiA 305 standard table, or -1 when the table has no entry
/// with that rate.
constexpr int cia305TableIndex(uint32_t bitsPerSecond) noexcept {
  for (uint8_t index = 0; index <= 8U; ++index) {
    if (bitsPerSecond != 0U && cia305BitRate(index) == bitsPerSecond) {
      return index;
    }
  }
  return -1;
}

static_assert(cia305TableIndex(500000) == 2);
static_assert(cia305TableIndex(10000) == 8);
static_assert(cia305TableIndex(0) == -1);
static_assert(cia305TableIndex(100000) == -1);

/// Re-times a CAN controller.
///
/// Implemented by a port whose controller can change its bit rate; given to the node through
/// NodeSettings::bitRateControl. Called only from the context that runs the stack (main loop),
/// at moments when the node sends nothing: during the LSS bit timing switch (after the first
/// switch delay, before the second) and during reset communication, before the boot-up frame.
class CanBitRateControl {
 public:
  CanBitRateControl(const CanBitRateControl&) = delete;
  CanBitRateControl& operator=(const CanBitRateControl&) = delete;

  /// Switches the controller to `bitsPerSecond` (a CiA 305 table rate: 1000000, 800000, 500000,
  /// 250000, 125000, 50000, 20000 or 10000). Returns true when the controller now runs at that
  /// rate, false when it cannot (unknown clock, a rate it cannot produce, no acknowledge) and
  /// still runs at the rate it had. Frames the controller already holds may leave at the new
  /// rate. Must not allocate; may wait, bounded, for the controller to change mode.
  /// The default switches nothing. (Port interfaces have no pure virtual functions, so that a
  /// firmware image needs nothing from the C++ runtime library.)
  virtual bool setBitRate(uint32_t bitsPerSecond) noexcept {
    (void)bitsPerSecond;
    return false;
  }

 protected:
  CanBitRateControl() = default;
  ~CanBitRateControl() = default;
};

}  // namespace costa
