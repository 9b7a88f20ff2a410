#include "bare_node_bus.hpp"

#include <gtest/gtest.h>

#include "allocation_guard.hpp"

namespace costa::test {

NodeSettings BareNodeBus::settings(NvStorage* storage, const DeviceProfile& profile) {
  NodeSettings settings;
  settings.profile = profile;
  settings.nodeId = 1;
  settings.storage = storage;
  settings.lss = true;
  settings.lssBitRates = 0x01DF;
  return settings;
}

BareNodeBus::BareNodeBus(const DeviceProfile& profile)
    : node_(gen::example::kDefinition, can_, settings(&storage_, profile)) {
  NoAllocationScope scope;
  node_.start(clock_.now());
  runProcess();
}

void BareNodeBus::runProcess() {
  const auto outcome = clock_.runProcess([this](Microseconds now) { return node_.process(now); });
  EXPECT_EQ(outcome, replay::VirtualClock::Outcome::kOk)
      << "process() asked for " << clock_.failedDeadline() << " us at " << clock_.now() << " us";
}

void BareNodeBus::send(const CanFrame& frame) {
  NoAllocationScope scope;
  node_.onFrame(frame, clock_.now());
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
  const auto outcome = clock_.advance(static_cast<Microseconds>(milliseconds * 1000U),
                                      [this](Microseconds now) { return node_.process(now); });
  EXPECT_EQ(outcome, replay::VirtualClock::Outcome::kOk)
      << "process() asked for " << clock_.failedDeadline() << " us at " << clock_.now() << " us";
}

std::string BareNodeBus::simulate(const std::string& command) {
  return "a bare node has no simulation (" + command + ")";
}

}  // namespace costa::test
