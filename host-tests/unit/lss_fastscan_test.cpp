// LSS Fastscan (CiA 305) end to end: several LSS slaves share a simulated bus with a small LSS
// master that runs the standard bit-by-bit scan, learns each non-configured slave's identity,
// gives it a node-id, and starts over until no slave answers.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "lss_test_bus.hpp"

namespace costa::test {
namespace {

/// One device on the simulated bus: an LSS slave, its transmit queue and a host that performs
/// reset communication the way a node does.
struct SimulatedDevice {
  SimulatedDevice(const LssIdentity& identity, uint8_t nodeId)
      : tx(can, slots, 4), slave(tx, host) {
    host.slave = &slave;
    slave.reset(identity, nodeId, nodeId, LssBitTiming{});
  }
  port::RecordingCan can;
  size_t cursor = 0;
  QueuedFrame slots[4];
  TransmitPath tx;
  RecordingLssHost host;
  LssSlave slave;
  int framesSent = 0;
};

/// The bus: a master frame reaches every device; what the devices answer is collected.
class SimulatedBus {
 public:
  void add(const LssIdentity& identity, uint8_t nodeId) {
    devices_.push_back(std::make_unique<SimulatedDevice>(identity, nodeId));
  }

  /// Sends one master request; returns how many devices answered with command `expectedCs`.
  /// Any other answer, or one that is not 0x7E4 [8] with the expected bytes, fails the test.
  int exchange(const uint8_t (&data)[8], uint8_t expectedCs, uint8_t expectedByte1 = 0) {
    ++requests_;
    CanFrame frame{0x7E5, {}, 8, false, false};
    for (size_t i = 0; i < 8; ++i) {
      frame.data[i] = data[i];
    }
    int answers = 0;
    for (auto& device : devices_) {
      {
        NoAllocationScope scope;
        // Whether the slave used the frame (a Fastscan step that is not for it is not) feeds
        // the node's count of ignored frames; here the answers tell.
        (void)device->slave.onFrame(frame, 0);
      }
      while (device->cursor < device->can.count()) {
        const CanFrame response = device->can.at(device->cursor++);
        ++device->framesSent;
        const CanFrame expected{0x7E4, {expectedCs, expectedByte1}, 8, false, false};
        EXPECT_TRUE(sameOnWire(response, expected))
            << "device " << device->slave.identity().serialNumber << " answered cs "
            << int{response.data[0]} << " " << int{response.data[1]};
        ++answers;
      }
    }
    return answers;
  }

  SimulatedDevice& device(size_t i) { return *devices_[i]; }
  size_t size() const { return devices_.size(); }
  int requests() const { return requests_; }

 private:
  std::vector<std::unique_ptr<SimulatedDevice>> devices_;
  int requests_ = 0;
};

/// The LSS master's side of Fastscan and node-id assignment, as CiA 305 describes it.
class FastscanMaster {
 public:
  explicit FastscanMaster(SimulatedBus& bus) : bus_(bus) {}

  /// Finds one non-configured slave and leaves it in LSS configuration state. False when no
  /// slave answers the reset request (or, on a broken slave, a confirmation).
  bool scan(LssIdentity* found) {
    if (fastscan(0, 0x80, 0, 0) == 0) {
      return false;
    }
    uint32_t value[4] = {};
    for (uint8_t sub = 0; sub < 4; ++sub) {
      for (int bit = 31; bit >= 0; --bit) {
        // Does any remaining slave have a 0 here (with the bits above as found so far)?
        if (fastscan(value[sub], static_cast<uint8_t>(bit), sub, sub) == 0) {
          value[sub] |= uint32_t{1} << static_cast<unsigned>(bit);
        }
      }
      const auto next = static_cast<uint8_t>(sub == 3U ? 0U : sub + 1U);
      if (fastscan(value[sub], 0, sub, next) == 0) {
        return false;
      }
    }
    *found = LssIdentity{value[0], value[1], value[2], value[3]};
    return true;
  }

  /// Gives the slave in configuration state its node-id, stores it, and returns every slave
  /// to waiting state (which makes a first node-id active at once).
  void assign(uint8_t nodeId) {
    EXPECT_EQ(bus_.exchange({0x11, nodeId}, 0x11, 0x00), 1);
    EXPECT_EQ(bus_.exchange({0x17}, 0x17, 0x00), 1);
    EXPECT_EQ(bus_.exchange({0x04, 0x00}, 0), 0);
  }

 private:
  int fastscan(uint32_t idNumber, uint8_t bitChecked, uint8_t lssSub, uint8_t lssNext) {
    const uint8_t data[8] = {0x51,
                             static_cast<uint8_t>(idNumber),
                             static_cast<uint8_t>(idNumber >> 8U),
                             static_cast<uint8_t>(idNumber >> 16U),
                             static_cast<uint8_t>(idNumber >> 24U),
                             bitChecked,
                             lssSub,
                             lssNext};
    return bus_.exchange(data, 0x4F);
  }

