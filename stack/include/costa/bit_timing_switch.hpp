// The bit timing a node runs with, the one it is to run with after the next reset
// communication, and the switch between them through the port's CanBitRateControl.
//
// Context: the one that runs the node. No allocation; every call O(1) plus the controller's
// setBitRate().
#pragma once

#include "costa/lss_bit_timing.hpp"
#include "costa/port/can_bit_rate.hpp"

namespace costa {

class BitTimingSwitch {
 public:
  /// `control` may be null: the node then only records the timing in use.
  BitTimingSwitch(CanBitRateControl* control, LssBitTiming initial) noexcept
      : control_(control), inUse_(initial), pending_(initial) {}

  /// The timing in use: with a controller to re-time, the one it last accepted.
  LssBitTiming inUse() const noexcept { return inUse_; }
  /// The timing to use from the next reset communication on.
  LssBitTiming pending() const noexcept { return pending_; }
  void setPending(LssBitTiming timing) noexcept { pending_ = timing; }

  /// Re-times the controller (when there is one) and makes `timing` the one in use if it
  /// accepted. A timing without a bit rate (in CiA 305's table, or in `table`, the device's own:
  /// NodeSettings::manufacturerBitRates), or one the controller refuses, leaves the timing in
  /// use as it was. Out of line: its callers (LSS, reset communication) share one copy.
  [[gnu::noinline]] void switchTo(LssBitTiming timing,
                                  const BitRateTable* table = nullptr) noexcept {
    if (control_ != nullptr) {
      const uint32_t rate = bitRateOf(timing, table);
      if (rate == 0U || !control_->setBitRate(rate)) {
        return;
      }
    }
    inUse_ = timing;
  }

  /// Reset communication: switches to the pending timing when it differs from the one in use
  /// (a refused switch is tried again at the next reset communication).
  void applyPending(const BitRateTable* table = nullptr) noexcept {
    if (pending_ != inUse_) {
      switchTo(pending_, table);
    }
  }

 private:
  CanBitRateControl* control_;
  LssBitTiming inUse_;
  LssBitTiming pending_;
};

}  // namespace costa
