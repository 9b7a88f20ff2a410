#include "in_process_bus.hpp"

#include <gtest/gtest.h>

#include <stdlib.h>

#include <stdexcept>

#include "allocation_guard.hpp"
#include "device_registry.hpp"

namespace costa::test {

Microseconds InProcessBus::powerOnTime() {
  static const Microseconds start = [] {
    const char* text = getenv("COSTA_TEST_CLOCK_START");
    return text != nullptr ? static_cast<Microseconds>(strtoul(text, nullptr, 0)) : 0U;
  }();
  return start;
}

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
  target_->start(clock_.now());
  runProcess();
}

bool InProcessBus::checked(replay::VirtualClock::Outcome outcome) {
  if (outcome == replay::VirtualClock::Outcome::kOk) {
    return true;
  }
  ADD_FAILURE() << "process() asked to run again at " << clock_.failedDeadline()
                << " us, not after now (" << clock_.now() << " us)";
  return false;
}

bool InProcessBus::runProcess() {
  return checked(clock_.runProcess([this](Microseconds now) { return target_->process(now); }));
}

void InProcessBus::send(const CanFrame& frame) {
  NoAllocationScope scope;
  target_->onFrame(frame, clock_.now());
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
  checked(clock_.advance(microseconds, [this](Microseconds now) { return target_->process(now); }));
}

void InProcessBus::wait(uint64_t milliseconds) {
  advance(static_cast<Microseconds>(milliseconds * 1000U));
}

}  // namespace costa::test
