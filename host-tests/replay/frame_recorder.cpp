#include "frame_recorder.hpp"

namespace costa::replay {

bool FrameRecorder::tryTransmit(const CanFrame& frame) noexcept {
  if (unread_ == kCapacity) {
    overflowed_ = true;
    return false;
  }
  frames_[(first_ + unread_) % kCapacity] = frame;
  ++unread_;
  ++sent_;
  if (listener_ != nullptr) {
    listener_->onSent(frame);
  }
  return true;
}

bool FrameRecorder::next(CanFrame* frame) noexcept {
  if (unread_ == 0U) {
    return false;
  }
  *frame = frames_[first_];
  first_ = (first_ + 1U) % kCapacity;
  --unread_;
  return true;
}

void FrameRecorder::reset() noexcept {
  first_ = 0;
  unread_ = 0;
  sent_ = 0;
  overflowed_ = false;
}

}  // namespace costa::replay
