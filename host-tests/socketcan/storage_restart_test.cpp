// Parameters kept by --storage across a restart of the costa-slave process.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "socket_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

std::string temporaryPath(const char* name) {
  char directory[] = "/tmp/costa-storage-XXXXXX";
  const char* made = ::mkdtemp(directory);
  return std::string(made != nullptr ? made : "/tmp") + "/" + name;
}

std::string runSlave(const std::string& device, const std::string& path, const char* transcript) {
  SocketBus bus(device, 1, {"--storage", path});
  if (!bus.error().empty()) {
    return bus.error();
  }
  const std::string result = playText(transcript, bus, kSocketReceiveTimeoutMs);
  const int status = bus.slave().stop(SIGTERM);
  if (status != 0) {
    return "costa-slave exit status " + std::to_string(status) + ": " + bus.slave().output();
  }
  return result.empty() ? "" : result + "\n" + bus.slave().output();
}

TEST(SlaveStorage, ExampleParametersSurviveARestartOnlyOnceSaved) {
  const std::string path = temporaryPath("example.nv");
  EXPECT_EQ(runSlave("example", path, R"(
    tx 701 [1] 00
    rx 601 [8] 23 00 20 00 20 4E 00 00   # setpoint 20000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 601 [8] 23 10 10 01 73 61 76 65   # "save"
    tx 581 [8] 60 10 10 01 00 00 00 00
    rx 601 [8] 23 00 20 00 30 75 00 00   # 30000, not saved
    tx 581 [8] 60 00 20 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(runSlave("example", path, R"(
    tx 701 [1] 00
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 20 4E 00 00   # the saved value
    rx 601 [8] 23 11 10 01 6C 6F 61 64   # "load": defaults from the next start on
    tx 581 [8] 60 11 10 01 00 00 00 00
  )"),
            "");
  EXPECT_EQ(runSlave("example", path, R"(
    tx 701 [1] 00
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 E8 03 00 00   # default 1000
  )"),
            "");
}

TEST(SlaveStorage, SoloKeepsItsMObjectsButNotItsVObjects) {
  const std::string path = temporaryPath("solo.nv");
  EXPECT_EQ(runSlave("solo", path, R"(
    tx 701 [1] 00
    rx 601 [8] 22 11 30 00 F4 01 00 00   # speed limit 500 rpm (M)
    tx 581 [8] 60 11 30 00 00 00 00 00
    rx 601 [8] 22 05 30 00 E8 03 00 00   # speed reference 1000 rpm (V)
    tx 581 [8] 60 05 30 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(runSlave("solo", path, R"(
    tx 701 [1] 00
    rx 601 [8] 40 11 30 00 00 00 00 00
    tx 581 [8] 42 11 30 00 F4 01 00 00   # kept
    rx 601 [8] 40 05 30 00 00 00 00 00
    tx 581 [8] 42 05 30 00 00 00 00 00   # back to 0
  )"),
            "");
}

}  // namespace
}  // namespace costa::test
