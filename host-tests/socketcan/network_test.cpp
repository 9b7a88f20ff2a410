// Several nodes in one costa-slave on vcan: their boot-ups and SDO servers, the manual's
// interpolation (M-series 5.10.3) with three joints moved by one SYNC, a heartbeat consumer of
// one node watching another node of the process, an LSS Fastscan that tells two unconfigured
// nodes apart by their serial numbers, a storage file per node, and the command line's errors.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <chrono>
#include <set>
#include <string>
#include <thread>

#include "frame_text.hpp"
#include "socket_bus.hpp"
#include "socket_lss_link.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

CanFrame frameOf(const char* text) {
  CanFrame frame;
  std::string error;
  EXPECT_TRUE(host::parseFrame(text, &frame, &error)) << error;
  return frame;
}

/// Frames received until `expected.size()` of them have CAN-IDs in (base, base + 127], or
/// until the bus is quiet: those frames as text.
std::set<std::string> answers(SocketBus& bus, uint32_t base, size_t expected) {
  std::set<std::string> got;
  CanFrame frame;
  while (got.size() < expected && bus.receive(&frame, kSocketReceiveTimeoutMs)) {
    if (frame.id > base && frame.id <= base + 0x7FU) {
      got.insert(host::formatFrame(frame));
    }
  }
  return got;
}

/// An LSS master's link to several slaves that may answer one request together (on a wire their
/// answers merge into one frame): every answer to a request counts once, the others that follow
/// it within kSettleMs are dropped, so that none passes for the next request's.
class SharedAnswerLink : public SocketLink {
 public:
  static constexpr int kSettleMs = 50;

  explicit SharedAnswerLink(SocketBus& bus) : SocketLink(bus), bus_(bus) {}
  bool receive(CanFrame* frame) override {
    if (!SocketLink::receive(frame)) {
      return false;
    }
    CanFrame more;
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(kSettleMs);
    while (std::chrono::steady_clock::now() < end) {
      bus_.receive(&more, kSettleMs);
    }
    return true;
  }

 private:
  SocketBus& bus_;
};

TEST(NetworkOnVcan, ThreeDevicesBootAndAnswerSdoOnTheirOwnNodeIds) {
  SocketBus bus(SlaveNodes{{"example@1", "solo@2", "gra@3"}});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(answers(bus, 0x700, 3),
            (std::set<std::string>{"701 [1] 00", "702 [1] 00", "703 [1] 00"}))
      << bus.slave().output();
  bus.send(frameOf("601 [8] 40 00 10 00 00 00 00 00"));  // the example's device type
  bus.send(frameOf("602 [8] 40 01 30 00 00 00 00 00"));  // the SOLO's node address (0x3001; its
                                                         // profile answers 42)
  bus.send(frameOf("603 [8] 40 00 10 00 00 00 00 00"));  // the GRA's device type
  EXPECT_EQ(answers(bus, 0x580, 3), (std::set<std::string>{"581 [8] 43 00 10 00 00 00 00 00",
                                                           "582 [8] 42 01 30 00 02 00 00 00",
                                                           "583 [8] 43 00 10 00 00 00 00 00"}))
      << bus.slave().output();
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  EXPECT_NE(bus.slave().output().find("3 nodes on " + testInterface() + ": example@1 solo@2 gra@3"),
            std::string::npos)
      << bus.slave().output();
}

