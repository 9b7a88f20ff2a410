// LSS on a whole node: an unconfigured node stays silent until LSS gives it a node-id, a new
// node-id takes effect at reset communication, the stored configuration survives a power
// cycle, bit timing activation reaches the application, and Fastscan finds the one
// unconfigured node among several nodes sharing a bus.
#include <memory>
#include <vector>

#include "costa/port/memory/memory_can_bus.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "example_fixture.hpp"
#include "lss_master.hpp"

namespace costa::test {
namespace {

/// The example's settings with `nodeId` and `storage`; a stored node-id wins at power-on.
NodeSettings lssSettings(uint8_t nodeId, NvStorage* storage = nullptr) {
  NodeSettings settings = example::ExampleTarget::settings();
  settings.nodeId = nodeId;
  settings.storage = storage;
  return settings;
}

TEST(LssNode, UnconfiguredNodeIsSilentUntilLssGivesItANodeId) {
  InProcessBus bus(exampleWith(lssSettings(0xFF)));
  EXPECT_EQ(playText(R"(
    silence                              # no boot-up without a node-id
    rx 000 [2] 01 00
    rx 67F [8] 40 00 10 00 00 00 00 00
    wait 1000
    silence
    rx 7E5 [8] 4C 00 00 00 00 00 00 00   # identify non-configured remote slave
    tx 7E4 [8] 50 00 00 00 00 00 00 00
    rx 7E5 [8] 04 01 00 00 00 00 00 00   # switch state global: configuration
    rx 7E5 [8] 11 22 00 00 00 00 00 00   # configure node-id 0x22
    tx 7E4 [8] 11 00 00 00 00 00 00 00
    rx 7E5 [8] 04 00 00 00 00 00 00 00   # back to waiting: the node starts with 0x22
    tx 722 [1] 00
    rx 622 [8] 40 00 12 01 00 00 00 00
    tx 5A2 [8] 43 00 12 01 22 06 00 00
  )",
                     bus),
            "");
  EXPECT_EQ(bus.node().nodeId(), 0x22U);
}

TEST(LssNode, ANewNodeIdTakesEffectAtResetCommunication) {
  InProcessBus bus(exampleWith(lssSettings(1)));
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 7E5 [8] 04 01 00 00 00 00 00 00
    rx 7E5 [8] 11 05 00 00 00 00 00 00
    tx 7E4 [8] 11 00 00 00 00 00 00 00
    rx 7E5 [8] 11 80 00 00 00 00 00 00   # 128 is out of range
    tx 7E4 [8] 11 01 00 00 00 00 00 00
    rx 7E5 [8] 5E 00 00 00 00 00 00 00   # inquire node-id: still the active one
    tx 7E4 [8] 5E 01 00 00 00 00 00 00
    rx 7E5 [8] 04 00 00 00 00 00 00 00
    rx 601 [8] 40 00 10 00 00 00 00 00   # still node 1
    tx 581 [8] 43 00 10 00 00 00 00 00
    rx 000 [2] 82 01                     # reset communication
    tx 705 [1] 00
  )",
                     bus),
            "");
}

TEST(LssNode, InquireIdentityComesFrom0x1018) {
  InProcessBus bus(exampleWith(lssSettings(1)));
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 7E5 [8] 04 01 00 00 00 00 00 00
    rx 7E5 [8] 5A 00 00 00 00 00 00 00
    tx 7E4 [8] 5A 05 0C 00 00 00 00 00   # vendor 0x00000C05
    rx 7E5 [8] 5B 00 00 00 00 00 00 00
    tx 7E4 [8] 5B 01 00 00 00 00 00 00   # product 1
    rx 7E5 [8] 5C 00 00 00 00 00 00 00
    tx 7E4 [8] 5C 00 00 01 00 00 00 00   # revision 0x00010000
    rx 7E5 [8] 5D 00 00 00 00 00 00 00
    tx 7E4 [8] 5D 01 00 00 00 00 00 00   # serial 1
  )",
                     bus),
            "");
}

