// The example device as a whole: its node (generated dictionary) and its behaviour.
#pragma once

#include "costa/node.hpp"
#include "device_control.hpp"
#include "example_device.hpp"
#include "example_od.hpp"

namespace costa::example {

class ExampleTarget {
 public:
  using Dictionary = NodeInstance<gen::example::Values, gen::example::Capacity>;

  /// One line for costa-slave --list-devices.
  static constexpr const char* kSummary =
      "Costa example device (every access type, several data types)";
  /// Bytes of non-volatile storage the example uses when it is given one (DeviceConfig::storage:
  /// costa-slave --storage, the fuzzer's memory). Without one it stores nothing.
  static constexpr size_t kStorageBytes = 16384;
  /// The words of its simulation commands (for the fuzzer's dictionary): it has none.
  static constexpr const char* kControlWords = "";

  /// The example's constant choices: node-id 1, LSS with the bit rates of the CiA 305 table but
  /// automatic detection (indices 0..4 and 6..8: 1000 to 125, 50, 20, 10 kbit/s), CiA 301
  /// everywhere else.
  static constexpr NodeSettings settings() noexcept {
    NodeSettings s;
    s.nodeId = 1;
    s.lss = true;
    s.lssBitRates = 0x01DF;
    return s;
  }

  /// `config`: node-id, storage (parameters and the LSS configuration across power cycles) and
  /// bit rate control, as the integrator gives them.
  ExampleTarget(CanTransmitter& can, const DeviceConfig& config) noexcept;

  void start(Microseconds now) noexcept { node_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  /// Runs the node and the device; returns the next deadline of either.
  Microseconds process(Microseconds now) noexcept;
  /// The example has no simulation commands (device_control.hpp).
  bool control(const char* command, char* why, size_t whySize) noexcept;

  Dictionary& node() noexcept { return node_; }
  /// Every hook and the listener of the behaviour found room in the node.
  bool attached() const noexcept { return device_.attached(); }
  /// Names of the dictionary's entries, for traces (costa_example_od_names: host programs).
  static const od::NameTable& names() noexcept { return gen::example::kNames; }

  /// The scratch pad's content (0x2008) and length.
  const uint8_t* scratchPad() const noexcept;
  size_t scratchPadLength() const noexcept;

 private:
  Dictionary node_;
  ExampleDevice device_;
};

}  // namespace costa::example
