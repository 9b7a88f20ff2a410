// Test doubles for the LSS slave: a host that records what the slave asks of it, and one slave
// with its transmit queue on a virtual clock, playable as a transcript (TranscriptBus).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "allocation_guard.hpp"
#include "costa/lss_slave.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "in_process_bus.hpp"
#include "transcript_player.hpp"
#include "virtual_clock.hpp"

namespace costa::test {

/// Records every call. Supports the CiA bit timing indices set in `supportedCiaIndices` (bit n
/// = index n) and manufacturer table 0x80 index 1. Records no heap use, so it can run inside a
/// NoAllocationScope.
class RecordingLssHost : public LssSlaveHost {
 public:
  bool bitTimingSupported(LssBitTiming timing) noexcept override {
    ++questions;
    lastQuestion = timing;
    if (timing.tableSelector == 0U) {
      return timing.tableIndex < 16U && ((supportedCiaIndices >> timing.tableIndex) & 1U) != 0U;
    }
    return timing.tableSelector == 0x80U && timing.tableIndex == 1U;
  }

  void activateBitTiming(LssBitTiming timing) noexcept override {
    ++activations;
    activated = timing;
    activatedAt = clock != nullptr ? clock->now() : 0U;
  }

  LssStoreResult storeConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept override {
    ++stores;
    storedNodeId = nodeId;
    storedTiming = timing;
    return storeResult;
  }

  /// Like a node: reset communication makes the pending node-id the active one.
  void requestResetCommunication() noexcept override {
    ++resetRequests;
    if (slave != nullptr) {
      slave->reset(slave->identity(), slave->pendingNodeId(), slave->pendingNodeId(),
                   slave->pendingBitTiming());
    }
  }

  uint16_t supportedCiaIndices = (1U << 2U) | (1U << 3U);  // 500 and 250 kbit/s
  LssStoreResult storeResult = LssStoreResult::kStored;
  const replay::VirtualClock* clock = nullptr;
  LssSlave* slave = nullptr;  ///< Reset on requestResetCommunication() when set.

  int questions = 0;
  LssBitTiming lastQuestion;
  int activations = 0;
  LssBitTiming activated;
  Microseconds activatedAt = 0;
  int stores = 0;
  uint8_t storedNodeId = 0;
  LssBitTiming storedTiming;
  int resetRequests = 0;
};

/// One LSS slave on a virtual clock. Every call into the slave runs inside a NoAllocationScope.
class LssBus : public TranscriptBus {
 public:
  static constexpr size_t kQueueDepth = 8;

  LssBus() : tx_(can_, slots_, kQueueDepth), slave_(tx_, host_) { host_.clock = &clock_; }

  void send(const CanFrame& frame) override {
    NoAllocationScope scope;
    accepted_ = slave_.onFrame(frame, clock_.now());
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
    advance(millisecondsToMicroseconds(static_cast<uint32_t>(milliseconds)));
  }
  bool checksTiming() const override { return true; }
  std::string simulate(const std::string& command) override {
    return "no simulation here: " + command;
  }

  /// Advances virtual time, calling process() at every deadline on the way and at the end.
  void advance(Microseconds microseconds) {
    NoAllocationScope scope;
    const auto outcome = clock_.advance(microseconds, [this](Microseconds now) {
      slave_.process(now);
      return slave_.nextDeadline();
    });
    EXPECT_EQ(outcome, replay::VirtualClock::Outcome::kOk)
        << "process(" << clock_.now() << ") left its deadline " << clock_.failedDeadline()
        << " us due";
  }

  void reset(const LssIdentity& identity, uint8_t activeNodeId, uint8_t pendingNodeId,
             LssBitTiming bitTiming = LssBitTiming{}) {
    NoAllocationScope scope;
    slave_.reset(identity, activeNodeId, pendingNodeId, bitTiming);
  }

  LssSlave& slave() { return slave_; }
  RecordingLssHost& host() { return host_; }
  TransmitPath& tx() { return tx_; }
  port::RecordingCan& can() { return can_; }
  /// Frames the slave sent that receive() has not returned yet.
  size_t unread() const { return can_.count() - cursor_; }
  Microseconds now() const { return clock_.now(); }
  /// What onFrame() returned for the last frame sent.
  bool accepted() const { return accepted_; }

 private:
  port::RecordingCan can_;
  size_t cursor_ = 0;
  QueuedFrame slots_[kQueueDepth];
  TransmitPath tx_;
  RecordingLssHost host_;
  LssSlave slave_;
  replay::VirtualClock clock_{InProcessBus::powerOnTime()};
  bool accepted_ = false;
};

/// Vendor-id 0x12345678, product code 0x9ABCDEF0, revision 0x00020001, serial 0xCAFEF00D.
inline const LssIdentity kLssTestIdentity{0x12345678U, 0x9ABCDEF0U, 0x00020001U, 0xCAFEF00DU};

/// A slave with kLssTestIdentity and node-id 5 (active and pending), in LSS waiting state.
class LssSlaveTest : public ::testing::Test {
 protected:
  LssSlaveTest() { bus_.reset(kLssTestIdentity, 5, 5); }

  /// Plays transcript lines (see transcript.hpp) against the slave.
  std::string play(const std::string& text) { return playText(text, bus_); }
  LssSlave& slave() { return bus_.slave(); }
  RecordingLssHost& host() { return bus_.host(); }

  void enterConfiguration() {
    ASSERT_EQ(play("rx 7E5 [8] 04 01 00 00 00 00 00 00"), "");
    ASSERT_TRUE(slave().configurationState());
  }

  LssBus bus_;
};

}  // namespace costa::test

/// Plays transcript lines against the fixture's slave; the report names the failing line.
#define EXPECT_TRANSCRIPT(text) EXPECT_EQ(play(text), "")
