// A GRA on vcan without a node-id: an LSS master finds it by Fastscan, gives it a node-id, and
// the sensor then starts by itself and sends its angle TPDO on the new id. And its parameters
// survive a restart with --storage, a node-id saved by 0x5999:03 too when costa-slave is started
// without --node-id.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>

#include "lss_master.hpp"
#include "socket_bus.hpp"
#include "socket_lss_link.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

TEST(GefranOnVcan, FastscanFindsAnUnconfiguredGraAndGivesItANodeId) {
  SocketBus bus("gra", 255);
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText("sim angle 270", bus, kSocketReceiveTimeoutMs), "");
  SocketLink link(bus);
  LssMaster master(link);
  LssIdentity found;
  ASSERT_TRUE(master.fastscan(&found)) << bus.slave().output();
  EXPECT_EQ(found.vendorId, 0x93U);
  EXPECT_EQ(found.productCode, 0x64U);
  EXPECT_EQ(found.revisionNumber, 1U);
  EXPECT_EQ(master.configureNodeId(0x21), 0);
  master.switchGlobal(false);  // the sensor resets communication with node-id 0x21
  EXPECT_EQ(playText(R"(
    ignore 7E4
    ignore 1A1                             # the cyclic TPDO beyond the two checked here
    tx 721 [1] 00                          # boot-up on the new node-id
    tx 1A1 [8] 0A 8C 03 84 FF FF FF 00     # automatic start: the angle TPDO (270.0 / 90.0)
    tx 1A1 [8] 0A 8C 03 84 FF FF FF 00     # and every 100 ms
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

TEST(GefranOnVcan, SavedParametersSurviveARestart) {
  char directory[] = "/tmp/costa-gra-XXXXXX";
  const std::string path = std::string(::mkdtemp(directory)) + "/gra.nv";
  {
    SocketBus bus("gra", 3, {"--storage", path});
    ASSERT_EQ(bus.error(), "");
    EXPECT_EQ(playText(R"(
      ignore 183
      tx 703 [1] 00
      rx 603 [8] 2B 00 18 05 E8 03 00 00   # event timer 1000 ms
      tx 583 [8] 60 00 18 05 00 00 00 00
      rx 603 [8] 2F 01 50 00 01 00 00 00   # little endian
      tx 583 [8] 60 01 50 00 00 00 00 00
      rx 603 [8] 23 10 10 01 73 61 76 65   # "save"
      tx 583 [8] 60 10 10 01 00 00 00 00
    )",
                       bus, kSocketReceiveTimeoutMs),
              "");
    EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  }
  SocketBus bus("gra", 3, {"--storage", path});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    ignore 183
    tx 703 [1] 00
    rx 603 [8] 40 00 18 05 00 00 00 00
    tx 583 [8] 4B 00 18 05 E8 03 00 00     # kept
    rx 603 [8] 40 01 50 00 00 00 00 00
    tx 583 [8] 4F 01 50 00 01 00 00 00     # kept
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
}

TEST(GefranOnVcan, ASavedNodeIdAppliesWhenStartedWithoutNodeId) {
  char directory[] = "/tmp/costa-gra-XXXXXX";
  const std::string path = std::string(::mkdtemp(directory)) + "/gra.nv";
  {
    SocketBus bus("gra", -1, {"--storage", path});  // costa-slave --storage FILE gra
    ASSERT_EQ(bus.error(), "");
    EXPECT_EQ(playText(R"(
      ignore 1FF
      tx 77F [1] 00                        # the factory node-id 0x7F (E1)
      rx 67F [8] 2F 99 59 02 21 00 00 00   # 0x5999:02 = node-id 0x21
      tx 5FF [8] 60 99 59 02 00 00 00 00
      rx 67F [8] 23 99 59 03 73 61 76 65   # 0x5999:03 = "save"
      tx 5FF [8] 60 99 59 03 00 00 00 00
    )",
                       bus, kSocketReceiveTimeoutMs),
              "");
    EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
  }
  {
    SocketBus bus("gra", -1, {"--storage", path});
    ASSERT_EQ(bus.error(), "");
    EXPECT_EQ(playText(R"(
      ignore 1A1
      tx 721 [1] 00                        # boot-up on the stored node-id
      tx 1A1 [8] 00 00 00 00 FF FF FF 00   # automatic start on it
      rx 621 [8] 40 99 59 02 00 00 00 00
      tx 5A1 [8] 4F 99 59 02 21 00 00 00
    )",
                       bus, kSocketReceiveTimeoutMs),
              "");
    EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
  }
  SocketBus bus("gra", 3, {"--storage", path});  // --node-id wins, for the start only
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    ignore 183
    ignore 1A1
    tx 703 [1] 00
    rx 000 [2] 81 03                       # reset node: the stored node-id again
    tx 721 [1] 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

}  // namespace
}  // namespace costa::test