  SimulatedBus& bus_;
};

bool sameIdentity(const LssIdentity& a, const LssIdentity& b) {
  return a.vendorId == b.vendorId && a.productCode == b.productCode &&
         a.revisionNumber == b.revisionNumber && a.serialNumber == b.serialNumber;
}

// Per found slave: the reset request, 32 bit steps and one confirmation per identity value.
constexpr int kRequestsPerScan = 1 + 4 * (32 + 1);

TEST(LssFastscan, FindsEveryNonConfiguredSlaveInAscendingOrderAndAssignsNodeIds) {
  SimulatedBus bus;
  bus.add({0x000001A2U, 0x00000010U, 0x00010000U, 0x80000000U}, 0xFF);
  bus.add({0x000001A2U, 0x00000010U, 0x00010000U, 0x12345678U}, 3);  // configured
  bus.add({0x000001A2U, 0x00000010U, 0x00010000U, 0x00000001U}, 0xFF);
  bus.add({0x000001A2U, 0x00000011U, 0x00000001U, 0x00000001U}, 0xFF);  // other product
  bus.add({0x000001A2U, 0x00000010U, 0x00010000U, 0x80000001U}, 0xFF);  // differs in bit 0
  FastscanMaster master(bus);

  const size_t expectedOrder[] = {2, 0, 4, 3};  // ascending 128-bit identity
  uint8_t nodeId = 10;
  for (const size_t index : expectedOrder) {
    LssIdentity found;
    const int before = bus.requests();
    ASSERT_TRUE(master.scan(&found));
    EXPECT_EQ(bus.requests() - before, kRequestsPerScan);
    SimulatedDevice& device = bus.device(index);
    EXPECT_TRUE(sameIdentity(found, device.slave.identity())) << index;
    EXPECT_TRUE(device.slave.configurationState()) << index;
    master.assign(nodeId);
    EXPECT_EQ(device.slave.activeNodeId(), nodeId) << index;
    EXPECT_EQ(device.host.storedNodeId, nodeId) << index;
    EXPECT_EQ(device.host.resetRequests, 1) << index;
    EXPECT_FALSE(device.slave.configurationState()) << index;
    ++nodeId;
  }
  LssIdentity none;
  EXPECT_FALSE(master.scan(&none));  // nobody left to answer the reset request

  SimulatedDevice& configured = bus.device(1);
  EXPECT_EQ(configured.framesSent, 0);
  EXPECT_EQ(configured.slave.activeNodeId(), 3U);
  EXPECT_EQ(configured.host.stores + configured.host.resetRequests, 0);
}

TEST(LssFastscan, FindsTheOnlyNonConfiguredSlaveAmongConfiguredOnes) {
  SimulatedBus bus;
  bus.add({0x00000019U, 0x00001234U, 0x00000002U, 0x00000100U}, 1);
  bus.add({0x00000019U, 0x00001234U, 0x00000002U, 0x00000101U}, 0xFF);
  bus.add({0x00000019U, 0x00001234U, 0x00000002U, 0x00000102U}, 2);
  FastscanMaster master(bus);
  LssIdentity found;
  ASSERT_TRUE(master.scan(&found));
  EXPECT_TRUE(sameIdentity(found, bus.device(1).slave.identity()));
  master.assign(0x7F);
  EXPECT_EQ(bus.device(1).slave.activeNodeId(), 0x7FU);
  EXPECT_FALSE(master.scan(&found));
  EXPECT_EQ(bus.device(0).framesSent + bus.device(2).framesSent, 0);
}

TEST(LssFastscan, FindsIdentitiesOfAllZeroAndAllOneBits) {
  SimulatedBus bus;
  bus.add({0xFFFFFFFFU, 0xFFFFFFFFU, 0xFFFFFFFFU, 0xFFFFFFFFU}, 0xFF);
  bus.add({0, 0, 0, 0}, 0xFF);
  FastscanMaster master(bus);
  LssIdentity found;
  ASSERT_TRUE(master.scan(&found));
  EXPECT_TRUE(sameIdentity(found, LssIdentity{0, 0, 0, 0}));
  master.assign(1);
  ASSERT_TRUE(master.scan(&found));
  EXPECT_TRUE(sameIdentity(found, LssIdentity{0xFFFFFFFFU, 0xFFFFFFFFU, 0xFFFFFFFFU, 0xFFFFFFFFU}));
  master.assign(2);
  EXPECT_FALSE(master.scan(&found));
}

TEST(LssFastscan, NoNonConfiguredSlaveMeansNoAnswerToTheReset) {
  SimulatedBus bus;
  bus.add({1, 2, 3, 4}, 5);
  bus.add({1, 2, 3, 5}, 6);
  FastscanMaster master(bus);
  LssIdentity found;
  EXPECT_FALSE(master.scan(&found));
  EXPECT_EQ(bus.requests(), 1);
}

}  // namespace
}  // namespace costa::test