TEST(LssNode, StoredConfigurationSurvivesAPowerCycle) {
  port::MemoryStorageOf<16384> storage;
  {
    InProcessBus bus(exampleWith(lssSettings(1, &storage)));
    EXPECT_EQ(playText(R"(
      tx 701 [1] 00
      rx 7E5 [8] 04 01 00 00 00 00 00 00
      rx 7E5 [8] 11 09 00 00 00 00 00 00
      tx 7E4 [8] 11 00 00 00 00 00 00 00
      rx 7E5 [8] 13 00 02 00 00 00 00 00   # bit timing index 2: 500 kbit/s
      tx 7E4 [8] 13 00 00 00 00 00 00 00
      rx 7E5 [8] 13 00 05 00 00 00 00 00   # index 5 is reserved
      tx 7E4 [8] 13 01 00 00 00 00 00 00
      rx 7E5 [8] 17 00 00 00 00 00 00 00   # store configuration
      tx 7E4 [8] 17 00 00 00 00 00 00 00
    )",
                       bus),
              "");
  }
  InProcessBus bus(exampleWith(lssSettings(1, &storage)));
  EXPECT_EQ(playText("tx 709 [1] 00", bus), "");
  EXPECT_EQ(bus.node().bitTiming().tableIndex, 2U);
}

TEST(LssNode, AStoredCobIdFollowsANewNodeIdOnlyAtItsDefaultCanId) {
  port::MemoryStorageOf<16384> storage;
  InProcessBus bus(exampleWith(lssSettings(9, &storage)));
  EXPECT_EQ(playText(R"(
    tx 709 [1] 00
    rx 609 [8] 23 14 10 00 00 00 00 80   # EMCY COB-ID: not valid, moved to CAN-ID 0
    tx 589 [8] 60 14 10 00 00 00 00 00
    rx 609 [8] 23 00 14 01 09 02 00 80   # RPDO1: not valid, at its default CAN-ID 0x200 + 9
    tx 589 [8] 60 00 14 01 00 00 00 00
    rx 609 [8] 23 01 14 01 00 03 00 80   # RPDO2: not valid, moved onto 0x300 itself
    tx 589 [8] 60 01 14 01 00 00 00 00
    rx 609 [8] 23 10 10 02 73 61 76 65   # save the communication parameters
    tx 589 [8] 60 10 10 02 00 00 00 00
    rx 7E5 [8] 04 01 00 00 00 00 00 00
    rx 7E5 [8] 11 05 00 00 00 00 00 00   # node-id 5, below 9
    tx 7E4 [8] 11 00 00 00 00 00 00 00
    rx 7E5 [8] 04 00 00 00 00 00 00 00
    rx 000 [2] 82 09                     # reset communication: node-id 5, the values loaded
    tx 705 [1] 00
    rx 605 [8] 40 14 10 00 00 00 00 00   # moved: stays where the master put it, not valid
    tx 585 [8] 43 14 10 00 00 00 00 80
    rx 605 [8] 40 00 14 01 00 00 00 00   # at its default: follows the node-id, not valid
    tx 585 [8] 43 00 14 01 05 02 00 80
    rx 605 [8] 40 01 14 01 00 00 00 00   # moved onto 0x300: stays there, not 0x305
    tx 585 [8] 43 01 14 01 00 03 00 80
    rx 000 [2] 81 05                     # reset node: node-id 9 again (the LSS one unstored)
    tx 709 [1] 00
    rx 609 [8] 40 01 14 01 00 00 00 00   # saved and loaded at 9: still 0x300
    tx 589 [8] 43 01 14 01 00 03 00 80
    rx 609 [8] 40 00 14 01 00 00 00 00
    tx 589 [8] 43 00 14 01 09 02 00 80
  )",
                     bus),
            "");
}

TEST(LssNode, StoreWithoutStorageIsNotSupported) {
  InProcessBus bus(exampleWith(lssSettings(1)));
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 7E5 [8] 04 01 00 00 00 00 00 00
    rx 7E5 [8] 17 00 00 00 00 00 00 00
    tx 7E4 [8] 17 01 00 00 00 00 00 00
  )",
                     bus),
            "");
}

