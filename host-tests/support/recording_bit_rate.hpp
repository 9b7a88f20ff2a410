// A CAN bit rate control that records every switch the node asks for: the rate, the virtual
// time and how many frames the node had sent by then.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>

#include "costa/port/can_bit_rate.hpp"
#include "costa/time.hpp"

namespace costa::test {

class RecordingBitRate final : public CanBitRateControl {
 public:
  struct Switch {
    uint32_t bitsPerSecond = 0;
    Microseconds at = 0;
    size_t framesBefore = 0;  ///< frames the node had sent when it asked
  };
  static constexpr size_t kCapacity = 8;

  /// Records the request (no heap use: safe inside a NoAllocationScope); answers `accept`.
  bool setBitRate(uint32_t bitsPerSecond) noexcept override {
    if (count_ < kCapacity) {
      switches_[count_] =
          Switch{bitsPerSecond, clock ? clock() : 0U, framesSent ? framesSent() : 0U};
    }
    ++count_;
    return accept;
  }

  size_t count() const { return count_; }
  const Switch& at(size_t i) const { return switches_[i]; }

  bool accept = true;
  std::function<Microseconds()> clock;  ///< the virtual time, if set
  std::function<size_t()> framesSent;   ///< frames sent so far, if set

 private:
  Switch switches_[kCapacity];
  size_t count_ = 0;
};

}  // namespace costa::test
