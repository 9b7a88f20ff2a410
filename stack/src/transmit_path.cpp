#include "costa/transmit_path.hpp"

namespace costa {

void TransmitPath::flush(Microseconds now) noexcept {
  while (!queue_.empty() && gates_ == 0U) {
    const QueuedFrame& queued = queue_.front();
    if (queued.expiry != kNever && before(queued.expiry, now)) {
      queue_.expireFront();
      continue;
    }
    if (!can_.tryTransmit(queued.frame)) {
      ++refused_;
      return;
    }
    queue_.pop();
  }
}

}  // namespace costa
