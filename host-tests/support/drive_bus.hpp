// The CiA 402 drive profile (stack/cia402) alone on a node, in front of a scripted axis, on a
// virtual clock, as a TranscriptBus: the profile's own tests through frames
// (host-tests/unit/cia402_drive_test.cpp), with the dictionary host-tests/data/cia402_drive.eds.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "allocation_guard.hpp"
#include "cia402_drive_od.hpp"
#include "costa/cia402/drive.hpp"
#include "costa/node.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "in_process_bus.hpp"
#include "transcript_player.hpp"
#include "virtual_clock.hpp"

namespace costa::test {

/// An axis the test moves: it remembers every command and arrives only when told to.
class ScriptedAxis : public cia402::Axis {
 public:
  void command(const cia402::AxisCommand& command) noexcept override {
    last = command;
    ++commands;
    if (command.motion == cia402::Motion::kHoming) {
      current.homing = cia402::HomingState::kRunning;
    }
    if (command.motion != cia402::Motion::kFree && command.motion != cia402::Motion::kStop) {
      current.atRest = false;
    }
  }
  cia402::AxisState state() const noexcept override { return current; }
  void resetFault() noexcept override { current.fault = faultStays; }

  /// The axis arrives where the last command sends it, and rests.
  void arrive() {
    if (last.motion == cia402::Motion::kPosition || last.motion == cia402::Motion::kInterpolate) {
      current.position = last.position;
    }
    current.velocity = last.motion == cia402::Motion::kVelocity ? last.velocity : 0;
    current.atRest = last.motion != cia402::Motion::kVelocity || last.velocity == 0;
  }

  cia402::AxisCommand last{};
  int commands = 0;
  cia402::AxisState current{};
  bool faultStays = false;  ///< a fault reset does not clear the fault
};

class DriveBus : public TranscriptBus {
 public:
  using Dictionary = NodeInstance<gen::cia402_drive::Values, gen::cia402_drive::Capacity>;

  /// A node with the drive (attached before the power-on), powered on at
  /// InProcessBus::powerOnTime(); the drive has run once.
  explicit DriveBus(const cia402::DriveOptions& options = cia402::DriveOptions{})
      : node_(gen::cia402_drive::kDefinition, can_, NodeSettings{}), drive_(node_, axis_, options) {
    NoAllocationScope scope;
    EXPECT_TRUE(drive_.attached());
    node_.start(clock_.now());
    drive_.update();
    runProcess();
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
    return "the drive bus has no simulation (" + command + ")";
  }

  /// The axis has moved as the test set it: the drive learns of it (as a device's process()
  /// would tell it), and the node sends what follows.
  void axisMoved() {
    NoAllocationScope scope;
    drive_.update();
    runProcess();
  }

  Dictionary& node() { return node_; }
  cia402::Drive& drive() { return drive_; }
  ScriptedAxis& axis() { return axis_; }

 private:
  void runProcess() {
    expectOk(clock_.runProcess([this](Microseconds now) { return node_.process(now); }));
  }
  void expectOk(replay::VirtualClock::Outcome outcome) {
    EXPECT_EQ(outcome, replay::VirtualClock::Outcome::kOk)
        << "process() asked for " << clock_.failedDeadline() << " us at " << clock_.now() << " us";
  }

  port::RecordingCan can_;
  ScriptedAxis axis_;
  Dictionary node_;
  cia402::Drive drive_;
  replay::VirtualClock clock_{InProcessBus::powerOnTime()};
  size_t cursor_ = 0;
};

}  // namespace costa::test
