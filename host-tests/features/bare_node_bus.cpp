#include "bare_node_bus.hpp"

#include <gtest/gtest.h>

#include "allocation_guard.hpp"

namespace costa::test {

NodeSettings BareNodeBus::settings(NvStorage* storage) {
  NodeSettings settings;
  settings.nodeId = 1;
  settings.storage = storage;
  settings.lss = true;
  settings.lssBitRates = 0x01DF;
  return settings;
}

BareNodeBus::BareNodeBus() : node_(gen::example::kDefinition, can_, settings(&storage_)) {
  NoAllocationScope scope;
  node_.start(now_);
  runProcess();
}

void BareNodeBus::runProcess() {
  constexpr int kImmediateRunsAllowed = 1000;
  for (int run = 0; run < kImmediateRunsAllowed; ++run) {
    nextDeadline_ = node_.process(now_);
    if (nextDeadline_ > now_) {
      return;
    }
  }
  ADD_FAILURE() << "process() keeps asking to run again at " << now_ << " us";
}

void BareNodeBus::send(const CanFrame& frame) {
  NoAllocationScope scope;
  node_.onFrame(frame, now_);
  runProcess();
}

bool BareNodeBus::receive(CanFrame* frame, int timeoutMs) {
  (void)timeoutMs;
  if (cursor_ == can_.count()) {
    return false;
  }
  *frame = can_.at(cursor_++);
  return true;
}

void BareNodeBus::wait(uint64_t milliseconds) {
  NoAllocationScope scope;
  const Microseconds end = now_ + milliseconds * 1000U;
  while (nextDeadline_ <= end) {
    now_ = nextDeadline_ > now_ ? nextDeadline_ : now_;
    runProcess();
  }
  now_ = end;
  runProcess();
}

std::string BareNodeBus::simulate(const std::string& command) {
  return "a bare node has no simulation (" + command + ")";
}

}  // namespace costa::test
