// The M-series joint as costa-slave runs it on vcan, under its public name `m-series`: RPDO3
// answered by TPDO3 while the speed ramps to 600 r/min, the stop with heartbeat 04 when node
// 0x7F's heartbeats stop and the resume when they return; and the manual's interpolation
// (5.10.3) with three costa-slave processes, node-ids 1..3, moved by one SYNC.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>

#include <chrono>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include "frame_text.hpp"
#include "socket_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

CanFrame frameOf(const char* text) {
  CanFrame frame;
  std::string error;
  EXPECT_TRUE(host::parseFrame(text, &frame, &error)) << error;
  return frame;
}

int32_t littleEndian32(const CanFrame& frame, size_t at) {
  return static_cast<int32_t>(static_cast<uint32_t>(frame.data[at]) |
                              static_cast<uint32_t>(frame.data[at + 1U]) << 8U |
                              static_cast<uint32_t>(frame.data[at + 2U]) << 16U |
                              static_cast<uint32_t>(frame.data[at + 3U]) << 24U);
}

/// The next frame on `id`, skipping others (heartbeats); false after the timeout.
bool nextOn(SocketBus& bus, uint32_t id, CanFrame* frame) {
  const auto end =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(kSocketReceiveTimeoutMs);
  while (std::chrono::steady_clock::now() < end) {
    if (bus.receive(frame, kSocketReceiveTimeoutMs) && frame->id == id) {
      return true;
    }
  }
  return false;
}

void sleepMs(int milliseconds) {
  std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
}

TEST(JointOnVcan, Rpdo3AnsweredWhileRampingStopAndResumeWithTheMastersHeartbeat) {
  SocketBus bus("m-series", -1, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  ASSERT_EQ(playText("tx 701 [1] 00", bus, kSocketReceiveTimeoutMs), "");
  // 600 r/min at 20000 (r/min)/s: 30 ms of ramp; each RPDO3 is answered by its TPDO3.
  int32_t previous = -1;
  int32_t speed = 0;
  for (int i = 0; i < 20 && speed < 600; ++i) {
    bus.send(frameOf("401 [7] 0F 00 03 58 02 00 00"));
    CanFrame answer;
    ASSERT_TRUE(nextOn(bus, 0x381, &answer));
    ASSERT_EQ(answer.dlc, 6U);
    speed = littleEndian32(answer, 0);
    EXPECT_GE(speed, previous);
    EXPECT_LE(speed, 600);
    const bool reached = (answer.data[5] & 0x04U) != 0U;
    EXPECT_EQ(reached, speed == 600) << "status " << host::formatFrame(answer);
    previous = speed;
    sleepMs(5);
  }
  EXPECT_EQ(speed, 600);
  // The master's heartbeat, then none: alarm 0x20, the joint stops, its heartbeat says 04.
  bus.send(frameOf("77F [1] 05"));
  CanFrame heartbeat;
  bool alarmed = false;
  for (int i = 0; i < 5 && !alarmed; ++i) {
    ASSERT_TRUE(nextOn(bus, 0x701, &heartbeat));
    alarmed = heartbeat.data[0] == 0x04U;
  }
  EXPECT_TRUE(alarmed);
  bus.send(frameOf("601 [8] 40 6C 60 00 00 00 00 00"));
  CanFrame reply;
  ASSERT_TRUE(nextOn(bus, 0x581, &reply));
  EXPECT_EQ(host::formatFrame(reply), "581 [8] 43 6C 60 00 00 00 00 00");  // stopped
  // The master is back: the alarm clears, the joint ramps to 600 r/min again.
  bus.send(frameOf("77F [1] 05"));
  sleepMs(200);
  bus.send(frameOf("77F [1] 05"));
  bus.send(frameOf("601 [8] 40 6C 60 00 00 00 00 00"));
  ASSERT_TRUE(nextOn(bus, 0x581, &reply));
  EXPECT_EQ(host::formatFrame(reply), "581 [8] 43 6C 60 00 58 02 00 00");
  bus.send(frameOf("77F [1] 05"));
  ASSERT_TRUE(nextOn(bus, 0x701, &heartbeat));
  EXPECT_EQ(heartbeat.data[0], 0x05U);
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  EXPECT_NE(output.find("heartbeat: an error is active"), std::string::npos) << output;
  EXPECT_NE(output.find("tx 381 [6] 58 02 00 00 37 04"), std::string::npos) << output;
}

TEST(JointsOnVcan, OneSyncMovesThreeJoints) {
  // Joint 1's bus receives every joint's frames; joints 2 and 3 run beside it.
  std::unique_ptr<SocketBus> joints[3];
  const char* positions[3] = {"position 3448", "position 6221", "position 10600"};
  for (int i = 0; i < 3; ++i) {
    joints[i] = std::make_unique<SocketBus>("m-series", i + 1);
    ASSERT_EQ(joints[i]->error(), "");
  }
  SocketBus& bus = *joints[0];
  sleepMs(300);  // every process is up
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(joints[i]->simulate(positions[i]), "");
  }
  const auto answers = [&bus](uint32_t base, const std::set<std::string>& expected) {
    std::set<std::string> got;
    CanFrame frame;
    while (got.size() < expected.size() && bus.receive(&frame, kSocketReceiveTimeoutMs)) {
      if (frame.id > base && frame.id <= base + 3U) {
        got.insert(host::formatFrame(frame));
      }
    }
    EXPECT_EQ(got, expected);
  };
  bus.send(frameOf("201 [7] 0F 00 07 78 0D 00 00"));  // enable, mode 7 (an addition)
  bus.send(frameOf("202 [7] 0F 00 07 4D 18 00 00"));
  bus.send(frameOf("203 [7] 0F 00 07 68 29 00 00"));
  answers(0x180,
          {"181 [6] 78 0D 00 00 37 04", "182 [6] 4D 18 00 00 37 04", "183 [6] 68 29 00 00 37 04"});
  bus.send(frameOf("501 [4] 50 C3 00 00"));  // lines 738-741, one RPDO4 each (W13)
  bus.send(frameOf("502 [4] 50 C3 00 00"));
  bus.send(frameOf("503 [4] 50 C3 00 00"));
  answers(0x480,
          {"481 [6] 78 0D 00 00 37 04", "482 [6] 4D 18 00 00 37 04", "483 [6] 68 29 00 00 37 04"});
  bus.send(frameOf("080 [0]"));  // line 742: all three move
  sleepMs(400);
  for (const char* read : {"601 [8] 40 64 60 00 00 00 00 00", "602 [8] 40 64 60 00 00 00 00 00",
                           "603 [8] 40 64 60 00 00 00 00 00"}) {
    bus.send(frameOf(read));
  }
  answers(0x580, {"581 [8] 43 64 60 00 50 C3 00 00", "582 [8] 43 64 60 00 50 C3 00 00",
                  "583 [8] 43 64 60 00 50 C3 00 00"});
  for (auto& joint : joints) {
    EXPECT_EQ(joint->slave().stop(SIGTERM), 0) << joint->slave().output();
  }
}