class BitTimingEvents : public NodeEvents {
 public:
  void onBitTimingActivation(LssBitTiming timing) noexcept override {
    activated = timing.tableIndex;
  }
  int activated = -1;
};

TEST(LssNode, ActivateBitTimingSilencesTheNodeAndTellsTheApplication) {
  InProcessBus bus(exampleWith(lssSettings(1)));
  BitTimingEvents events;
  ASSERT_TRUE(bus.node().addListener(events));
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 17 10 00 0A 00 00 00   # heartbeat 10 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 7E5 [8] 04 01 00 00 00 00 00 00
    rx 7E5 [8] 13 00 04 00 00 00 00 00   # 125 kbit/s
    tx 7E4 [8] 13 00 00 00 00 00 00 00
    rx 7E5 [8] 15 64 00 00 00 00 00 00   # activate, switch delay 100 ms
    wait 150
  )",
                     bus),
            "");
  EXPECT_EQ(events.activated, 4);
  EXPECT_EQ(bus.node().bitTiming().tableIndex, 4U);
  CanFrame frame;
  while (bus.receive(&frame, 0)) {  // heartbeats queued during the switch may follow
    EXPECT_EQ(frame.id, 0x701U);
  }
}

/// Several example nodes on one in-memory bus with an LSS master.
class SharedBus : public LssMasterLink {
 public:
  void add(uint8_t nodeId, uint32_t serial) {
    endpoints_.push_back(std::make_unique<port::MemoryCanEndpoint>());
    bus_.attach(*endpoints_.back());
    nodes_.push_back(
        std::make_unique<ExampleWithSettings>(*endpoints_.back(), lssSettings(nodeId), serial));
    NoAllocationScope scope;
    nodes_.back()->start(0);
  }
  void attachMaster() { bus_.attach(master_); }
  void send(const CanFrame& frame) override {
    master_.tryTransmit(frame);
    deliver();
  }
  bool receive(CanFrame* frame) override {
    while (master_.receive(frame)) {
      if (frame->id == 0x7E4) {
        return true;
      }
    }
    return false;
  }
  void deliver() {
    NoAllocationScope scope;
    for (size_t i = 0; i < nodes_.size(); ++i) {
      CanFrame frame;
      while (endpoints_[i]->receive(&frame)) {
        nodes_[i]->onFrame(frame, 0);
      }
    }
  }
  ExampleWithSettings& node(size_t i) { return *nodes_[i]; }

 private:
  port::MemoryCanBus bus_;
  port::MemoryCanEndpoint master_;
  std::vector<std::unique_ptr<port::MemoryCanEndpoint>> endpoints_;
  std::vector<std::unique_ptr<ExampleWithSettings>> nodes_;
};

TEST(LssNode, FastscanFindsTheOneUnconfiguredNodeAmongSeveral) {
  SharedBus bus;
  bus.attachMaster();
  bus.add(1, 0x1001);
  bus.add(0xFF, 0xCAFE0042);  // the unconfigured one
  bus.add(2, 0x1003);
  LssMaster master(bus);
  LssIdentity found;
  ASSERT_TRUE(master.fastscan(&found));
  EXPECT_EQ(found.vendorId, 0x00000C05U);
  EXPECT_EQ(found.productCode, 1U);
  EXPECT_EQ(found.revisionNumber, 0x00010000U);
  EXPECT_EQ(found.serialNumber, 0xCAFE0042U);
  EXPECT_EQ(master.configureNodeId(0x30), 0);
  master.switchGlobal(false);  // the node resets communication with its new node-id
  EXPECT_EQ(bus.node(1).node().nodeId(), 0x30U);
  EXPECT_EQ(bus.node(1).node().state(), NmtState::kPreOperational);
  EXPECT_EQ(bus.node(0).node().nodeId(), 1U);
  EXPECT_EQ(bus.node(2).node().nodeId(), 2U);
  LssIdentity again;
  EXPECT_FALSE(master.fastscan(&again));  // nobody is left unconfigured
}

}  // namespace
}  // namespace costa::test
