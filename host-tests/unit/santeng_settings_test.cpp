// The Santeng's configuration (errata B13, D13, W7, W12, W13): the RS232 utility's settings as
// simulation commands, hidden from the bus, saved by 0x2017 with the node-id and bit rate, and
// loaded at the next power-on from the controller's memory (costa-slave --storage FILE).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "costa/port/memory/memory_storage.hpp"
#include "device_target.hpp"
#include "in_process_bus.hpp"
#include "recording_bit_rate.hpp"
#include "santeng_target.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

using santeng::SantengTarget;

class SantengSettings : public ::testing::Test {
 protected:
  /// Switches the controller on (again) over the same memory, node-id from storage (as
  /// costa-slave --storage FILE santeng, without --node-id), with a recording bit rate control.
  void powerOn() {
    bus_.reset();
    bus_ = std::make_unique<InProcessBus>([this](CanTransmitter& can) {
      return std::make_unique<host::HostedTarget<SantengTarget>>(
          nullptr, can, DeviceConfig{0, false, &memory_, &rate_});
    });
  }
  std::string play(const std::string& text) { return playText(text, *bus_); }
  std::string sim(const std::string& command) { return bus_->simulate(command); }

  port::MemoryStorageOf<SantengTarget::kStorageBytes> memory_;
  RecordingBitRate rate_;
  std::unique_ptr<InProcessBus> bus_;
};

TEST_F(SantengSettings, FactoryDefaults) {  // lines 121-132
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00                          # node-id 1
    wait 1000
    tx 701 [1] 05                          # heartbeat 1000 ms, operational by itself
    wait 500
    tx 181 [8] 00 00 00 00 00 00 00 00     # TPDOs every 1500 ms
    tx 281 [8] 00 00 00 00 00 00 00 00
    tx 381 [8] 00 00 00 00 00 00 00 00
    tx 481 [8] 00 00 00 00 00 00 00 00
  )"),
            "");
  EXPECT_EQ(rate_.count(), 0U);  // 250 kbit/s, as the controller was started
  EXPECT_EQ(bus_->node().bitTiming(), (LssBitTiming{128, 3}));
}

TEST_F(SantengSettings, TheConfigurationIsHiddenFromTheBus) {  // D13
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 40 00 50 00 00 00 00 00
    tx 581 [8] 80 00 50 00 00 00 02 06
    rx 601 [8] 2F 00 50 00 00 00 00 00
    tx 581 [8] 80 00 50 00 00 00 02 06
    rx 601 [8] 40 01 50 01 00 00 00 00
    tx 581 [8] 80 01 50 01 00 00 02 06
    rx 601 [8] 2B 02 50 02 10 27 00 00
    tx 581 [8] 80 02 50 02 00 00 02 06
    rx 601 [8] 40 03 50 00 00 00 00 00
    tx 581 [8] 80 03 50 00 00 00 02 06
  )"),
            "");
}

TEST_F(SantengSettings, NodeIdAndBitRateApplyAtTheNextResetAndAreSavedBy2017) {
  powerOn();
  ASSERT_EQ(play("tx 701 [1] 00"), "");
  ASSERT_EQ(sim("set heartbeat 0"), "");
  ASSERT_EQ(sim("set tpdo-rate 0"), "");
  ASSERT_EQ(sim("set node-id 5"), "");
  ASSERT_EQ(sim("set bit-rate 25"), "");
  EXPECT_EQ(rate_.count(), 0U);  // not yet
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 17 20 00 01 00 00 00     # 0x2017: save
    tx 581 [8] 60 17 20 00 00 00 00 00
    rx 000 [2] 82 01                       # reset communication
    tx 705 [1] 00                          # node-id 5
  )"),
            "");
  ASSERT_EQ(rate_.count(), 1U);
  EXPECT_EQ(rate_.at(0).bitsPerSecond, 25000U);  // its own table's 25 kbit/s (W13)
  powerOn();
  EXPECT_EQ(play("tx 705 [1] 00"), "");  // the saved node-id; heartbeat 0 saved too
  ASSERT_EQ(rate_.count(), 2U);
  EXPECT_EQ(rate_.at(1).bitsPerSecond, 25000U);  // before the boot-up
  EXPECT_EQ(play("wait 2000\nsilence"), "");
}

TEST_F(SantengSettings, HeartbeatAndTpdoRateApplyAtOnce) {
  powerOn();
  ASSERT_EQ(play("tx 701 [1] 00"), "");
  ASSERT_EQ(sim("set heartbeat 200"), "");
  ASSERT_EQ(sim("set tpdo-rate 0"), "");
  EXPECT_EQ(play(R"(
    wait 200
    tx 701 [1] 05
    wait 200
    tx 701 [1] 05
    rx 601 [8] 40 17 10 00 00 00 00 00     # 0x1017 shows it
    tx 581 [8] 4B 17 10 00 C8 00 00 00
  )"),
            "");
  ASSERT_EQ(sim("set heartbeat 0"), "");
  ASSERT_EQ(sim("set tpdo-rate 300"), "");
  EXPECT_EQ(play(R"(
    wait 300
    tx 181 [8] 00 00 00 00 00 00 00 00
    tx 281 [8] 00 00 00 00 00 00 00 00
    tx 381 [8] 00 00 00 00 00 00 00 00
    tx 481 [8] 00 00 00 00 00 00 00 00
    rx 601 [8] 40 00 18 05 00 00 00 00
    tx 581 [8] 4B 00 18 05 2C 01 00 00
  )"),
            "");
}

