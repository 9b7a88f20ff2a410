// The example device as a whole: its node (generated dictionary) and its behaviour.
#pragma once

#include "costa/node.hpp"
#include "example_device.hpp"
#include "example_od.hpp"

namespace costa::example {

class ExampleTarget {
 public:
  using Dictionary = NodeInstance<gen::example::Values, gen::example::Capacity>;

  /// `storage` (may be null) keeps parameters and the LSS configuration across power cycles.
  ExampleTarget(CanTransmitter& can, uint8_t nodeId, NvStorage* storage = nullptr) noexcept;
  /// With explicit settings (node-id, profile, ...), for tests of profile-specific behaviour.
  ExampleTarget(CanTransmitter& can, const NodeSettings& settings,
                uint32_t serialNumber = 1) noexcept;

  void start(Microseconds now) noexcept { node_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  /// Runs the node and the device; returns the next deadline of either.
  Microseconds process(Microseconds now) noexcept;

  Dictionary& node() noexcept { return node_; }
  /// The scratch pad's content (0x2008) and length.
  const uint8_t* scratchPad() const noexcept;
  size_t scratchPadLength() const noexcept;

  /// The example's settings: LSS on, bit rates of the CiA 305 table, optional storage.
  static NodeSettings settings(uint8_t nodeId, NvStorage* storage) noexcept;

 private:
  Dictionary node_;
  ExampleDevice device_;
};

}  // namespace costa::example
