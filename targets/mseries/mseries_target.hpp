// An M-series robot joint as a whole: its node (generated dictionary, the joint's profile), the
// CiA 402 drive with the joint's behaviour (JointDevice) and the simulated motor.
#pragma once

#include "costa/node.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "device_control.hpp"
#include "joint_device.hpp"
#include "mseries_od.hpp"
#include "mseries_profile.hpp"
#include "simulated_joint.hpp"

namespace costa::mseries {

class MSeriesTarget {
 public:
  using Dictionary = MSeriesNode;

  /// One line for costa-slave --list-devices.
  static constexpr const char* kSummary =
      "M-series robot joint (M4230, M8025): CiA 402 servo with a simulated motor";
  /// The name the manual's readers use; costa-slave accepts it for the device's own.
  static constexpr const char* kAlias = "m-series";
  /// Bytes of the joint's parameter memory (its own, or DeviceConfig::storage).
  static constexpr size_t kStorageBytes = 4096;
  /// The words of its simulation commands (joint_control.hpp), for the fuzzer's dictionary.
  static constexpr const char* kControlWords = "position dir pu alarm voltage on off 0x12";

  /// The joint's constant choices: node-id 1 until 0x2615 is saved (W11), 1 Mbit/s (W12),
  /// operational by itself after every boot-up (W5), the joint's profile (mseries_profile.hpp),
  /// no LSS; 0x2614 saves the communication and application groups (A5).
  static constexpr NodeSettings settings() noexcept {
    NodeSettings s;
    s.nodeId = 1;
    s.profile = profile();
    s.automaticStart = true;
    s.bitTiming = LssBitTiming{0, 0};
    s.storeAllGroups = groupBit(od::kGroupCommunication) | groupBit(od::kGroupApplication);
    s.restoreAllGroups = s.storeAllGroups;
    return s;
  }

  /// `config.nodeId`, when given: the node-id at power-on, over 0x2615 (any value outside
  /// 1..127 is 1: the joint has no LSS). `config.storage` keeps the saved parameters across
  /// power cycles; without it they live in the joint's own memory (kept across NMT resets).
  MSeriesTarget(CanTransmitter& can, const DeviceConfig& config) noexcept;

  void start(Microseconds now) noexcept;
  /// A read or an RPDO's answer sees the motor as it is at `now`: the motor runs up to `now`
  /// first, and the answering TPDO leaves before it runs on (errata W8: at reception).
  void onFrame(const CanFrame& frame, Microseconds now) noexcept {
    device_.process(now);
    node_.onFrame(frame, now);
    static_cast<void>(node_.process(now));
  }
  Microseconds process(Microseconds now) noexcept {
    const Microseconds deviceNext = device_.process(now);
    return earliest(deviceNext, node_.process(now));
  }
  /// The status word shows a state of the drive (JointDevice::consistent): an invariant the
  /// fuzzer checks after every event.
  bool consistent(char* why, size_t whySize) const noexcept {
    return device_.consistent(why, whySize);
  }
  /// The simulation commands of joint_control.hpp; each takes effect at once.
  bool control(const char* command, char* why, size_t whySize) noexcept;

  Dictionary& node() noexcept { return node_; }
  SimulatedJoint& joint() noexcept { return joint_; }
  JointDevice& device() noexcept { return device_; }
  /// Every hook and listener of the joint and its drive found room in the node.
  bool attached() const noexcept { return device_.attached(); }
  /// Names of the dictionary's entries, for traces (costa_mseries_od_names: host programs).
  static const od::NameTable& names() noexcept { return gen::mseries::kNames; }

 private:
  static uint8_t address(uint8_t nodeId) noexcept {
    return nodeId >= 1U && nodeId <= 127U ? nodeId : 1U;
  }
  static NodeSettings settingsFor(const DeviceConfig& config, NvStorage* eeprom) noexcept;

  port::MemoryStorageOf<kStorageBytes> eeprom_;
  SimulatedJoint joint_;
  Dictionary node_;
  JointDevice device_;
};

}  // namespace costa::mseries
