// The example's behaviour on a node with any NodeSettings, for tests of settings and profiles
// the example device does not have (example::ExampleTarget runs the example's own,
// ExampleTarget::settings(), configured by a DeviceConfig). `serialNumber` (0x1018:04) tells
// several such nodes apart by LSS. The composition interface of targets/devices.hpp.
#pragma once

#include "costa/node.hpp"
#include "device_control.hpp"
#include "example_device.hpp"
#include "example_od.hpp"
#include "example_target.hpp"

namespace costa::test {

class ExampleWithSettings {
 public:
  using Dictionary = example::ExampleTarget::Dictionary;

  explicit ExampleWithSettings(CanTransmitter& can, const NodeSettings& settings,
                               uint32_t serialNumber = 1) noexcept
      : node_(gen::example::kDefinition, can, settings), device_(node_, serialNumber) {}

  void start(Microseconds now) noexcept { node_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  Microseconds process(Microseconds now) noexcept {
    const Microseconds deviceNext = device_.process(now);
    return earliest(deviceNext, node_.process(now));
  }
  bool control(const char* command, char* why, size_t whySize) noexcept {
    (void)command;
    return refuseControl(kNoSimulationCommands, why, whySize);
  }
  Dictionary& node() noexcept { return node_; }
  bool attached() const noexcept { return device_.attached(); }
  static const od::NameTable& names() noexcept { return gen::example::kNames; }

 private:
  Dictionary node_;
  example::ExampleDevice device_;
};

}  // namespace costa::test
