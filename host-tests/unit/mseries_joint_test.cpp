// The M-series joint's own functions: the multi-turn zero by 0x260A (B11), the power-on
// functions of 0x2619 (B12), the simulation commands, and the manual's interpolation with three
// joints on one bus moved by one SYNC (5.10.3, lines 733-744).
#include <array>
#include <memory>
#include <string>

#include "costa/port/memory/memory_can_bus.hpp"
#include "frame_text.hpp"
#include "mseries_fixture.hpp"

namespace costa::test {
namespace {

using JointFunctions = JointTest;

TEST_F(JointFunctions, ZeroSettingBy60006Then60016) {
  EXPECT_TRANSCRIPT(R"(
    sim position 123456
    rx 601 [8] 2B 0A 26 00 66 EA 00 00   # 60006 (line 254)
    tx 581 [8] 60 0A 26 00 00 00 00 00
    rx 601 [8] 40 0A 26 00 00 00 00 00   # held until the second write
    tx 581 [8] 4B 0A 26 00 66 EA 00 00
    rx 601 [8] 2B 0A 26 00 70 EA 00 00   # 60016 (line 255)
    tx 581 [8] 60 0A 26 00 00 00 00 00
    rx 601 [8] 40 64 60 00 00 00 00 00   # the position is 0 (line 257)
    tx 581 [8] 43 64 60 00 00 00 00 00
    rx 601 [8] 40 0A 26 00 00 00 00 00   # the numerator is back to 32768
    tx 581 [8] 4B 0A 26 00 00 80 00 00
  )");
}

TEST_F(JointFunctions, OtherNumeratorWritesAreJustNumerators) {
  EXPECT_TRANSCRIPT(R"(
    sim position 1000
    rx 601 [8] 2B 0A 26 00 70 EA 00 00   # 60016 without 60006: a numerator
    tx 581 [8] 60 0A 26 00 00 00 00 00
    rx 601 [8] 2B 0A 26 00 66 EA 00 00   # 60006
    tx 581 [8] 60 0A 26 00 00 00 00 00
    rx 601 [8] 2B 0A 26 00 00 10 00 00   # then 4096: the sequence is broken
    tx 581 [8] 60 0A 26 00 00 00 00 00
    rx 601 [8] 2B 0A 26 00 70 EA 00 00   # 60016 is a numerator again
    tx 581 [8] 60 0A 26 00 00 00 00 00
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 E8 03 00 00
    rx 601 [8] 40 0A 26 00 00 00 00 00
    tx 581 [8] 4B 0A 26 00 70 EA 00 00
  )");
}

TEST_F(JointFunctions, NoInternalRampFrom60000On) {
  // Lines 195-203: below 60000 (r/min)/s the joint ramps, from 60000 on it does not (D17).
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 83 60 00 5F EA 00 00   # 59999
    tx 581 [8] 60 83 60 00 00 00 00 00
    rx 601 [8] 23 FF 60 00 E8 03 00 00   # 1000 r/min
    tx 581 [8] 60 FF 60 00 00 00 00 00
    rx 601 [8] 2F 60 60 00 03 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    wait 1
    rx 601 [8] 40 6C 60 00 00 00 00 00   # 1 ms at 59999 (r/min)/s: 60 r/min
    tx 581 [8] 43 6C 60 00 3C 00 00 00
    rx 601 [8] 2B 40 60 00 06 00 00 00   # stop (shutdown)
    tx 581 [8] 60 40 60 00 00 00 00 00
    rx 601 [8] 23 83 60 00 60 EA 00 00   # 60000
    tx 581 [8] 60 83 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    wait 1
    rx 601 [8] 40 6C 60 00 00 00 00 00   # at once: 1000 r/min
    tx 581 [8] 43 6C 60 00 E8 03 00 00
  )");
}

// The positions the transcripts of 5.07.1 and 5.09 leave open (they also run in real time over
// SocketCAN), here on the virtual clock.
TEST_F(JointFunctions, WhereTheSpeedExampleStops) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2F 60 60 00 03 00 00 00
    tx 581 [8] 60 60 60 00 00 00 00 00
    rx 601 [8] 23 FF 60 00 E8 03 00 00
    tx 581 [8] 60 FF 60 00 00 00 00 00
    rx 601 [8] 2B 40 60 00 0F 00 00 00
    tx 581 [8] 60 40 60 00 00 00 00 00
    wait 100
    rx 601 [8] 2B 40 60 00 0F 01 00 00   # halt after 100 ms
    tx 581 [8] 60 40 60 00 00 00 00 00
    wait 100
    rx 601 [8] 40 64 60 00 00 00 00 00   # 50 ms of ramp and 50 ms at 1000 r/min:
    tx 581 [8] 43 64 60 00 11 A1 00 00   # 13926 + 27307 = 41233 counts
  )");
}

