// The bit timing a node runs with, the one it is to run with after the next reset
// communication, and the switch between them through the port's CanBitRateControl.
//
// Context: the one that runs the node. No allocation; every call O(1) plus the controller's
// setBitRate().
#pragma once

#include "costa/lss_bit_timing.hpp"
#include "costa/node_settings.hpp"
#include "costa/port/can_bit_rate.hpp"

namespace costa {

class BitTimingSwitch {
 public:
  /// Starts at `settings.bitTiming`; re-times `settings.bitRateControl` (when null, the node
  /// only records the timing in use) with the rates of CiA 305's table and of
  /// `settings.manufacturerBitRates`. `settings` outlives the switch.
  explicit BitTimingSwitch(const NodeSettings& settings) noexcept
      : settings_(settings), inUse_(settings.bitTiming), pending_(settings.bitTiming) {}

  /// The timing in use: with a controller to re-time, the one it last accepted.
  LssBitTiming inUse() const noexcept { return inUse_; }
  /// The timing to use from the next reset communication on.
  LssBitTiming pending() const noexcept { return pending_; }
  void setPending(LssBitTiming timing) noexcept { pending_ = timing; }

  /// Re-times the controller (when there is one) and makes `timing` the one in use if it
  /// accepted. A timing without a bit rate (CiA 305's or the device's own table's), or one the
  /// controller refuses, leaves the timing in use as it was.
  void switchTo(LssBitTiming timing) noexcept {
    if (settings_.bitRateControl != nullptr) {
      const uint32_t rate = bitRateOf(timing, settings_.manufacturerBitRates);
      if (rate == 0U || !settings_.bitRateControl->setBitRate(rate)) {
        return;
      }
    }
    inUse_ = timing;
  }

  /// Reset communication: switches to the pending timing when it differs from the one in use
  /// (a refused switch is tried again at the next reset communication).
  void applyPending() noexcept {
    if (pending_ != inUse_) {
      switchTo(pending_);
    }
  }

 private:
  const NodeSettings& settings_;
  LssBitTiming inUse_;
  LssBitTiming pending_;
};

}  // namespace costa
