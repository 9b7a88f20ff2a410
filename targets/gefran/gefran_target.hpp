// A GRA or GRN as a whole: its node (the variant's generated dictionary), the simulated hall
// chips and the behaviour that joins them; GraTarget and GrnTarget.
#pragma once

#include "costa/node.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "device_control.hpp"
#include "gefran_control.hpp"
#include "gefran_device.hpp"
#include "gra_od.hpp"
#include "grn_od.hpp"
#include "hall_sensors.hpp"

namespace costa::gefran {

/// The GRA/GRN profile: event-driven TPDO sent on entering operational (E17), 0x1001 always 0
/// (E14), heartbeat only (E48).
constexpr DeviceProfile profile() noexcept {
  DeviceProfile p{};
  // The device needs the quirk profiles (gefran_device.cpp); its header compiles in any tree.
#if COSTA_QUIRK_PROFILES
  p.pdo.tpdoOnEnteringOperational = true;
  p.emcy.reportErrorRegister = false;
  p.errorControl.nodeGuarding = false;
#endif
  return p;
}

/// What differs between the variants: the generated dictionary and the summary line.
struct Gra {
  static constexpr const char* kSummary =
      "Gefran GRA contactless angle sensor (with shaft), simulated hall chips";
  using Values = gen::gra::Values;
  using Capacity = gen::gra::Capacity;
  static const od::Definition& definition() noexcept { return gen::gra::kDefinition; }
  static const od::NameTable& names() noexcept { return gen::gra::kNames; }
};
struct Grn {
  static constexpr const char* kSummary = "Gefran GRN contactless angle sensor (without shaft)";
  using Values = gen::grn::Values;
  using Capacity = gen::grn::Capacity;
  static const od::Definition& definition() noexcept { return gen::grn::kDefinition; }
  static const od::NameTable& names() noexcept { return gen::grn::kNames; }
};

/// `Variant`: Gra or Grn.
template <typename Variant>
class GefranTarget {
 public:
  using Dictionary = NodeInstance<typename Variant::Values, typename Variant::Capacity>;

  /// One line for costa-slave --list-devices.
  static constexpr const char* kSummary = Variant::kSummary;
  /// Bytes of the sensor's parameter EEPROM (its own, or DeviceConfig::storage).
  static constexpr size_t kStorageBytes = 4096;
  /// The words of its simulation commands (gefran_control.hpp), for the fuzzer's dictionary.
  static constexpr const char* kControlWords = "raw angle fault chip1 chip2 magnet on off";

  /// A GRA/GRN's constant choices: the factory node-id 0x7F (E1), LSS with the manual's bit
  /// rates (E26), "save" stores PARA (communication and application groups, E22), "load"
  /// restores PARA and LSS-PARA (E21), event-driven TPDO sent on entering operational (E17),
  /// 0x1001 always 0 (E14), heartbeat only (E48). The automatic start is 0x5000's (E16), which
  /// the device applies after every boot-up.
  static constexpr NodeSettings settings() noexcept {
    NodeSettings s;
    s.nodeId = kFactoryNodeId;
    s.profile = profile();
    s.lss = true;
    s.lssBitRates = kListedBitRates;
    s.storeAllGroups = groupBit(od::kGroupCommunication) | groupBit(od::kGroupApplication);
    s.restoreAllGroups = s.storeAllGroups;
    s.restoreAllIncludesLss = true;
    return s;
  }

  /// `config.nodeId`, when given: the node-id at power-on, over a stored one; otherwise a
  /// stored node-id, else 0x7F. `config.storage` keeps parameters across power cycles; without
  /// it they live in the sensor's own memory (kept across NMT resets, like its EEPROM, but not
  /// beyond the program). `config.bitRateControl`: the CAN controller to re-time when the bit
  /// rate changes (0x5999:01 after a reset, LSS), or null.
  GefranTarget(CanTransmitter& can, const DeviceConfig& config) noexcept
      : node_(Variant::definition(), can, withEeprom(configured(settings(), config))),
        device_(node_, gefranValues(node_.values()), sensors_) {
    static_assert(settings().lss && settings().storeAllGroups != 0U,
                  "the GRA/GRN have LSS (E50) and a store command (E22)");
  }

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
  /// The simulation commands of gefran_control.hpp: raw A B, angle DEG, fault WHAT on|off. A
  /// command that changes the chips takes effect at once (process() runs).
  bool control(const char* command, char* why, size_t whySize) noexcept {
    const ParsedControl parsed = parseControl(command);
    if (parsed.error != ControlError::kNone) {
      describeControlError(parsed, why, why != nullptr ? whySize : 0U);
      return false;
    }
    applyControl(parsed.command, sensors_);
    process(node_.now());
    return true;
  }

  Dictionary& node() noexcept { return node_; }
  SimulatedHallSensors& sensors() noexcept { return sensors_; }
  /// Every hook and the listener of the behaviour found room in the node.
  bool attached() const noexcept { return device_.attached(); }
  /// Names of the dictionary's entries, for traces (costa_<variant>_od_names: host programs).
  static const od::NameTable& names() noexcept { return Variant::names(); }

 private:
  NodeSettings withEeprom(NodeSettings settings) noexcept {
    if (settings.storage == nullptr) {
      settings.storage = &eeprom_;
    }
    return settings;
  }

  port::MemoryStorageOf<kStorageBytes> eeprom_;
  SimulatedHallSensors sensors_;
  Dictionary node_;
  GefranDevice device_;
};

using GraTarget = GefranTarget<Gra>;
using GrnTarget = GefranTarget<Grn>;

}  // namespace costa::gefran
