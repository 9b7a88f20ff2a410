#include "virtual_bus.hpp"

namespace costa::replay {

bool VirtualBus::powerOn() noexcept {
  device_.start(now_);
  return runProcess();
}

bool VirtualBus::send(const CanFrame& frame) noexcept {
  device_.onFrame(frame, now_);
  return runProcess();
}

bool VirtualBus::wait(uint64_t milliseconds) noexcept {
  return advance(milliseconds * 1000U);
}

bool VirtualBus::simulate(const char* command, Text& why) noexcept {
  return device_.control(command, why) && recorderKeptUp();
}

bool VirtualBus::runProcess() noexcept {
  // A deadline of `now` asks for another call at once (a block upload queueing a sub-block
  // longer than the transmit queue); a deadline in the past, or `now` without end, is a bug.
  constexpr int kImmediateRunsAllowed = 1000;
  for (int run = 0;; ++run) {
    nextDeadline_ = device_.process(now_);
    if (!recorderKeptUp()) {
      return false;
    }
    if (nextDeadline_ > now_) {
      return true;
    }
    if (nextDeadline_ < now_ || run == kImmediateRunsAllowed) {
      failure_.clear();
      failure_.append("process() asked to run again at ").appendDecimal(nextDeadline_);
      failure_.append(" us, not after now (").appendDecimal(now_).append(" us)");
      return false;
    }
  }
}

bool VirtualBus::advance(Microseconds microseconds) noexcept {
  const Microseconds end = now_ + microseconds;
  while (nextDeadline_ <= end) {
    now_ = nextDeadline_ > now_ ? nextDeadline_ : now_;
    if (!runProcess()) {
      return false;
    }
  }
  now_ = end;
  return runProcess();
}

bool VirtualBus::recorderKeptUp() noexcept {
  if (!recorder_.overflowed()) {
    return true;
  }
  failure_.clear();
  failure_.append("the slave sent more than ").appendDecimal(FrameRecorder::kCapacity);
  failure_.append(" frames that no step read (the replay's recorder is full)");
  return false;
}

}  // namespace costa::replay
