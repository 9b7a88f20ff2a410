// A SOLO UNO / SOLO MINI as a whole: its node (generated dictionary, SOLO profile), the
// simulated drive, and the behaviour that joins them.
#pragma once

#include "costa/node.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "device_control.hpp"
#include "simulated_drive.hpp"
#include "solo_device.hpp"
#include "solo_od.hpp"
#include "solo_profile.hpp"

namespace costa::solo {

class SoloTarget {
 public:
  using Dictionary = SoloNode;

  /// One line for costa-slave --list-devices.
  static constexpr const char* kSummary =
      "SOLO UNO / SOLO MINI motor controller with a simulated motor";
  /// Bytes of the SOLO's parameter memory (its own EEPROM, or DeviceConfig::storage).
  static constexpr size_t kStorageBytes = 4096;
  /// The words of its simulation commands (for the fuzzer's dictionary): it has none.
  static constexpr const char* kControlWords = "";

  /// The SOLO's constant choices: address 1 until one is stored in 0x3001, the SOLO profile
  /// (solo_profile.hpp, with its fixed PDO mappings), every M object kept as soon as it is
  /// written (it has no store command), no LSS: it cannot start without a node-id.
  static constexpr NodeSettings settings() noexcept {
    NodeSettings s;
    s.nodeId = 1;
    s.saveParametersOnWrite = true;
    s.profile = profile();
    return s;
  }

  /// `config.nodeId`, when given: the device address (0x3001) at power-on, over a stored one;
  /// 0 means 1 (manual line 861), and so does any value above 127: the SOLO has no LSS, so it
  /// cannot start without a node-id (0x3001 holds 1..127, errata D6). `config.storage` keeps
  /// the M objects across power cycles; without it they live in the SOLO's own memory (kept
  /// across NMT resets, like its EEPROM, but not beyond the program).
  SoloTarget(CanTransmitter& can, const DeviceConfig& config) noexcept;

  void start(Microseconds now) noexcept { node_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  Microseconds process(Microseconds now) noexcept;
  /// The SOLO has no simulation commands (device_control.hpp).
  bool control(const char* command, char* why, size_t whySize) noexcept;

  Dictionary& node() noexcept { return node_; }
  SimulatedDrive& drive() noexcept { return drive_; }
  /// The hook and the listener of the behaviour found room in the node.
  bool attached() const noexcept { return device_.attached(); }
  /// Names of the dictionary's entries, for traces (costa_solo_od_names: host programs).
  static const od::NameTable& names() noexcept { return gen::solo::kNames; }

 private:
  static uint8_t address(uint8_t nodeId) noexcept {
    return nodeId >= 1U && nodeId <= 127U ? nodeId : 1U;
  }
  /// The settings for `config`, with the SOLO's own memory when it is given no storage.
  static NodeSettings settingsFor(const DeviceConfig& config, NvStorage* eeprom) noexcept;

  static bool discardStoredParameters(void* target) noexcept;

  port::MemoryStorageOf<kStorageBytes> eeprom_;
  Dictionary node_;
  SimulatedDrive drive_;
  SoloDevice device_;
};

}  // namespace costa::solo
