// SDO block transfer with costa-slave over vcan, through the test's raw socket.
#include <gtest/gtest.h>
#include <signal.h>

#include <string>
#include <vector>

#include "sdo_block_client.hpp"
#include "socket_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

TEST(BlockTransferOnVcan, UploadsTheDeviceName) {
  SocketBus bus("example", 1);
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] A4 08 10 00 7F 00 00 00
    tx 581 [8] C6 08 10 00 0D 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 43 6F 73 74 61 20 65
    tx 581 [8] 82 78 61 6D 70 6C 65 00
    rx 601 [8] A2 02 7F 00 00 00 00 00
    tx 581 [8] C5 32 17 00 00 00 00 00
    rx 601 [8] A1 00 00 00 00 00 00 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

TEST(BlockTransferOnVcan, ScratchPadRoundTripOfTenKilobytes) {
  SocketBus bus("example", 1);
  ASSERT_EQ(bus.error(), "");
  ASSERT_EQ(playText("tx 701 [1] 00", bus, kSocketReceiveTimeoutMs), "");
  std::vector<uint8_t> data(10240);
  for (size_t i = 0; i < data.size(); ++i) {
    data[i] = static_cast<uint8_t>(i * 13U + 5U);
  }
  SdoBlockClient client(bus, 1, kSocketReceiveTimeoutMs);
  const BlockTransferResult down = client.download(0x2008, 0, data);
  EXPECT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;
  const BlockTransferResult up = client.upload(0x2008, 0);
  EXPECT_TRUE(up.ok()) << up.error << " abort " << std::hex << up.abortCode;
  EXPECT_EQ(up.data, data);
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

}  // namespace
}  // namespace costa::test
