// What a CAN controller's driver reports to the node (Node::onControllerEvent), and a bounded
// list of such reports. A port type: drivers need nothing of the stack to report them.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// Signals from the CAN controller's driver (CiA 301 EMCY codes 0x81xx).
enum class CanControllerEvent : uint8_t {
  kRxOverrun,        ///< frames were lost: EMCY 0x8110
  kErrorPassive,     ///< EMCY 0x8120 until error active again
  kErrorActive,      ///< back to normal: clears error passive
  kBusOff,           ///< transmission stops; the communication error behaviour (0x1029) applies
  kBusOffRecovered,  ///< transmission resumes: EMCY 0x8140
};

/// The controller events a driver found in one look at its controller, in the order they
/// happened; at most `Capacity` (a driver's bound), further ones are dropped.
template <size_t Capacity>
class CanControllerEvents {
 public:
  static constexpr size_t kCapacity = Capacity;

  size_t size() const noexcept { return count_; }
  bool empty() const noexcept { return count_ == 0; }
  CanControllerEvent operator[](size_t i) const noexcept { return events_[i]; }
  const CanControllerEvent* begin() const noexcept { return events_; }
  const CanControllerEvent* end() const noexcept { return events_ + count_; }

  void add(CanControllerEvent event) noexcept {
    if (count_ < Capacity) {
      events_[count_++] = event;
    }
  }

 private:
  CanControllerEvent events_[Capacity] = {};
  size_t count_ = 0;
};

}  // namespace costa