TEST_F(SantengSettings, AutomaticStartOffWaitsForNmtStart) {  // lines 80, 132
  powerOn();
  ASSERT_EQ(play("tx 701 [1] 00"), "");
  ASSERT_EQ(sim("set auto-start off"), "");
  ASSERT_EQ(sim("set tpdo-rate 0"), "");
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 17 20 00 00 00 00 00
    tx 581 [8] 60 17 20 00 00 00 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    wait 1000
    tx 701 [1] 7F                          # pre-operational
    rx 000 [2] 01 01                       # NMT start
    wait 1000
    tx 701 [1] 05
  )"),
            "");
  ASSERT_EQ(sim("set auto-start on"), "");  // not saved: the next reset node loads "off"
  EXPECT_EQ(play(R"(
    rx 000 [2] 81 01
    tx 701 [1] 00
    wait 1000
    tx 701 [1] 7F
  )"),
            "");
}

TEST_F(SantengSettings, ChannelSettingsAreSavedToo) {
  powerOn();
  ASSERT_EQ(play("tx 701 [1] 00"), "");
  ASSERT_EQ(sim("set mode 2 position"), "");
  ASSERT_EQ(sim("set encoder-lines 2 250"), "");
  ASSERT_EQ(sim("set max-rpm 2 600"), "");
  ASSERT_EQ(sim("set heartbeat 0"), "");
  ASSERT_EQ(sim("set tpdo-rate 0"), "");
  ASSERT_EQ(play("rx 601 [8] 2F 17 20 00 00 00 00 00\ntx 581 [8] 60 17 20 00 00 00 00 00"), "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 23 02 20 02 E8 03 00 00     # 1000 RPM, capped at 600
    tx 581 [8] 60 02 20 02 00 00 00 00
    rx 601 [8] 23 01 20 02 E8 03 00 00     # 1000 counts: one revolution of 250 lines
    tx 581 [8] 60 01 20 02 00 00 00 00
    wait 3000
    rx 601 [8] 40 04 21 02 00 00 00 00
    tx 581 [8] 43 04 21 02 E8 03 00 00     # arrived
  )"),
            "");
}

TEST_F(SantengSettings, ADamagedConfigurationIsFlaggedAfterThePowerOn) {  // B10
  powerOn();
  ASSERT_EQ(play("tx 701 [1] 00\nrx 601 [8] 2F 17 20 00 00 00 00 00\n"
                 "tx 581 [8] 60 17 20 00 00 00 00 00"),
            "");
  memory_.bytes()[28] ^= 0xFFU;  // the first payload byte of the first stored region
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 40 12 21 00 00 00 00 00
    tx 581 [8] 4F 12 21 00 80 00 00 00     # FF f8: default configuration loaded
  )"),
            "");
}

TEST_F(SantengSettings, ASaveTheMemoryRefusesAborts) {
  powerOn();
  ASSERT_EQ(play("tx 701 [1] 00"), "");
  memory_.cutPowerAfter(0);
  EXPECT_EQ(play(R"(
    rx 601 [8] 2F 17 20 00 00 00 00 00
    tx 581 [8] 80 17 20 00 20 00 00 08
  )"),
            "");
  memory_.restorePower();
}

TEST_F(SantengSettings, SimulationCommandsRefuseBadArgumentsWithOneLine) {
  powerOn();
  EXPECT_EQ(sim("set node-id 127"), "usage: set node-id 1..126");
  EXPECT_EQ(sim("set node-id 0"), "usage: set node-id 1..126");
  EXPECT_EQ(sim("set bit-rate 20"), "usage: set bit-rate 1000|800|500|250|125|50|25|10");
  EXPECT_EQ(sim("set heartbeat 65536"), "usage: set heartbeat|tpdo-rate 0..65535 (ms)");
  EXPECT_EQ(sim("set auto-start maybe"), "usage: set auto-start on|off");
  EXPECT_EQ(sim("set mode 3 speed"), "usage: set mode 1|2 open-loop|speed|position");
  EXPECT_EQ(sim("set mode 1 torque"), "usage: set mode 1|2 open-loop|speed|position");
  EXPECT_EQ(sim("set max-rpm 1 0"), "usage: set max-rpm|encoder-lines 1|2 1..65535");
  EXPECT_EQ(sim("set colour red"),
            "usage: set node-id|bit-rate|heartbeat|tpdo-rate|auto-start|mode|max-rpm|"
            "encoder-lines ...");
  EXPECT_EQ(sim("fault fire on"),
            "usage: fault overheat|overvoltage|undervoltage|short|sensor|mosfet on|off");
  EXPECT_EQ(sim("stall 0 on"), "usage: stall 1|2 on|off");
  EXPECT_EQ(sim("input 33 on"), "usage: input 1..32 on|off");
  EXPECT_EQ(sim("output 9 on"), "usage: output 1..8 on|off");
  EXPECT_EQ(sim("jump 3"), "unknown command 'jump' (set, fault, stall, input, output)");
  EXPECT_EQ(sim("set bit-rate 1000"), "");
  EXPECT_EQ(sim("  stall   2   on   extra"), "");
}

}  // namespace
}  // namespace costa::test
