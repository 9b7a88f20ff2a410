// The CiA 402 drive profile (stack/cia402) alone on a node, in front of a scripted axis, on a
// virtual clock, as a TranscriptBus: the profile's own tests through frames
// (host-tests/unit/cia402_drive_test.cpp), with the dictionary host-tests/data/cia402_drive.eds.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "allocation_guard.hpp"
#include "cia402_drive_od.hpp"
#include "costa/cia402/drive.hpp"
#include "dictionary_node_bus.hpp"

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

class DriveBus : public DictionaryNodeBus<gen::cia402_drive::Values, gen::cia402_drive::Capacity> {
 public:
  using Base = DictionaryNodeBus<gen::cia402_drive::Values, gen::cia402_drive::Capacity>;

  /// A node with the drive (attached before the power-on), powered on at
  /// InProcessBus::powerOnTime(); the drive has run once.
  explicit DriveBus(const cia402::DriveOptions& options = cia402::DriveOptions{})
      : Base(gen::cia402_drive::kDefinition, NodeSettings{}, PowerOnLater{}),
        drive_(node(), axis_, options) {
    EXPECT_TRUE(drive_.attached());
    powerOn();
    axisMoved();
  }

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

  cia402::Drive& drive() { return drive_; }
  ScriptedAxis& axis() { return axis_; }

 private:
  ScriptedAxis axis_;
  cia402::Drive drive_;
};

}  // namespace costa::test
