// The CAN controller's bit rate as the stack may change it: LSS "activate bit timing" (CiA 305)
// and a bit timing that becomes active at reset communication.
#pragma once

#include <stdint.h>

namespace costa {

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
