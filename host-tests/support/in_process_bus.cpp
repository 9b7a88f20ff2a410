#include "in_process_bus.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "allocation_guard.hpp"
#include "device_registry.hpp"

namespace costa::test {

InProcessBus::InProcessBus(const std::string& device, int nodeId,
                           const host::TargetOptions& extra) {
  const host::DeviceEntry* entry = host::findDevice(device);
  if (entry == nullptr) {
    throw std::runtime_error("unknown device " + device);
  }
  host::TargetOptions options = extra;
  options.nodeId = nodeId;
  std::string error;
  target_ = host::createDevice(*entry, can_, options, &error);
  if (!target_) {
    throw std::runtime_error(error);
  }
  powerOn();
}

InProcessBus::InProcessBus(const Factory& factory) : target_(factory(can_)) {
  powerOn();
}

void InProcessBus::powerOn() {
  NoAllocationScope scope;
  target_->start(now_);
  runProcess();
}

bool InProcessBus::runProcess() {
  // A deadline of `now` asks for another call at once (a block upload queueing a sub-block
  // longer than the transmit queue); a deadline in the past, or `now` without end, is a bug.
  constexpr int kImmediateRunsAllowed = 1000;
  for (int run = 0;; ++run) {
    nextDeadline_ = target_->process(now_);
    if (nextDeadline_ > now_) {
      return true;
    }
    if (nextDeadline_ < now_ || run == kImmediateRunsAllowed) {
      ADD_FAILURE() << "process() asked to run again at " << nextDeadline_ << " us, not after now ("
                    << now_ << " us)";
      return false;
    }
  }
}

void InProcessBus::send(const CanFrame& frame) {
  NoAllocationScope scope;
  target_->onFrame(frame, now_);
  runProcess();
}

bool InProcessBus::receive(CanFrame* frame, int timeoutMs) {
  (void)timeoutMs;
  if (cursor_ == can_.count()) {
    return false;
  }
  *frame = can_.at(cursor_++);
  return true;
}

void InProcessBus::advance(Microseconds microseconds) {
  NoAllocationScope scope;
  const Microseconds end = now_ + microseconds;
  while (nextDeadline_ <= end) {
    now_ = nextDeadline_ > now_ ? nextDeadline_ : now_;
    if (!runProcess()) {
      break;
    }
  }
  now_ = end;
  runProcess();
}

void InProcessBus::wait(uint64_t milliseconds) {
  advance(milliseconds * 1000U);
}

}  // namespace costa::test
