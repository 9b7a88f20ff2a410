// The example dictionary's node with no device behaviour behind it, on a virtual clock, as a
// TranscriptBus. It needs nothing of the stack beyond NodeInstance, so that it can be built
// against any variant of the stack library (features_test.cpp).
#pragma once

#include <string>

#include "costa/node.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "example_od.hpp"
#include "transcript_player.hpp"
#include "virtual_clock.hpp"

namespace costa::test {

class BareNodeBus : public TranscriptBus {
 public:
  /// Node-id 1, LSS asked for (bit rates of the CiA 305 table), parameters in a memory
  /// storage, the given profile (a quirk profile only in a build with them); powered on at the
  /// unit tests' virtual power-on time (1 s before the clock wraps).
  explicit BareNodeBus(const DeviceProfile& profile = DeviceProfile{});

  void send(const CanFrame& frame) override;
  bool receive(CanFrame* frame, int timeoutMs) override;
  void wait(uint64_t milliseconds) override;
  bool checksTiming() const override { return true; }
  std::string simulate(const std::string& command) override;

  Node& node() { return node_; }

 private:
  static NodeSettings settings(NvStorage* storage, const DeviceProfile& profile);
  /// Runs process() now, and again while it asks for an immediate call.
  void runProcess();

  port::RecordingCan can_;
  port::MemoryStorageOf<4096> storage_;
  NodeInstance<gen::example::Values, gen::example::Capacity> node_;
  replay::VirtualClock clock_{0xFFFFFFFFU - 999999U};
  size_t cursor_ = 0;
};

}  // namespace costa::test
