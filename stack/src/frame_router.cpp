#include "costa/frame_router.hpp"

namespace costa {

bool FrameRouter::add(uint16_t id, Route route, uint8_t channel) noexcept {
  if (count_ == capacity_) {
    return false;
  }
  size_t at = count_;
  while (at > 0U && slots_[at - 1U].id > id) {
    slots_[at] = slots_[at - 1U];
    --at;
  }
  slots_[at] = RouteEntry{id, route, channel};
  ++count_;
  return true;
}

}  // namespace costa