TEST(JointOnVcan, ASavedNodeIdIsTheNextRunsWithStorage) {
  char directory[] = "/tmp/costa-joint-XXXXXX";
  const char* made = ::mkdtemp(directory);
  ASSERT_NE(made, nullptr);
  const std::string path = std::string(made) + "/joint.nv";
  {
    SocketBus bus("m-series", -1, {"--storage", path});
    ASSERT_EQ(bus.error(), "");
    EXPECT_EQ(playText(R"(
      tx 701 [1] 00
      rx 601 [8] 2B 15 26 00 05 00 00 00   # node-id 5 (line 374)
      tx 581 [8] 60 15 26 00 00 00 00 00
      rx 601 [8] 2B 14 26 00 01 00 00 00   # save (line 271)
      tx 581 [8] 60 14 26 00 00 00 00 00
      rx 601 [8] 40 14 26 00 00 00 00 00   # reads 2 (line 273)
      tx 581 [8] 4B 14 26 00 02 00 00 00
    )",
                       bus, kSocketReceiveTimeoutMs),
              "");
    EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  }
  SocketBus bus("m-series", -1, {"--storage", path});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    tx 705 [1] 00                          # the next power-on: node-id 5
    rx 205 [7] 0F 00 01 00 00 00 00        # RPDO1 and TPDO1 followed it
    tx 185 [6] 00 00 00 00 37 04
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
}

TEST(JointCommandLine, ListDevicesShowsThePublicName) {
  SlaveProcess slave({"--list-devices"});
  EXPECT_EQ(slave.waitExit(kSlaveExitTimeoutMs), 0);
  EXPECT_NE(slave.output().find("mseries    M-series robot joint"), std::string::npos)
      << slave.output();
  EXPECT_NE(slave.output().find("(also: m-series)"), std::string::npos) << slave.output();
}

}  // namespace
}  // namespace costa::test