TEST_F(JointFunctions, WhereTheHomingExampleIsAfter100Ms) {
  EXPECT_TRANSCRIPT(R"(
    sim position 10000
    rx 601 [8] 2F 60 60 00 06 00 00 00   # method 17: down at 100 r/min
    tx 581 [8] 60 60 60 00 00 00 00 00
    wait 100
    rx 601 [8] 40 64 60 00 00 00 00 00   # 10000 - 100 x 54.6 counts
    tx 581 [8] 43 64 60 00 BA 11 00 00
  )");
}

// Found by fuzzing (host-tests/fuzz/regressions/mseries/negative-target-position): negative
// positions are fixed-point products, never shifts of a negative number.
TEST_F(JointFunctions, NegativePositionsAreReachedExactly) {
  EXPECT_TRANSCRIPT(R"(
    sim position -20000
    rx 201 [7] 2F 00 01 B0 3C FF FF      # 0x2F, mode 1, target -50000
    tx 181 [6] E0 B1 FF FF 37 00
    wait 200
    rx 201 [7] 2F 00 01 B0 3C FF FF
    tx 181 [6] B0 3C FF FF 37 04         # -50000, reached
    wait 1                               # the inhibit time (0.3 ms)
    rx 201 [7] 2F 00 01 46 C3 00 C8      # -939474106: far away, at 1000 r/min
    tx 181 [6] B0 3C FF FF 37 00
    wait 800
    tx 701 [1] 05                        # the heartbeat at 1000 ms
    rx 601 [8] 40 6C 60 00 00 00 00 00
    tx 581 [8] 43 6C 60 00 18 FC FF FF   # -1000 r/min
  )");
}

TEST_F(JointFunctions, AlarmAcknowledgeBy0x260E) {
  EXPECT_TRANSCRIPT(R"(
    sim alarm 0x12
    rx 601 [8] 2B 0E 26 00 00 00 00 00   # acknowledged: the locked rotor is gone
    tx 581 [8] 60 0E 26 00 00 00 00 00
    rx 601 [8] 40 0E 26 00 00 00 00 00
    tx 581 [8] 4B 0E 26 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00   # the drive stays in fault until a fault reset
    tx 581 [8] 4B 41 60 00 08 04 00 00
  )");
}

TEST_F(JointFunctions, SaveFlagZeroIsStored) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 2B 14 26 00 01 00 00 00
    tx 581 [8] 60 14 26 00 00 00 00 00
    rx 601 [8] 2B 14 26 00 00 00 00 00
    tx 581 [8] 60 14 26 00 00 00 00 00
    rx 601 [8] 40 14 26 00 00 00 00 00
    tx 581 [8] 4B 14 26 00 00 00 00 00
  )");
}

TEST_F(JointFunctions, SimulationCommandsAndTheirRefusals) {
  EXPECT_EQ(bus_.simulate("position -5"), "");
  EXPECT_EQ(signedValue(0x6064, 0), -5);
  EXPECT_EQ(bus_.simulate("pu on"), "");
  EXPECT_EQ(value(0x60FD, 0), 0x02U);
  EXPECT_EQ(bus_.simulate("dir on"), "");
  EXPECT_EQ(value(0x60FD, 0), 0x07U);
  const std::string usage =
      "usage: position N | dir on|off | pu on|off | alarm 0x10|0x12|0x14 | voltage 0..100";
  for (const char* wrong :
       {"", "position", "position 2147483648", "position 1 2", "dir maybe", "pu", "alarm 0x20",
        "alarm 0x15", "alarm 12", "voltage 101", "voltage -1", "speed 5", "position 0x"}) {
    EXPECT_EQ(bus_.simulate(wrong), usage) << wrong;
  }
  EXPECT_EQ(bus_.simulate("alarm 0x10"), "");
  EXPECT_EQ(value(0x260E, 0), 0x10U);
}

