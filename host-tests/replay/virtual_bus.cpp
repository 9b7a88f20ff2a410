#include "virtual_bus.hpp"

namespace costa::replay {

bool VirtualBus::powerOn() noexcept {
  device_.start(clock_.now());
  return runProcess();
}

bool VirtualBus::send(const CanFrame& frame) noexcept {
  device_.onFrame(frame, clock_.now());
  return runProcess();
}

bool VirtualBus::wait(uint64_t milliseconds) noexcept {
  return checked(
      clock_.advance(static_cast<Microseconds>(milliseconds * 1000U), processAndRecord()));
}

bool VirtualBus::simulate(const char* command, Text& why) noexcept {
  return device_.control(command, why) && recorderKeptUp();
}

bool VirtualBus::runProcess() noexcept {
  return checked(clock_.runProcess(processAndRecord()));
}

bool VirtualBus::checked(VirtualClock::Outcome outcome) noexcept {
  if (!recorderKeptUp()) {
    return false;
  }
  if (outcome == VirtualClock::Outcome::kOk) {
    return true;
  }
  failure_.clear();
  failure_.append("process() asked to run again at ").appendDecimal(clock_.failedDeadline());
  failure_.append(" us, not after now (").appendDecimal(clock_.now()).append(" us)");
  return false;
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
