// A SOLO UNO / SOLO MINI as a whole: its node (generated dictionary, SOLO profile), the
// simulated drive, and the behaviour that joins them.
#pragma once

#include "costa/node.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "simulated_drive.hpp"
#include "solo_device.hpp"
#include "solo_od.hpp"

namespace costa::solo {

static_assert(
    features::kParameterStorage,
    "the SOLO keeps its parameters in EEPROM: build with COSTA_FEATURE_PARAMETER_STORAGE=ON");
static_assert(
    features::kNodeGuarding,
    "the SOLO answers node guarding (errata A12, S5): build with COSTA_FEATURE_NODE_GUARDING=ON");

class SoloTarget {
 public:
  using Dictionary = NodeInstance<gen::solo::Values, gen::solo::Capacity>;

  /// Bytes of the SOLO's parameter memory.
  static constexpr size_t kEepromBytes = 4096;

  /// `nodeId`: the device address (0x3001) at power-on when nothing is stored, or always when
  /// `explicitNodeId`; 0 means 1 (manual line 861), and so does any value above 127: the SOLO
  /// has no LSS, so it cannot start without a node-id (0x3001 holds 1..127, errata D6).
  /// `storage` keeps the M objects across power cycles; without it they live in RAM (kept
  /// across NMT resets, like the SOLO's EEPROM, but not beyond the process). `bitRate`: the
  /// controller to re-time, or null (NodeSettings::bitRateControl).
  SoloTarget(CanTransmitter& can, uint8_t nodeId, NvStorage* storage = nullptr,
             bool explicitNodeId = false, CanBitRateControl* bitRate = nullptr) noexcept;

  void start(Microseconds now) noexcept { node_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  Microseconds process(Microseconds now) noexcept;

  Dictionary& node() noexcept { return node_; }
  SimulatedDrive& drive() noexcept { return drive_; }

 private:
  static uint8_t address(uint8_t nodeId) noexcept {
    return nodeId >= 1U && nodeId <= 127U ? nodeId : 1U;
  }

  static void discardStoredParameters(void* target) noexcept;

  port::MemoryStorageOf<kEepromBytes> eeprom_;
  Dictionary node_;
  SimulatedDrive drive_;
  SoloDevice device_;
};

}  // namespace costa::solo
