// A node on any generated dictionary, with no device behind it, on a virtual clock, as a
// TranscriptBus: for tests of stack behaviour that depends on what a dictionary declares.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "allocation_guard.hpp"
#include "costa/node.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "in_process_bus.hpp"
#include "transcript_player.hpp"
#include "virtual_clock.hpp"

namespace costa::test {

template <typename Values, typename Capacity>
class DictionaryNodeBus : public TranscriptBus {
 public:
  /// Powers the node on at InProcessBus::powerOnTime().
  DictionaryNodeBus(const od::Definition& definition, const NodeSettings& settings,
                    NodeEvents* events = nullptr)
      : node_(definition, can_, settings) {
    NoAllocationScope scope;
    if (events != nullptr) {
      EXPECT_TRUE(node_.addListener(*events));
    }
    powerOn();
  }

  void send(const CanFrame& frame) override {
    NoAllocationScope scope;
    node_.onFrame(frame, clock_.now());
    runProcess();
  }
  bool receive(CanFrame* frame, int timeoutMs) override {
    (void)timeoutMs;
    if (cursor_ == can_.count()) {
      return false;
    }
    *frame = can_.at(cursor_++);
    return true;
  }
  void wait(uint64_t milliseconds) override {
    NoAllocationScope scope;
    expectOk(clock_.advance(static_cast<Microseconds>(milliseconds * 1000U),
                            [this](Microseconds now) { return node_.process(now); }));
  }
  bool checksTiming() const override { return true; }
  std::string simulate(const std::string& command) override {
    return "a dictionary node has no simulation (" + command + ")";
  }

  NodeInstance<Values, Capacity>& node() { return node_; }

 protected:
  struct PowerOnLater {};
  /// For a derived bus that attaches its own behaviour first, then calls powerOn().
  DictionaryNodeBus(const od::Definition& definition, const NodeSettings& settings,
                    PowerOnLater /*unused*/)
      : node_(definition, can_, settings) {}

  /// Starts the node at InProcessBus::powerOnTime() and runs what follows.
  void powerOn() {
    NoAllocationScope scope;
    node_.start(clock_.now());
    runProcess();
  }

  /// Runs process() now, and again while it asks for an immediate call.
  void runProcess() {
    expectOk(clock_.runProcess([this](Microseconds now) { return node_.process(now); }));
  }

 private:
  void expectOk(replay::VirtualClock::Outcome outcome) {
    EXPECT_EQ(outcome, replay::VirtualClock::Outcome::kOk)
        << "process() asked for " << clock_.failedDeadline() << " us at " << clock_.now() << " us";
  }

  port::RecordingCan can_;
  NodeInstance<Values, Capacity> node_;
  replay::VirtualClock clock_{InProcessBus::powerOnTime()};
  size_t cursor_ = 0;
};

}  // namespace costa::test
