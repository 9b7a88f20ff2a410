// A GRA or GRN as a whole: its node (the variant's generated dictionary), the simulated hall
// chips and the behaviour that joins them.
#pragma once

#include "costa/node.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "gefran_device.hpp"
#include "hall_sensors.hpp"

namespace costa::gefran {

/// `Values`, `Capacity` and `definition` of the generated dictionary of the variant (gra / grn).
template <typename Values, typename Capacity>
class GefranTarget {
 public:
  using Dictionary = NodeInstance<Values, Capacity>;

  /// Bytes of the sensor's parameter EEPROM.
  static constexpr size_t kEepromBytes = 4096;

  /// `nodeId`: the node-id when nothing is stored (or at power-on, when `explicitNodeId`).
  /// `storage` keeps parameters across power cycles; without it they live in RAM (kept across
  /// NMT resets, like the sensor's EEPROM, but not beyond the process). `bitRate`: the CAN
  /// controller to re-time when the bit rate changes (0x5999:01 after a reset, LSS), or null.
  GefranTarget(const od::Definition& definition, CanTransmitter& can, uint8_t nodeId,
               NvStorage* storage, bool explicitNodeId,
               CanBitRateControl* bitRate = nullptr) noexcept
      : node_(definition, can,
              settings(nodeId, storage != nullptr ? storage : &eeprom_, explicitNodeId, bitRate)),
        device_(node_, sensors_) {}

  void start(Microseconds now) noexcept {
    node_.start(now);
    process(now);
  }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept {
    device_.process(now);  // a read sees the sensors as they are now
    node_.onFrame(frame, now);
  }
  Microseconds process(Microseconds now) noexcept {
    const Microseconds deviceNext = device_.process(now);
    return earliest(deviceNext, node_.process(now));
  }

  Dictionary& node() noexcept { return node_; }
  SimulatedHallSensors& sensors() noexcept { return sensors_; }

 private:
  port::MemoryStorageOf<kEepromBytes> eeprom_;
  SimulatedHallSensors sensors_;
  Dictionary node_;
  GefranDevice device_;
};

}  // namespace costa::gefran
