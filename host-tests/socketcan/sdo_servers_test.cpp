// Two SDO clients at once against costa-slave over vcan: one on the default server
// (0x601/0x581), one on the example's additional server 0x1201 (given 0x681/0x6C1), each on its
// own raw socket and thread, uploading the 10 KiB scratch pad segment by segment.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdint.h>

#include <string>
#include <thread>
#include <vector>

#include "raw_socket.hpp"
#include "sdo_block_client.hpp"
#include "socket_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

constexpr int kTimeoutMs = 2000;

struct UploadResult {
  std::vector<uint8_t> data;
  std::string error;  ///< empty when the upload completed
};

/// A segmented upload of (index, sub) from the server at `request`/`response`, on a socket of
/// its own: frames on other CAN-IDs (the other client's) are skipped.
UploadResult segmentedUpload(uint32_t request, uint32_t response, uint16_t index, uint8_t sub) {
  UploadResult result;
  RawCanSocket socket;
  if (!socket.open(testInterface(), &result.error)) {
    return result;
  }
  auto exchange = [&](const uint8_t(&data)[8], CanFrame* answer) {
    CanFrame frame;
    frame.id = request;
    frame.dlc = 8;
    for (size_t i = 0; i < 8; ++i) {
      frame.data[i] = data[i];
    }
    if (!socket.send(frame)) {
      return false;
    }
    while (socket.receive(answer, kTimeoutMs)) {
      if (answer->id == response) {
        return true;
      }
    }
    return false;
  };
  CanFrame answer;
  const uint8_t initiate[8] = {0x40, static_cast<uint8_t>(index), static_cast<uint8_t>(index >> 8U),
                               sub};
  if (!exchange(initiate, &answer) || answer.data[0] != 0x41) {
    result.error = "initiate not answered with a segmented upload";
    return result;
  }
  const size_t size = answer.data[4] | (answer.data[5] << 8U) | (answer.data[6] << 16U);
  uint8_t toggle = 0;
  while (result.data.size() < size + 7U) {
    const uint8_t segment[8] = {static_cast<uint8_t>(0x60U | toggle)};
    if (!exchange(segment, &answer) || (answer.data[0] & 0xE0U) != 0U ||
        (answer.data[0] & 0x10U) != toggle) {
      result.error = "segment " + std::to_string(result.data.size() / 7U) + " not answered";
      return result;
    }
    const size_t count = 7U - ((answer.data[0] >> 1U) & 7U);
    result.data.insert(result.data.end(), answer.data + 1, answer.data + 1 + count);
    if ((answer.data[0] & 1U) != 0U) {
      break;
    }
    toggle ^= 0x10U;
  }
  if (result.data.size() != size) {
    result.error =
        "got " + std::to_string(result.data.size()) + " bytes of " + std::to_string(size);
  }
  return result;
}

TEST(SdoServersOnVcan, TwoClientsUploadAtOnceFromTwoServers) {
  SocketBus bus("example", 1);
  ASSERT_EQ(bus.error(), "");
  ASSERT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 23 01 12 01 81 06 00 00
    tx 581 [8] 60 01 12 01 00 00 00 00
    rx 601 [8] 23 01 12 02 C1 06 00 00
    tx 581 [8] 60 01 12 02 00 00 00 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  std::vector<uint8_t> data(10240);
  for (size_t i = 0; i < data.size(); ++i) {
    data[i] = static_cast<uint8_t>(i * 13U + 5U);
  }
  SdoBlockClient client(bus, 1, kSocketReceiveTimeoutMs);
  const BlockTransferResult down = client.download(0x2008, 0, data);
  ASSERT_TRUE(down.ok()) << down.error << " abort " << std::hex << down.abortCode;

  UploadResult fromDefault;
  UploadResult fromSecond;
  std::thread a([&] { fromDefault = segmentedUpload(0x601, 0x581, 0x2008, 0); });
  std::thread b([&] { fromSecond = segmentedUpload(0x681, 0x6C1, 0x2008, 0); });
  a.join();
  b.join();
  EXPECT_EQ(fromDefault.error, "");
  EXPECT_EQ(fromSecond.error, "");
  EXPECT_EQ(fromDefault.data, data);
  EXPECT_EQ(fromSecond.data, data);
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

}  // namespace
}  // namespace costa::test
