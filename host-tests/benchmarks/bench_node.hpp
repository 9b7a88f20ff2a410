// The example device (node-id 1) on an in-memory CAN transmitter, for measuring the stack.
//
// Unlike the unit-test harness there is no allocation guard and no transcript: a benchmark
// drives the node directly through Node::onFrame() and Node::process() on a virtual clock that
// moves only when the benchmark moves it. Setup helpers configure the node over SDO, as a
// master would, and report anything unexpected as an error string.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "costa/port/memory/recording_can.hpp"
#include "example_target.hpp"

namespace costa::bench {

/// A frame with the given id and payload (DLC = number of bytes).
CanFrame makeFrame(uint32_t id, std::initializer_list<uint8_t> bytes);

class BenchNode {
 public:
  static constexpr uint8_t kNodeId = 1;

  /// Powers the node on at time 0 (boot-up, pre-operational) and discards the boot-up frame.
  BenchNode();

  Node& node() noexcept { return target_.node(); }
  Microseconds now() const noexcept { return now_; }
  void advance(Microseconds microseconds) noexcept { now_ += microseconds; }

  /// Empties the recorder once it is nearly full. Called after every measured run: a
  /// comparison per run, and a clear once every few thousand frames.
  void recycle() noexcept {
    if (can_.count() > kRecycleAt) {
      can_.clear();
    }
  }
  void clearFrames() noexcept { can_.clear(); }
  size_t frameCount() const noexcept { return can_.count(); }
  const CanFrame& frame(size_t i) const noexcept { return can_.at(i); }

  /// Empty when the frames recorded since the last clear are exactly `expected` (on the wire).
  std::string expectFrames(const std::vector<CanFrame>& expected) const;

  // --- Setup, not measured: each returns an empty string or what went wrong. ---------------
  /// Sends `request` and expects exactly `response` back.
  std::string exchange(const CanFrame& request, const CanFrame& response);
  /// SDO download of `bytes`: expedited up to 4 bytes, segmented (size indicated) above.
  std::string sdoDownload(uint16_t index, uint8_t subIndex, const std::vector<uint8_t>& bytes);
  /// SDO download of a little-endian unsigned value of `size` bytes.
  std::string sdoWriteUnsigned(uint16_t index, uint8_t subIndex, uint32_t value, size_t size);
  /// NMT command addressed to this node, expecting `state` afterwards.
  std::string nmt(NmtCommand command, NmtState state);

 private:
  static constexpr size_t kRecycleAt = port::RecordingCan::kCapacity - 64U;

  port::RecordingCan can_;
  example::ExampleTarget target_;
  Microseconds now_ = 0;
};

}  // namespace costa::bench
