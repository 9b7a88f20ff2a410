// A SOLO UNO / SOLO MINI as a whole: its node (generated dictionary, SOLO profile), the
// simulated drive, and the behaviour that joins them.
#pragma once

#include "costa/node.hpp"
#include "simulated_drive.hpp"
#include "solo_device.hpp"
#include "solo_od.hpp"

namespace costa::solo {

class SoloTarget {
 public:
  using Dictionary = NodeInstance<gen::solo::Values, gen::solo::Capacity>;

  /// `nodeId`: the device address at power-on (0x3001); 0 means 1 (manual line 861).
  SoloTarget(CanTransmitter& can, uint8_t nodeId) noexcept;

  void start(Microseconds now) noexcept { node_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  Microseconds process(Microseconds now) noexcept;

  Dictionary& node() noexcept { return node_; }
  SimulatedDrive& drive() noexcept { return drive_; }

 private:
  static uint8_t address(uint8_t nodeId) noexcept { return nodeId == 0U ? 1U : nodeId; }

  Dictionary node_;
  SimulatedDrive drive_;
  SoloDevice device_;
};

}  // namespace costa::solo
