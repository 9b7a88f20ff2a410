// A booted example node (node-id 1) on a virtual clock, for unit tests.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "allocation_guard.hpp"
#include "costa/od/little_endian.hpp"
#include "device_target.hpp"
#include "example_with_settings.hpp"
#include "in_process_bus.hpp"
#include "transcript_player.hpp"

/// Plays transcript lines against the fixture's node; the report names the failing line.
#define EXPECT_TRANSCRIPT(text) EXPECT_EQ(play(text), "")

namespace costa::test {

/// TPDO1 of the example given an inhibit time of 50 ms (set while not valid), then operational.
inline constexpr const char* kTpdo1Inhibit50ms = R"(
    rx 601 [8] 23 00 18 01 81 01 00 80   # invalidate
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 601 [8] 2B 00 18 03 F4 01 00 00   # inhibit 500 x 100 us = 50 ms
    tx 581 [8] 60 00 18 03 00 00 00 00
    rx 601 [8] 23 00 18 01 81 01 00 00   # valid again
    tx 581 [8] 60 00 18 01 00 00 00 00
    rx 000 [2] 01 01
)";

/// The example's behaviour on a node with explicit settings (for profile-specific behaviour).
inline InProcessBus::Factory exampleWith(const NodeSettings& settings) {
  return [settings](CanTransmitter& can) -> std::unique_ptr<host::DeviceTarget> {
    return std::make_unique<host::HostedTarget<ExampleWithSettings>>(nullptr, can, settings);
  };
}

/// The example device as it is, configured by `config` (as costa-slave or firmware give it).
inline InProcessBus::Factory exampleWith(const DeviceConfig& config) {
  return [config](CanTransmitter& can) -> std::unique_ptr<host::DeviceTarget> {
    return std::make_unique<host::HostedTarget<example::ExampleTarget>>(nullptr, can, config);
  };
}

class ExampleNodeTest : public ::testing::Test {
 protected:
  ExampleNodeTest() : bus_("example", 1) {}
  explicit ExampleNodeTest(const NodeSettings& settings) : bus_(exampleWith(settings)) {}

  void SetUp() override { ASSERT_EQ(play("tx 701 [1] 00"), ""); }

  /// Plays transcript lines (see transcript.hpp) against the node.
  std::string play(const std::string& text) { return playText(text, bus_); }

  /// Little-endian numeric value of an entry, read straight from the dictionary.
  uint64_t value(uint16_t index, uint8_t subIndex) {
    return bus_.node().dictionary().readUnsigned(index, subIndex, 0xDEADBEEFU);
  }

  /// Runs `action` on the node inside a no-allocation scope, then lets the node transmit.
  template <typename Action>
  void withNode(Action action) {
    {
      NoAllocationScope scope;
      action(bus_.node());
    }
    bus_.advance(0);
  }

  InProcessBus bus_;
};

}  // namespace costa::test
