// A node on any generated dictionary, with no device behind it, on a virtual clock, as a
// TranscriptBus: for tests of stack behaviour that depends on what a dictionary declares.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "allocation_guard.hpp"
#include "costa/node.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "transcript_player.hpp"

namespace costa::test {

template <typename Values, typename Capacity>
class DictionaryNodeBus : public TranscriptBus {
 public:
  /// Powers the node on at virtual time 0.
  DictionaryNodeBus(const od::Definition& definition, const NodeSettings& settings,
                    NodeEvents* events = nullptr)
      : node_(definition, can_, settings) {
    NoAllocationScope scope;
    if (events != nullptr) {
      EXPECT_TRUE(node_.addListener(*events));
    }
    node_.start(now_);
    runProcess();
  }

  void send(const CanFrame& frame) override {
    NoAllocationScope scope;
    node_.onFrame(frame, now_);
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
    const Microseconds end = now_ + milliseconds * 1000U;
    while (nextDeadline_ <= end) {
      now_ = nextDeadline_ > now_ ? nextDeadline_ : now_;
      runProcess();
    }
    now_ = end;
    runProcess();
  }
  bool checksTiming() const override { return true; }
  std::string simulate(const std::string& command) override {
    return "a dictionary node has no simulation (" + command + ")";
  }

  Node& node() { return node_; }

 private:
  /// Runs process() now, and again while it asks for an immediate call.
  void runProcess() {
    constexpr int kImmediateRunsAllowed = 1000;
    for (int run = 0; run < kImmediateRunsAllowed; ++run) {
      nextDeadline_ = node_.process(now_);
      if (nextDeadline_ > now_) {
        return;
      }
    }
    ADD_FAILURE() << "process() keeps asking to run again at " << now_ << " us";
  }

  port::RecordingCan can_;
  NodeInstance<Values, Capacity> node_;
  Microseconds now_ = 0;
  Microseconds nextDeadline_ = 0;
  size_t cursor_ = 0;
};

}  // namespace costa::test
