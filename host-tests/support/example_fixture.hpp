// A booted example node (node-id 1) on a virtual clock, for unit tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "costa/od/little_endian.hpp"
#include "in_process_bus.hpp"
#include "transcript_player.hpp"

/// Plays transcript lines against the fixture's node; the report names the failing line.
#define EXPECT_TRANSCRIPT(text) EXPECT_EQ(play(text), "")

namespace costa::test {

class ExampleNodeTest : public ::testing::Test {
 protected:
  ExampleNodeTest() : bus_("example", 1) {}

  void SetUp() override { ASSERT_EQ(play("tx 701 [1] 00"), ""); }

  /// Plays transcript lines (see transcript.hpp) against the node.
  std::string play(const std::string& text) { return playText(text, bus_); }

  /// Little-endian numeric value of an entry, read straight from the dictionary.
  uint64_t value(uint16_t index, uint8_t subIndex) {
    return bus_.node().dictionary().readUnsigned(index, subIndex, 0xDEADBEEFU);
  }

  InProcessBus bus_;
};

}  // namespace costa::test
