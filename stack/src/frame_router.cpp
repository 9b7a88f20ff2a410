#include "costa/frame_router.hpp"

namespace costa {

bool FrameRouter::add(uint16_t id, Route route, uint8_t channel) noexcept {
  if (count_ == capacity_ || id > kLargestId) {
    return false;
  }
  size_t at = count_;
  while (at > 0U && slots_[at - 1U].id > id) {
    slots_[at] = slots_[at - 1U];
    --at;
  }
  // The new route goes after every route of its CAN-ID: the one before it tells.
  shared_ = shared_ || (at > 0U && slots_[at - 1U].id == id);
  slots_[at] = RouteEntry{id, route, channel};
  ++count_;
  // Every function code after the new route's starts one route later.
  for (size_t code = (id >> 7U) + 1U; code <= kFunctionCodes; ++code) {
    ++first_[code];
  }
  return true;
}

}  // namespace costa
