// A booted Santeng controller (node-id 1) on a virtual clock, heartbeat and TPDOs off so that
// tests see only the frames they ask for, with SDO helpers that check every reply.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "costa/od/little_endian.hpp"
#include "device_fixture.hpp"

namespace costa::test {

class SantengTest : public DeviceTest {
 protected:
  SantengTest() : DeviceTest("santeng", 1) {}

  void SetUp() override {
    ASSERT_EQ(play("tx 701 [1] 00"), "");
    ASSERT_EQ(sim("set heartbeat 0"), "");
    ASSERT_EQ(sim("set tpdo-rate 0"), "");
  }

  /// A simulation command (santeng_control.hpp): "" when done, else why not.
  std::string sim(const std::string& command) { return bus_.simulate(command); }

  /// Writes `value` to `index`:`sub` with a four-byte expedited download (0x23) and checks the
  /// download response.
  void write(uint16_t index, uint8_t sub, int32_t value) {
    EXPECT_EQ(play("rx 601 [8] " + request(0x23, index, sub, static_cast<uint32_t>(value)) +
                   "\ntx 581 [8] " + request(0x60, index, sub, 0)),
              "")
        << "write " << index << ":" << static_cast<int>(sub) << " = " << value;
  }

  /// The abort code of a four-byte write of `value`, 0 when it is accepted.
  uint32_t writeAbort(uint16_t index, uint8_t sub, int32_t value) {
    CanFrame frame = requestFrame(0x23, index, sub, static_cast<uint32_t>(value));
    bus_.send(frame);
    CanFrame reply;
    if (!bus_.receive(&reply, 0)) {
      ADD_FAILURE() << "no reply";
      return 0xFFFFFFFFU;
    }
    return reply.data[0] == 0x80U ? loadU32(reply.data + 4) : 0U;
  }

  int16_t read16(uint16_t index, uint8_t sub) {
    return static_cast<int16_t>(uploadFourBytes(index, sub, 0x4B));
  }
  int32_t read32(uint16_t index, uint8_t sub) {
    return static_cast<int32_t>(uploadFourBytes(index, sub, 0x43));
  }
  uint8_t read8(uint16_t index, uint8_t sub) {
    return static_cast<uint8_t>(uploadFourBytes(index, sub, 0x4F));
  }

  /// `milliseconds` pass on the virtual clock.
  void wait(uint64_t milliseconds) { bus_.wait(milliseconds); }

 private:
  static std::string request(uint8_t command, uint16_t index, uint8_t sub, uint32_t value) {
    char text[40];
    std::snprintf(text, sizeof(text), "%02X %02X %02X %02X %02X %02X %02X %02X", command,
                  index & 0xFFU, index >> 8U, sub, value & 0xFFU, (value >> 8U) & 0xFFU,
                  (value >> 16U) & 0xFFU, value >> 24U);
    return text;
  }
  static CanFrame requestFrame(uint8_t command, uint16_t index, uint8_t sub, uint32_t value) {
    CanFrame frame;
    frame.id = 0x601;
    frame.dlc = 8;
    frame.data[0] = command;
    storeU16(frame.data + 1, index);
    frame.data[3] = sub;
    storeU32(frame.data + 4, value);
    return frame;
  }
};

}  // namespace costa::test
