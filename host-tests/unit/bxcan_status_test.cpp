// The bxCAN driver's status reports (poll) and the example node running over the driver on a
// simulated register block.
#include <gtest/gtest.h>

#include <vector>

#include "allocation_guard.hpp"
#include "costa/port/stm32/bxcan_port.hpp"
#include "example_target.hpp"
#include "simulated_bxcan.hpp"

namespace costa::test {
namespace {

using namespace port::stm32;
using namespace port::stm32::bxcan;
using Events = std::vector<CanControllerEvent>;

constexpr uint32_t kBtr = 0x011C0003;
constexpr uint32_t kTec = 1U << esr::kTecShift;
constexpr uint32_t kRec = 1U << esr::kRecShift;

class BxCanStatusTest : public ::testing::Test {
 protected:
  BxCanStatusTest() : port_(sim_.registers, 50) { sim_.attach(port_); }
  void SetUp() override { ASSERT_TRUE(port_.start(kBtr)); }

  Events poll() {
    const BxCanEvents events = port_.poll();
    return Events(events.begin(), events.end());
  }

  SimulatedBxCan sim_;
  BxCanPort port_;
};

TEST_F(BxCanStatusTest, NothingToReportWhileErrorActive) {
  sim_.registers.esr = esr::kEwgf | (100 * kTec) | (3U << esr::kLecShift);  // warning only
  sim_.registers.rf0r = rfr::kFull | 3U;
  EXPECT_EQ(poll(), Events{});
  EXPECT_EQ(sim_.registers.rf0r, rfr::kFull | 3U);  // nothing written
}

TEST_F(BxCanStatusTest, AnOverrunIsReportedAndClearedByWritingItsBitOnly) {
  sim_.registers.rf0r = rfr::kFovr | rfr::kFull | 3U;
  EXPECT_EQ(poll(), Events{CanControllerEvent::kRxOverrun});
  EXPECT_EQ(sim_.registers.rf0r, rfr::kFovr);  // FULL not cleared, no message released
  sim_.registers.rf0r = rfr::kFull | 3U;       // the hardware cleared FOVR0
  EXPECT_EQ(poll(), Events{});
  sim_.registers.rf0r = rfr::kFovr | rfr::kFull | 3U;  // another message lost
  EXPECT_EQ(poll(), Events{CanControllerEvent::kRxOverrun});
}

TEST_F(BxCanStatusTest, ErrorPassiveIsReportedOncePerChange) {
  sim_.registers.esr = esr::kEwgf | esr::kEpvf | (128 * kTec);
  EXPECT_EQ(poll(), Events{CanControllerEvent::kErrorPassive});
  EXPECT_EQ(poll(), Events{});
  sim_.registers.esr = esr::kEwgf | esr::kEpvf | (200 * kRec);
  EXPECT_EQ(poll(), Events{});
  sim_.registers.esr = esr::kEwgf | (100 * kTec);
  EXPECT_EQ(poll(), Events{CanControllerEvent::kErrorActive});
  EXPECT_EQ(poll(), Events{});
}

TEST_F(BxCanStatusTest, BusOffAndRecoveryFromErrorActive) {
  sim_.registers.esr = esr::kBoff | esr::kEpvf | esr::kEwgf | (248 * kTec);
  EXPECT_EQ(poll(), (Events{CanControllerEvent::kErrorPassive, CanControllerEvent::kBusOff}));
  EXPECT_EQ(poll(), Events{});
  sim_.registers.esr = 0;  // 128 x 11 recessive bits later: counters reset
  EXPECT_EQ(poll(),
            (Events{CanControllerEvent::kBusOffRecovered, CanControllerEvent::kErrorActive}));
  EXPECT_EQ(poll(), Events{});
}

TEST_F(BxCanStatusTest, BusOffFromErrorPassiveReportsOnlyTheBusOff) {
  sim_.registers.esr = esr::kEpvf | esr::kEwgf | (130 * kTec);
  EXPECT_EQ(poll(), Events{CanControllerEvent::kErrorPassive});
  sim_.registers.esr = esr::kBoff | esr::kEpvf | esr::kEwgf;
  EXPECT_EQ(poll(), Events{CanControllerEvent::kBusOff});
  sim_.registers.esr = esr::kBoff | esr::kEpvf | esr::kEwgf;
  EXPECT_EQ(poll(), Events{});
}

TEST_F(BxCanStatusTest, AnOverrunComesBeforeErrorStateChangesOfTheSamePoll) {
  sim_.registers.rf0r = rfr::kFovr;
  sim_.registers.esr = esr::kEpvf;
  EXPECT_EQ(poll(), (Events{CanControllerEvent::kRxOverrun, CanControllerEvent::kErrorPassive}));
}

TEST_F(BxCanStatusTest, RestartForgetsTheRememberedErrorState) {
  sim_.registers.esr = esr::kEpvf;
  EXPECT_EQ(poll(), Events{CanControllerEvent::kErrorPassive});
  ASSERT_TRUE(port_.start(kBtr));
  EXPECT_EQ(poll(), Events{CanControllerEvent::kErrorPassive});  // the node hears it again
  sim_.registers.esr = 0;
  ASSERT_TRUE(port_.start(kBtr));
  EXPECT_EQ(poll(), Events{});
}

// --- the example node over the driver ------------------------------------------------------

class NodeOverBxCanTest : public BxCanStatusTest {
 protected:
  NodeOverBxCanTest() : target_(port_, DeviceConfig{}) {}  // node-id 1
  void SetUp() override {
    BxCanStatusTest::SetUp();
    NoAllocationScope scope;
    target_.start(0);
  }