TEST(NetworkOnVcan, OneSyncMovesThreeJointsOfOneProcess) {
  SocketBus bus(SlaveNodes{{"m-series@1", "m-series@2", "m-series@3"}});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(answers(bus, 0x700, 3),
            (std::set<std::string>{"701 [1] 00", "702 [1] 00", "703 [1] 00"}));
  // The manual's example (5.10.3): three joints at their positions, one target each by RPDO4,
  // all three moving at one SYNC. --control commands name their node.
  EXPECT_EQ(bus.simulate("position 3448"), "error: name the node: @NODE-ID position 3448");
  EXPECT_EQ(bus.simulate("@1 position 3448"), "");
  EXPECT_EQ(bus.simulate("@2 position 6221"), "");
  EXPECT_EQ(bus.simulate("@0x03 position 10600"), "");
  EXPECT_EQ(bus.simulate("@4 position 1"), "error: no node with node-id 4");
  bus.send(frameOf("201 [7] 0F 00 07 78 0D 00 00"));  // enable, mode 7 (an addition)
  bus.send(frameOf("202 [7] 0F 00 07 4D 18 00 00"));
  bus.send(frameOf("203 [7] 0F 00 07 68 29 00 00"));
  EXPECT_EQ(answers(bus, 0x180, 3),
            (std::set<std::string>{"181 [6] 78 0D 00 00 37 04", "182 [6] 4D 18 00 00 37 04",
                                   "183 [6] 68 29 00 00 37 04"}));
  bus.send(frameOf("501 [4] 50 C3 00 00"));  // lines 738-741, one RPDO4 each (W13)
  bus.send(frameOf("502 [4] 50 C3 00 00"));
  bus.send(frameOf("503 [4] 50 C3 00 00"));
  EXPECT_EQ(answers(bus, 0x480, 3),
            (std::set<std::string>{"481 [6] 78 0D 00 00 37 04", "482 [6] 4D 18 00 00 37 04",
                                   "483 [6] 68 29 00 00 37 04"}));
  bus.send(frameOf("080 [0]"));  // line 742: all three move
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  bus.send(frameOf("601 [8] 40 64 60 00 00 00 00 00"));
  bus.send(frameOf("602 [8] 40 64 60 00 00 00 00 00"));
  bus.send(frameOf("603 [8] 40 64 60 00 00 00 00 00"));
  EXPECT_EQ(answers(bus, 0x580, 3), (std::set<std::string>{"581 [8] 43 64 60 00 50 C3 00 00",
                                                           "582 [8] 43 64 60 00 50 C3 00 00",
                                                           "583 [8] 43 64 60 00 50 C3 00 00"}));
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

TEST(NetworkOnVcan, HeartbeatConsumerWatchesAnotherNodeOfTheProcess) {
  SocketBus bus(SlaveNodes{{"example@1", "example@5"}}, {"--trace"});
  ASSERT_EQ(bus.error(), "");
  // Node 1 watches node 5 (100 ms), node 5 beats every 50 ms: the heartbeats reach node 1
  // inside the process. A stopped node goes on beating (state 04, CiA 301): no timeout. A reset
  // node starts again without a heartbeat (0x1017 = 0): node 1's consumer times out.
  EXPECT_EQ(playText(R"(
    ignore 705
    tx 701 [1] 00
    rx 601 [8] 23 16 10 01 64 00 05 00     # 0x1016:01 = node 5, 100 ms
    tx 581 [8] 60 16 10 01 00 00 00 00
    rx 605 [8] 2B 17 10 00 32 00 00 00     # 0x1017 = 50 ms
    tx 585 [8] 60 17 10 00 00 00 00 00
    rx 000 [2] 02 05                       # NMT stop node 5
    wait 400
    rx 601 [8] 40 01 10 00 00 00 00 00     # node 1's error register: no error
    tx 581 [8] 4F 01 10 00 00 00 00 00
    rx 000 [2] 81 05                       # NMT reset node 5
    tx 081 [8] 30 81 11 05 00 00 00 00     # node 1: heartbeat of node 5 lost
  )",
                     bus, kSocketReceiveTimeoutMs),
            "")
      << bus.slave().output();
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0);
  const std::string output = bus.slave().output();
  EXPECT_NE(output.find("@05 tx 705 [1] 04"), std::string::npos) << output;  // stopped, beating
  EXPECT_NE(output.find("@01 tx 081 [8] 30 81 11 05"), std::string::npos) << output;
}

