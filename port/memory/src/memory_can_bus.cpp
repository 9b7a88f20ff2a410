#include "costa/port/memory/memory_can_bus.hpp"

namespace costa::port {

bool MemoryCanEndpoint::tryTransmit(const CanFrame& frame) noexcept {
  if (bus_ != nullptr) {
    bus_->broadcast(*this, frame);
  }
  return true;
}

bool MemoryCanEndpoint::receive(CanFrame* frame) noexcept {
  if (count_ == 0U) {
    return false;
  }
  *frame = inbox_[head_];
  head_ = (head_ + 1U) % kInboxCapacity;
  --count_;
  return true;
}

void MemoryCanEndpoint::deliver(const CanFrame& frame) noexcept {
  if (count_ == kInboxCapacity) {
    ++overruns_;
    return;
  }
  inbox_[(head_ + count_) % kInboxCapacity] = frame;
  ++count_;
}

bool MemoryCanBus::attach(MemoryCanEndpoint& endpoint) noexcept {
  if (count_ == kMaxEndpoints) {
    return false;
  }
  endpoint.bus_ = this;
  endpoints_[count_++] = &endpoint;
  return true;
}

void MemoryCanBus::broadcast(const MemoryCanEndpoint& sender, const CanFrame& frame) noexcept {
  for (size_t i = 0; i < count_; ++i) {
    if (endpoints_[i] != &sender) {
      endpoints_[i]->deliver(frame);
    }
  }
}

}  // namespace costa::port
