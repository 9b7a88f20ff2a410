// The example device (node-id 1, booted) with a block transfer client, for tests of whole block
// transfers. The scratch pad (0x2008, a DOMAIN streamed by the device, up to 12 kB) takes
// large values.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "device_target.hpp"
#include "example_target.hpp"
#include "in_process_bus.hpp"
#include "sdo_block_client.hpp"
#include "transcript_player.hpp"

namespace costa::test {

inline constexpr uint16_t kScratchPad = 0x2008;
inline constexpr uint32_t kCrcError = 0x05040004;

/// `size` bytes that differ from their neighbours and repeat only every 251 * 256 bytes.
inline std::vector<uint8_t> pattern(size_t size) {
  std::vector<uint8_t> data(size);
  for (size_t i = 0; i < size; ++i) {
    data[i] = static_cast<uint8_t>((i * 7U + i / 251U) & 0xFFU);
  }
  return data;
}

class BlockTransferTest : public ::testing::Test {
 protected:
  BlockTransferTest() : bus_("example", 1), client_(bus_, 1) {}

  void SetUp() override { ASSERT_EQ(playText("tx 701 [1] 00", bus_), ""); }

  example::ExampleTarget& device() {
    return dynamic_cast<host::HostedTarget<example::ExampleTarget>&>(bus_.target()).composition();
  }
  std::vector<uint8_t> scratchPad() {
    const uint8_t* data = device().scratchPad();
    return std::vector<uint8_t>(data, data + device().scratchPadLength());
  }
  /// The server sent nothing the client did not read.
  void expectSilence() { EXPECT_EQ(bus_.unread(), 0U); }

  InProcessBus bus_;
  SdoBlockClient client_;
};

}  // namespace costa::test