using JointPowerOn = JointPowerCycle;

TEST_F(JointPowerOn, Function6ReturnsToTheMultiTurnZero) {
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 19 26 00 06 00 00 00   # special function 6 (line 269)
    tx 581 [8] 60 19 26 00 00 00 00 00
    rx 601 [8] 2B 14 26 00 01 00 00 00   # saved (line 271)
    tx 581 [8] 60 14 26 00 00 00 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    sim position 5461                    # where the battery kept it
    rx 601 [8] 40 41 60 00 00 00 00 00   # on its way back, under pulse control
    tx 581 [8] 4B 41 60 00 04 00 00 00
    wait 200                             # at 100 r/min, 0x6083's ones digit (line 277)
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 00 00 00 00
    rx 601 [8] 40 41 60 00 00 00 00 00
    tx 581 [8] 4B 41 60 00 04 04 00 00
  )"),
            "");
}

TEST_F(JointPowerOn, AnAngleFunctionGoesThere) {
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 19 26 00 00 40 00 00   # 16384: half a turn (line 377)
    tx 581 [8] 60 19 26 00 00 00 00 00
    rx 601 [8] 2B 14 26 00 01 00 00 00
    tx 581 [8] 60 14 26 00 00 00 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    wait 400
    rx 601 [8] 40 64 60 00 00 00 00 00
    tx 581 [8] 43 64 60 00 00 40 00 00
  )"),
            "");
}

TEST_F(JointPowerOn, Function9StartsUnderCanOpenControl) {
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 19 26 00 09 00 00 00   # 9: CANopen control, pulses invalid (line 377)
    tx 581 [8] 60 19 26 00 00 00 00 00
    rx 601 [8] 2B 14 26 00 01 00 00 00
    tx 581 [8] 60 14 26 00 00 00 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 40 41 60 00 00 00 00 00   # no pulse word: switch on disabled, bit 6 unused
    tx 581 [8] 4B 41 60 00 00 04 00 00
  )"),
            "");
}

/// Three joints on one bus, node-ids 1, 2, 3, driven on a common clock in steps of 1 ms.
class ThreeJoints : public ::testing::Test {
 protected:
  ThreeJoints() {
    bus_.attach(client_);
    for (size_t i = 0; i < joints_.size(); ++i) {
      bus_.attach(ports_[i]);
      joints_[i] = std::make_unique<mseries::MSeriesTarget>(
          ports_[i], DeviceConfig{static_cast<uint8_t>(i + 1), true, nullptr, nullptr});
    }
    NoAllocationScope scope;
    for (auto& joint : joints_) {
      joint->start(now_);
    }
  }

  void send(const char* text) {
    CanFrame frame;
    std::string error;
    ASSERT_TRUE(host::parseFrame(text, &frame, &error)) << error;
    client_.tryTransmit(frame);
    deliver();
  }
  /// What the joints sent, in order, one frame a line.
  std::string sent() {
    std::string text;
    CanFrame frame;
    while (client_.receive(&frame)) {
      text += host::formatFrame(frame) + "\n";
    }
    return text;
  }
  void deliver() {
    NoAllocationScope scope;
    CanFrame frame;
    for (size_t i = 0; i < joints_.size(); ++i) {
      while (ports_[i].receive(&frame)) {
        joints_[i]->onFrame(frame, now_);
      }
      joints_[i]->process(now_);
    }
  }
  void wait(Microseconds microseconds) {
    for (Microseconds elapsed = 0; elapsed < microseconds; elapsed += 1000U) {
      now_ += 1000U;
      deliver();
    }
  }
  int32_t position(size_t joint) {
    return static_cast<int32_t>(joints_[joint]->node().values().x6064_position_actual_value);
  }

