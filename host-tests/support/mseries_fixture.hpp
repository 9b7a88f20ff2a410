// A booted M-series joint (node-id 1 unless given) on a virtual clock, for unit tests; and one
// that can be powered off and on again over the same parameter memory.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "device_fixture.hpp"
#include "device_target.hpp"
#include "mseries_target.hpp"

namespace costa::test {

class JointTest : public DeviceTest {
 protected:
  explicit JointTest(int nodeId = 1) : DeviceTest("mseries", nodeId) {}
  void SetUp() override { ASSERT_EQ(play("tx " + std::to_string(700 + nodeId_) + " [1] 00"), ""); }

  mseries::MSeriesTarget& joint() {
    return static_cast<host::HostedTarget<mseries::MSeriesTarget>&>(bus_.target()).composition();
  }
};

/// A joint that is switched off and on again over the same parameter memory, as costa-slave
/// --storage FILE m-series does across runs (without --node-id).
class JointPowerCycle : public ::testing::Test {
 protected:
  void powerOn() {
    bus_.reset();
    bus_ = std::make_unique<InProcessBus>([this](CanTransmitter& can) {
      return std::make_unique<host::HostedTarget<mseries::MSeriesTarget>>(
          nullptr, can, DeviceConfig{0, false, &memory_, nullptr});
    });
  }
  std::string play(const std::string& text) { return playText(text, *bus_); }

  port::MemoryStorageOf<mseries::MSeriesTarget::kStorageBytes> memory_;
  std::unique_ptr<InProcessBus> bus_;
};

}  // namespace costa::test
