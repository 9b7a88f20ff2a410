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

  /// The four data bytes (little-endian) of an expedited SDO upload of `index`:`subIndex`
  /// whose response has command byte `command` (0x43 for four bytes by CiA 301; 0x42 on a
  /// device that never indicates the size). A missing or different response is a test failure
  /// and gives 0.
  uint32_t uploadFourBytes(uint16_t index, uint8_t subIndex, uint8_t command) {
    CanFrame request;
    request.id = 0x600U + static_cast<uint32_t>(nodeId_);
    request.dlc = 8;
    request.data[0] = 0x40;
    request.data[1] = static_cast<uint8_t>(index & 0xFFU);
    request.data[2] = static_cast<uint8_t>(index >> 8U);
    request.data[3] = subIndex;
    bus_.send(request);
    CanFrame response;
    if (!bus_.receive(&response, 0) || response.id != 0x580U + static_cast<uint32_t>(nodeId_) ||
        response.dlc != 8U || response.data[0] != command || response.data[1] != request.data[1] ||
        response.data[2] != request.data[2] || response.data[3] != subIndex) {
      ADD_FAILURE() << "no upload response with command " << static_cast<int>(command)
                    << " for object " << index << " sub " << static_cast<int>(subIndex);
      return 0;
    }
    return static_cast<uint32_t>(response.data[4]) |
           (static_cast<uint32_t>(response.data[5]) << 8U) |
           (static_cast<uint32_t>(response.data[6]) << 16U) |
           (static_cast<uint32_t>(response.data[7]) << 24U);
  }

  InProcessBus bus_;
  int nodeId_;
};

}  // namespace costa::test
