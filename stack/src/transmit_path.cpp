#include "costa/transmit_path.hpp"

#include "costa/od/bytes.hpp"

namespace costa {

void TransmitPath::send(uint32_t id, const uint8_t* data, uint8_t length) noexcept {
  CanFrame frame;
  frame.id = id;
  frame.dlc = length;
  copyBytes(frame.data, data, length);
  send(frame);
}

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
