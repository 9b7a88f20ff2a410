// A CAN transmitter that records frames in memory, for tests.
#pragma once

#include <stddef.h>

#include "costa/port/can_port.hpp"

namespace costa::port {

/// Keeps the frames a node transmits, in order, up to a fixed capacity. Can refuse frames to
/// imitate a full controller. Never allocates.
class RecordingCan : public CanTransmitter {
 public:
  static constexpr size_t kCapacity = 4096;

  bool tryTransmit(const CanFrame& frame) noexcept override {
    if (!accepting_ || count_ == kCapacity) {
      return false;
    }
    frames_[count_++] = frame;
    return true;
  }

  /// When false, tryTransmit() refuses every frame.
  void setAccepting(bool accepting) noexcept { accepting_ = accepting; }

  size_t count() const noexcept { return count_; }
  const CanFrame& at(size_t i) const noexcept { return frames_[i]; }
  void clear() noexcept { count_ = 0; }

 private:
  CanFrame frames_[kCapacity];
  size_t count_ = 0;
  bool accepting_ = true;
};

}  // namespace costa::port
