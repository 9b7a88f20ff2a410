// The Santeng as costa-slave runs it on vcan (docs/errata-santeng.md): --trace shows its
// heartbeats, a speed command ramping 0x2103 and a 7-byte request answered with 8 bytes; its
// configuration saved with 0x2017 comes back after a restart with --storage.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

#include "socket_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

/// Reads 0x2103:01 (channel 1's speed, RPM) through `bus`.
int readSpeed(SocketBus& bus) {
  CanFrame request;
  request.id = 0x601;
  request.dlc = 8;
  const uint8_t upload[8] = {0x40, 0x03, 0x21, 0x01, 0, 0, 0, 0};
  std::copy(upload, upload + 8, request.data);
  bus.send(request);
  for (int i = 0; i < 20; ++i) {
    CanFrame reply;
    if (!bus.receive(&reply, kSocketReceiveTimeoutMs)) {
      break;
    }
    if (reply.id == 0x581U && reply.data[0] == 0x4BU) {
      return static_cast<int16_t>(reply.data[4] | (reply.data[5] << 8U));
    }  // heartbeats and TPDOs in between
  }
  ADD_FAILURE() << "no answer to the read of 0x2103:01";
  return -1;
}

TEST(SantengOnVcan, TraceShowsHeartbeatsARampAndAShortRequest) {
  SocketBus bus("santeng", 1, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    ignore 181
    ignore 281
    ignore 381
    ignore 481
    tx 701 [1] 00
    tx 701 [1] 05                          # operational by itself, every 1000 ms
    tx 701 [1] 05
    rx 601 [8] 23 06 20 01 D0 07 00 00     # 0x2006:01 = 2000: 200 RPM/s
    tx 581 [8] 60 06 20 01 00 00 00 00
    rx 601 [8] 23 00 20 01 E8 03 00 00     # 0x2000:01 = 1000
    tx 581 [8] 60 00 20 01 00 00 00 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  int previous = 0;
  for (int i = 0; i < 3; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const int rpm = readSpeed(bus);
    EXPECT_GT(rpm, previous);  // ramping towards 1000 RPM
    EXPECT_LT(rpm, 1000);
    previous = rpm;
  }
  EXPECT_EQ(playText(R"(
    ignore 701
    ignore 181
    ignore 281
    ignore 381
    ignore 481
    rx 601 [7] 23 01 20 01 00 09 34        # manual line 394
    tx 581 [8] 60 01 20 01 00 00 00 00
    rx 601 [8] 2B 00 20 01 00 00 00 00
    tx 581 [8] 60 00 20 01 00 00 00 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  EXPECT_NE(output.find("tx 701 [1] 05"), std::string::npos) << output;
  EXPECT_NE(output.find("SDO download 0x2000:01 = 1000"), std::string::npos) << output;
  EXPECT_NE(output.find("SDO upload response 0x2103:01"), std::string::npos) << output;
  EXPECT_NE(output.find("rx 601 [7] 23 01 20 01 00 09 34"), std::string::npos) << output;
  EXPECT_NE(output.find("SDO download 0x2001:01 = 3410176 (7 bytes, the rest taken as 0)"),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("tx 581 [8] 60 01 20 01 00 00 00 00"), std::string::npos) << output;
}

TEST(SantengOnVcan, TheConfigurationSavedBy2017SurvivesARestart) {
  char directory[] = "/tmp/costa-santeng-XXXXXX";
  const std::string path = std::string(::mkdtemp(directory)) + "/santeng.nv";
  {
    SocketBus bus("santeng", -1, {"--storage", path});  // costa-slave --storage FILE santeng
    ASSERT_EQ(bus.error(), "");
    EXPECT_EQ(playText(R"(
      ignore 701
      ignore 181
      ignore 281
      ignore 381
      ignore 481
      tx 701 [1] 00                        # node-id 1 (line 126)
      sim set node-id 5
      sim set auto-start off
      sim set tpdo-rate 0
      rx 601 [8] 2F 17 20 00 00 00 00 00   # 0x2017: save
      tx 581 [8] 60 17 20 00 00 00 00 00
    )",
                       bus, kSocketReceiveTimeoutMs),
              "");
    EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
  }
  SocketBus bus("santeng", -1, {"--storage", path});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    tx 705 [1] 00                          # the saved node-id
    tx 705 [1] 7F                          # and no automatic start: pre-operational
    rx 605 [8] 40 00 18 05 00 00 00 00     # TPDOs off, as saved
    tx 585 [8] 4B 00 18 05 00 00 00 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

}  // namespace
}  // namespace costa::test
