// The example device as a whole: its node (generated dictionary) and its behaviour.
#pragma once

#include "costa/node.hpp"
#include "example_device.hpp"
#include "example_od.hpp"

namespace costa::example {

class ExampleTarget {
 public:
  using Dictionary = NodeInstance<gen::example::Values, gen::example::Capacity>;

  ExampleTarget(CanTransmitter& can, uint8_t nodeId) noexcept;

  void start(Microseconds now) noexcept { node_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) noexcept { node_.onFrame(frame, now); }
  /// Runs the node and the device; returns the next deadline of either.
  Microseconds process(Microseconds now) noexcept;

  Dictionary& node() noexcept { return node_; }
  /// The scratch pad's content (0x2008) and length.
  const uint8_t* scratchPad() const noexcept;
  size_t scratchPadLength() const noexcept;

 private:
  static NodeSettings settings(uint8_t nodeId) noexcept;

  Dictionary node_;
  ExampleDevice device_;
};

}  // namespace costa::example