TEST(NetworkOnVcan, FastscanFindsTwoUnconfiguredNodesOneAfterTheOther) {
  SocketBus bus(SlaveNodes{{"gra@255", "gra@255"}});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(bus.simulate("@255 angle 90"), "");  // up (the first unconfigured node)
  SharedAnswerLink link(bus);
  LssMaster master(link);
  std::set<uint32_t> serials;
  for (const uint8_t nodeId : {uint8_t{0x21}, uint8_t{0x22}}) {
    LssIdentity found;
    ASSERT_TRUE(master.fastscan(&found)) << bus.slave().output();
    EXPECT_EQ(found.vendorId, 0x93U);
    EXPECT_EQ(found.productCode, 0x64U);
    serials.insert(found.serialNumber);
    EXPECT_EQ(master.configureNodeId(nodeId), 0);
    master.switchGlobal(false);  // resets communication with its node-id: out of the next scan
    CanFrame frame;
    bool booted = false;
    while (!booted && bus.receive(&frame, kSocketReceiveTimeoutMs)) {
      booted = frame.id == 0x700U + nodeId && frame.dlc == 1U && frame.data[0] == 0U;
    }
    EXPECT_TRUE(booted) << "node " << int{nodeId};
  }
  EXPECT_EQ(serials, (std::set<uint32_t>{1, 2}));  // the K-th node given has serial number K
  LssIdentity none;
  EXPECT_FALSE(master.fastscan(&none));  // nobody unconfigured is left
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

TEST(NetworkOnVcan, StorageDirectoryKeepsOneFilePerNode) {
  char directory[] = "/tmp/costa-network-XXXXXX";
  const char* made = ::mkdtemp(directory);
  ASSERT_NE(made, nullptr);
  const std::string storage = std::string(made) + "/nodes";  // created by costa-slave
  const SlaveNodes nodes{{"example@1", "example@2"}};
  {
    SocketBus bus(nodes, {"--storage", storage});
    ASSERT_EQ(bus.error(), "");
    EXPECT_EQ(playText(R"(
      tx 701 [1] 00
      tx 702 [1] 00
      rx 602 [8] 23 00 20 00 20 4E 00 00   # node 2: setpoint 20000
      tx 582 [8] 60 00 20 00 00 00 00 00
      rx 602 [8] 23 10 10 01 73 61 76 65   # "save"
      tx 582 [8] 60 10 10 01 00 00 00 00
    )",
                       bus, kSocketReceiveTimeoutMs),
              "");
    EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
  }
  // The second node's file: written at its save (the first node saved nothing: no file yet).
  EXPECT_EQ(::access((storage + "/example-2.bin").c_str(), F_OK), 0);
  EXPECT_NE(::access((storage + "/example-1.bin").c_str(), F_OK), 0);
  SocketBus bus(nodes, {"--storage", storage});
  ASSERT_EQ(bus.error(), "");
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    tx 702 [1] 00
    rx 602 [8] 40 00 20 00 00 00 00 00
    tx 582 [8] 43 00 20 00 20 4E 00 00     # node 2's saved value
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 E8 03 00 00     # node 1 saved nothing: default 1000
  )",
                     bus, kSocketReceiveTimeoutMs),
            "");
  EXPECT_EQ(bus.slave().stop(SIGTERM), 0) << bus.slave().output();
}

TEST(NetworkCommandLine, ErrorsAreOneLineAndStatusTwo) {
  struct Case {
    std::vector<std::string> arguments;
    const char* message;
  };
  std::vector<std::string> tooMany;
  for (int i = 1; i <= 128; ++i) {
    tooMany.push_back("example@" + std::to_string(i == 128 ? 255 : i));
  }
  const Case cases[] = {
      {{"example@1", "solo@2", "gra@1"},
       "costa-slave: node-id 1 given twice (gra): every node needs its own\n"},
      {{"example@1", "toaster@2"}, "costa-slave: unknown device 'toaster' (one of: "},
      {tooMany, "costa-slave: 128 nodes given: at most 127 fit on one bus\n"},
      {{"solo@255", "gra@255"}, "costa-slave: solo has no LSS: it needs a node-id"},
  };
  for (const Case& c : cases) {
    SlaveProcess slave(c.arguments);
    const int status = slave.waitExit(kSlaveExitTimeoutMs);
    const std::string output = slave.output();
    EXPECT_EQ(output.rfind(c.message, 0), 0U) << output;
    EXPECT_EQ(output.find('\n'), output.size() - 1U) << output;  // one line
    EXPECT_EQ(status, 2) << output;
  }
}

}  // namespace
}  // namespace costa::test
