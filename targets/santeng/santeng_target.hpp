// A Santeng dual-channel motor controller as a whole: its node (generated dictionary, Santeng
// profile), the simulated power stage, and the behaviour that joins them.
#pragma once

#include "costa/node.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "device_control.hpp"
#include "santeng_device.hpp"
#include "santeng_od.hpp"
#include "santeng_profile.hpp"
#include "simulated_power_stage.hpp"

namespace costa::santeng {

class SantengTarget {
 public:
  using Dictionary = SantengNode;

  /// One line for costa-slave --list-devices.
  static constexpr const char* kSummary =
      "Santeng dual-channel motor controller with two simulated motors";
  /// Bytes of the controller's configuration memory (its own, or DeviceConfig::storage).
  static constexpr size_t kStorageBytes = 4096;
  /// The words of its simulation commands (santeng_control.hpp), for the fuzzer's dictionary.
  static constexpr const char* kControlWords =
      "set node-id bit-rate heartbeat tpdo-rate auto-start mode max-rpm encoder-lines open-loop "
      "speed position fault overheat overvoltage undervoltage short sensor mosfet stall input "
      "output on off";
  /// The largest node-id it takes (W11): costa-slave refuses a larger --node-id.
  static constexpr uint8_t kHighestNodeId = santeng::kHighestNodeId;

  /// The Santeng's constant choices: node-id 1 (line 126), the Santeng profile
  /// (santeng_profile.hpp), its own bit rate table with 250 kbit/s (line 125, W12, W13),
  /// automatic start after the boot-up (0x5000 decides at every reset communication, W7), no
  /// LSS; 0x2017 saves what kSavedGroups names.
  static constexpr NodeSettings settings() noexcept {
    NodeSettings s;
    s.nodeId = 1;
    s.profile = profile();
    s.bitTiming = kDefaultBitTiming;
    s.manufacturerBitRates = &kBitRateTable;
    s.automaticStart = true;
    s.storeAllGroups = kSavedGroups;
    s.restoreAllGroups = kSavedGroups;
    return s;
  }

  /// `config.nodeId`, when given and within 1..126: the node-id at power-on, over a stored one
  /// (another given node-id means the default, 1: costa-slave refuses it before). The
  /// configuration lives in `config.storage` across power cycles; without it in the
  /// controller's own memory (kept across NMT resets, not beyond the program).
  SantengTarget(CanTransmitter& can, const DeviceConfig& config) noexcept;

  void start(Microseconds now) noexcept;
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  Microseconds process(Microseconds now) noexcept;
  /// The simulation commands of santeng_control.hpp.
  bool control(const char* command, char* why, size_t whySize) noexcept;

  Dictionary& node() noexcept { return node_; }
  SimulatedPowerStage& powerStage() noexcept { return stage_; }
  SantengDevice& device() noexcept { return device_; }
  /// The hooks and the listener of the behaviour found room in the node.
  bool attached() const noexcept { return device_.attached(); }
  /// Names of the dictionary's entries, for traces (costa_santeng_od_names: host programs).
  static const od::NameTable& names() noexcept { return gen::santeng::kNames; }

 private:
  static NodeSettings settingsFor(const DeviceConfig& config, NvStorage* memory) noexcept;
  /// Writes a 16-bit value into `index`:`sub` as the controller's own setting; true when taken.
  bool writeSetting(uint16_t index, uint8_t sub, uint32_t value) noexcept;

  port::MemoryStorageOf<kStorageBytes> memory_;
  SimulatedPowerStage stage_;
  Dictionary node_;
  SantengDevice device_;
};

}  // namespace costa::santeng
