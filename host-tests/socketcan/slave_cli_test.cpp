// costa-slave as a process on vcan: clean shutdown, the trace, and its error paths.
#include <gtest/gtest.h>

#include <signal.h>
#include <sstream>

#include <chrono>
#include <thread>

#include "frame_text.hpp"
#include "socket_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

int countLines(const std::string& text) {
  int lines = 0;
  for (const char c : text) {
    lines += c == '\n' ? 1 : 0;
  }
  return lines;
}

TEST(SlaveProcessOnVcan, StopsCleanlyOnSigtermAndSigint) {
  for (const int signal : {SIGTERM, SIGINT}) {
    SocketBus bus("example", 7);
    ASSERT_EQ(bus.error(), "");
    EXPECT_EQ(playText("tx 707 [1] 00", bus, kSocketReceiveTimeoutMs), "");
    EXPECT_EQ(bus.slave().stop(signal), 0) << bus.slave().output();
    EXPECT_NE(bus.slave().output().find("costa-slave: stopped"), std::string::npos);
  }
}

TEST(SlaveProcessOnVcan, TraceShowsEveryFrameWithItsMeaning) {
  SocketBus bus("example", 1, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 40 08 10 00 00 00 00 00
    tx 581 [8] 41 08 10 00 0D 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 43 6F 73 74 61 20 65
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 13 78 61 6D 70 6C 65 00
    rx 601 [8] 2B 17 10 00 E8 03 00 00
    tx 581 [8] 60 17 10 00 00 00 00 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  EXPECT_NE(output.find("tx 701 [1] 00"), std::string::npos) << output;
  EXPECT_NE(output.find("boot-up"), std::string::npos) << output;
  EXPECT_NE(output.find("rx 601 [8] 40 08 10 00 00 00 00 00"), std::string::npos) << output;
  EXPECT_NE(output.find("SDO upload 0x1008:00"), std::string::npos) << output;
  EXPECT_NE(output.find("0x1008:00 = \"Costa example\""), std::string::npos) << output;
  EXPECT_NE(output.find("SDO download 0x1017:00 = 1000"), std::string::npos) << output;
}

TEST(SlaveProcessOnVcan, TraceShowsTheIndicatorsOfEachNode) {
  SocketBus bus(SlaveNodes{{"example@1", "solo@2"}}, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    tx 702 [1] 00
    rx 000 [2] 01 02                     # node 2 operational
    rx 000 [2] 02 01                     # node 1 stopped
    rx 601 [8] 40 00 10 00 00 00 00 00   # (an answer shows that both have seen their command)
    rx 602 [8] 40 00 10 00 00 00 00 00
    tx 582 [8] xx 00 10 00 xx xx xx xx
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  // A line of the node with "indicators" and the states after it.
  const auto shows = [&output](const std::string& node, const std::string& states) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
      const size_t at = line.find(node + " -- indicators ");
      if (at != std::string::npos && line.size() >= states.size() &&
          line.compare(line.size() - states.size(), states.size(), states) == 0) {
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(shows("@01", "RUN blinking, ERROR off")) << output;
  EXPECT_TRUE(shows("@02", "RUN on, ERROR off")) << output;
  EXPECT_TRUE(shows("@01", "RUN single flash, ERROR off")) << output;
}

TEST(SlaveProcessOnVcan, TraceReportsTheBitRateTheNodeSwitchedTo) {
  SocketBus bus("gra", 3, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    ignore 183
    tx 703 [1] 00
    rx 603 [8] 2B 99 59 01 F4 01 00 00     # 0x5999:01 = 500 kbit/s
    tx 583 [8] 60 99 59 01 00 00 00 00
    rx 603 [8] 23 99 59 03 73 61 76 65     # "save"
    tx 583 [8] 60 99 59 03 00 00 00 00
    rx 000 [2] 81 03                       # reset node: the saved rate applies
    tx 703 [1] 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  const size_t reset = output.find("rx 000 [2] 81 03");
  const size_t rate = output.find("bit rate now 500 kbit/s");
  ASSERT_NE(reset, std::string::npos) << output;
  ASSERT_NE(rate, std::string::npos) << output;
  EXPECT_LT(reset, rate) << output;
  EXPECT_EQ(output.find("bit rate now", rate + 1), std::string::npos) << output;  // once
}

TEST(SlaveProcessOnVcan, SoloSpeedReferenceBecomesARampingSpeedFeedbackTpdo) {
  SocketBus bus("solo", 1, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 22 15 30 00 01 00 00 00
    tx 581 [8] 60 15 30 00 00 00 00 00
    rx 601 [8] 22 16 30 00 00 00 00 00
    tx 581 [8] 60 16 30 00 00 00 00 00
    rx 601 [8] 22 02 30 00 01 00 00 00
    tx 581 [8] 60 02 30 00 00 00 00 00
    rx 601 [8] 22 15 18 01 81 02 00 C0
    tx 581 [8] 60 15 18 01 00 00 00 00
    rx 601 [8] 22 15 18 02 01 00 00 00
    tx 581 [8] 60 15 18 02 00 00 00 00
    rx 000 [2] 01 01
    rx 601 [8] 22 2A 30 00 00 00 14 00
    tx 581 [8] 60 2A 30 00 00 00 00 00
    rx 601 [8] 22 05 30 00 E8 03 00 00
    tx 581 [8] 60 05 30 00 00 00 00 00
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  int32_t previous = -1;
  for (int i = 0; i < 4; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    CanFrame sync;
    sync.id = 0x080;
    bus.send(sync);
    CanFrame frame;
    ASSERT_TRUE(bus.receive(&frame, kSocketReceiveTimeoutMs));
    ASSERT_EQ(host::formatFrame(frame).substr(0, 7), "281 [4]");
    const auto rpm = static_cast<int32_t>(
        static_cast<uint32_t>(frame.data[0]) | static_cast<uint32_t>(frame.data[1]) << 8U |
        static_cast<uint32_t>(frame.data[2]) << 16U | static_cast<uint32_t>(frame.data[3]) << 24U);
    // 10 rev/s^2: 600 rpm/s, ramping towards 1000 rpm (reached after 1.7 s; a slow machine
    // may get there within these four samples, and then it stays there).
    EXPECT_TRUE(rpm > previous || (rpm == 1000 && previous == 1000))
        << rpm << " after " << previous;
    EXPECT_LE(rpm, 1000);
    previous = rpm;
  }
  EXPECT_GT(previous, 300);
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  EXPECT_NE(output.find("SDO download 0x3005:00 = 1000"), std::string::npos) << output;
  EXPECT_NE(output.find("tx 281 [4]"), std::string::npos) << output;
}

TEST(SlaveProcessOnVcan, UnknownInterfaceIsOneLineAndNonZero) {
  SlaveProcess slave({"--iface", "nosuchcan0", "example"});
  const int status = slave.waitExit(kSlaveExitTimeoutMs);
  EXPECT_EQ(status, 1);
  EXPECT_EQ(slave.output(), "costa-slave: no such CAN interface: nosuchcan0\n");
}

TEST(SlaveCommandLine, BadArgumentsAreOneLineAndNonZero) {
  struct Case {
    std::vector<std::string> arguments;
    const char* message;
  };
  const Case cases[] = {
      {{"toaster"}, "costa-slave: unknown device 'toaster'"},
      {{"--node-id", "0", "example"},
       "costa-slave: invalid node-id '0': expected 1..127 (or 255: unconfigured, LSS only)\n"},
      {{"--node-id", "300", "example"},
       "costa-slave: invalid node-id '300': expected 1..127 (or 255: unconfigured, LSS only)\n"},
      {{}, "costa-slave: no DEVICE given"},
      {{"--node-id", "127", "santeng"},
       "costa-slave: invalid node-id 127 for santeng: it takes 1..126\n"},
  };
  for (const Case& c : cases) {
    SlaveProcess slave(c.arguments);
    EXPECT_EQ(slave.waitExit(kSlaveExitTimeoutMs), 2);
    const std::string output = slave.output();
    EXPECT_EQ(output.rfind(c.message, 0), 0U) << output;
    EXPECT_EQ(countLines(output), 1) << output;
  }
}

TEST(SlaveCommandLine, HelpListsTheInterface) {
  SlaveProcess slave({"--help"});
  EXPECT_EQ(slave.waitExit(kSlaveExitTimeoutMs), 0);
  EXPECT_NE(slave.output().find("--iface NAME"), std::string::npos);
}

}  // namespace
}  // namespace costa::test
