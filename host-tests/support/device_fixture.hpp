// A booted device of any registered kind on a virtual clock, for unit tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "allocation_guard.hpp"
#include "in_process_bus.hpp"
#include "transcript_player.hpp"

#ifndef EXPECT_TRANSCRIPT
/// Plays transcript lines against the fixture's node; the report names the failing line.
#define EXPECT_TRANSCRIPT(text) EXPECT_EQ(play(text), "")
#endif

namespace costa::test {

class DeviceTest : public ::testing::Test {
 protected:
  DeviceTest(const std::string& device, int nodeId) : bus_(device, nodeId), nodeId_(nodeId) {}

  std::string play(const std::string& text) { return playText(text, bus_); }

  uint64_t value(uint16_t index, uint8_t subIndex) {
    return bus_.node().dictionary().readUnsigned(index, subIndex, 0xDEADBEEFU);
  }
  int64_t signedValue(uint16_t index, uint8_t subIndex) {
    return static_cast<int64_t>(value(index, subIndex));
  }

  InProcessBus bus_;
  int nodeId_;
};

}  // namespace costa::test