  /// Expects `mailbox` to hold a transmission request for a standard data frame.
  void expectSent(size_t mailbox, uint32_t id, uint32_t dlc, uint32_t low, uint32_t high) {
    const BxCanTxMailbox& box = sim_.registers.tx[mailbox];
    EXPECT_EQ(box.tir, (id << 21) | ir::kTxrq) << std::hex << id;
    EXPECT_EQ(box.tdtr, dlc) << std::hex << id;
    EXPECT_EQ(box.tdlr, low) << std::hex << id;
    EXPECT_EQ(box.tdhr, high) << std::hex << id;
  }

  /// One pass of a firmware main loop at time `now`.
  void loop(Microseconds now) {
    NoAllocationScope scope;
    for (const CanControllerEvent event : port_.poll()) {
      target_.node().onControllerEvent(event, now);
    }
    CanFrame frame;
    while (port_.receive(&frame)) {
      target_.onFrame(frame, now);
    }
    target_.process(now);
  }

  example::ExampleTarget target_;
};

TEST_F(NodeOverBxCanTest, BootUpAndAnSdoExchangeGoThroughTheMailboxes) {
  expectSent(0, 0x701, 1, 0x00000000, 0);  // boot-up 701 [1] 00
  // 601 [8] 40 00 20 00 ...: upload 0x2000:00 -> 581 [8] 43 00 20 00 E8 03 00 00
  sim_.receive(0xC0200000, 8, 0x00200040, 0);
  loop(1000);
  expectSent(0, 0x581, 8, 0x00200043, 0x000003E8);
  EXPECT_EQ(sim_.registers.rf0r, rfr::kRfom);
}

TEST_F(NodeOverBxCanTest, AFrameWaitsInTheNodeWhileAllMailboxesArePending) {
  sim_.registers.tsr = 0;
  sim_.receive(0xC0200000, 8, 0x00200040, 0);
  loop(1000);
  EXPECT_TRUE(target_.node().txPending());
  expectSent(0, 0x701, 1, 0x00000000, 0);  // still the boot-up
  sim_.registers.tsr = tsr::tme(1);
  loop(2000);
  EXPECT_FALSE(target_.node().txPending());
  expectSent(1, 0x581, 8, 0x00200043, 0x000003E8);
}

TEST_F(NodeOverBxCanTest, ControllerStatusBecomesEmcy) {
  sim_.registers.esr = esr::kEpvf;
  loop(1000);
  expectSent(0, 0x081, 8, 0x00118120, 0);  // 081 [8] 20 81 11 00 00 00 00 00
  sim_.registers.rf0r = rfr::kFovr;
  loop(2000);
  expectSent(0, 0x081, 8, 0x00118110, 0);  // 081 [8] 10 81 11 00 00 00 00 00
  EXPECT_EQ(target_.node().statistics().rxOverruns, 1U);
  sim_.registers.esr = esr::kBoff | esr::kEpvf;
  loop(3000);
  EXPECT_TRUE(target_.node().busOff());
  sim_.registers.esr = 0;
  loop(4000);
  EXPECT_FALSE(target_.node().busOff());
  expectSent(0, 0x081, 8, 0x00118140, 0);  // 081 [8] 40 81 11 00 00 00 00 00
}

}  // namespace
}  // namespace costa::test