  port::MemoryCanBus bus_;
  port::MemoryCanEndpoint client_;
  std::array<port::MemoryCanEndpoint, 3> ports_;
  std::array<std::unique_ptr<mseries::MSeriesTarget>, 3> joints_;
  Microseconds now_ = InProcessBus::powerOnTime();
};

TEST_F(ThreeJoints, OneSyncMovesAllThree) {
  EXPECT_EQ(sent(), "701 [1] 00\n702 [1] 00\n703 [1] 00\n");
  char why[80] = {};
  ASSERT_TRUE(joints_[0]->control("position 3448", why, sizeof(why)));
  ASSERT_TRUE(joints_[1]->control("position 6221", why, sizeof(why)));
  ASSERT_TRUE(joints_[2]->control("position 10600", why, sizeof(why)));
  send("201 [7] 0F 00 07 78 0D 00 00");  // enable, mode 7 (an addition: the manual omits it)
  send("202 [7] 0F 00 07 4D 18 00 00");
  send("203 [7] 0F 00 07 68 29 00 00");
  EXPECT_EQ(sent(),
            "181 [6] 78 0D 00 00 37 04\n182 [6] 4D 18 00 00 37 04\n183 [6] 68 29 00 00 37 04\n");
  wait(1000);
  send("501 [4] 50 C3 00 00");  // lines 738-741, each joint on its own RPDO4 (W13)
  send("502 [4] 50 C3 00 00");
  send("503 [4] 50 C3 00 00");
  EXPECT_EQ(sent(),
            "481 [6] 78 0D 00 00 37 04\n482 [6] 4D 18 00 00 37 04\n483 [6] 68 29 00 00 37 04\n");
  wait(10000);
  EXPECT_EQ(position(0), 3448);  // held until the SYNC
  EXPECT_EQ(position(1), 6221);
  EXPECT_EQ(position(2), 10600);
  send("080 [0]");  // line 742: all three start together
  wait(1000);
  EXPECT_GT(position(0), 3448);
  EXPECT_GT(position(1), 6221);
  EXPECT_GT(position(2), 10600);
  wait(100000);
  EXPECT_EQ(position(0), 50000);
  EXPECT_EQ(position(1), 50000);
  EXPECT_EQ(position(2), 50000);
  EXPECT_EQ(sent(), "");  // no TPDO at the SYNC (W8), no heartbeat yet
}

}  // namespace
}  // namespace costa::test

namespace costa::test {
namespace {

// The simulated motor keeps its reading: each change of its state is in the next read(), and a
// new motor reads at rest (0x6078's idle 100 counts).
TEST(SimulatedJointReading, EveryChangeIsInTheNextRead) {
  mseries::SimulatedJoint joint;
  mseries::JointFeedback r = joint.read();
  EXPECT_EQ(r.position, 0);
  EXPECT_EQ(r.velocity, 0);
  EXPECT_TRUE(r.atRest);
  EXPECT_EQ(r.current, 100U);
  EXPECT_EQ(r.pwm, 0);
  joint.setPosition(-5000);
  EXPECT_EQ(joint.read().position, -5000);
  mseries::JointCommand command;
  command.axis.motion = cia402::Motion::kVelocity;
  command.axis.velocity = 1500;  // no ramp: at speed with the first step
  joint.drive(command);
  EXPECT_FALSE(joint.read().atRest);  // about to move
  joint.step(mseries::SimulatedJoint::kStep);
  r = joint.read();
  EXPECT_EQ(r.velocity, 1500);
  EXPECT_EQ(r.position, -5000 + 819);  // 1500 r/min = 819.2 counts a millisecond
  EXPECT_EQ(r.current, 1600U);
  EXPECT_EQ(r.pwm, 16383);
  joint.step(mseries::SimulatedJoint::kStep / 2);  // no whole step: nothing moves
  EXPECT_EQ(joint.read().position, -5000 + 819);
  joint.setInputs(true, false);
  EXPECT_TRUE(joint.read().dir);
  EXPECT_FALSE(joint.read().pu);
  command.axis.motion = cia402::Motion::kFree;
  joint.drive(command);
  r = joint.read();
  EXPECT_EQ(r.velocity, 0);
  EXPECT_TRUE(r.atRest);
  EXPECT_EQ(r.current, 100U);
}

}  // namespace
}  // namespace costa::test
