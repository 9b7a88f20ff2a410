// The SOLO behind its objects: the simulated drive (plausibility), the objects with side
// effects, the device error register, and the SOLO wire profile.
#include <algorithm>
#include <memory>
#include <string>

#include "costa/port/memory/recording_can.hpp"
#include "device_fixture.hpp"
#include "device_registry.hpp"
#include "sfxt.hpp"
#include "solo_od.hpp"
#include "solo_target.hpp"

namespace costa::test {
namespace {

class Solo : public DeviceTest {
 protected:
  Solo() : DeviceTest("solo", 1) {}
  void SetUp() override { ASSERT_EQ(play("tx 701 [1] 00"), ""); }

  double sfxt(uint16_t index) { return solo::sfxtToDouble(static_cast<int32_t>(value(index, 0))); }
  double speed() { return static_cast<double>(static_cast<int32_t>(value(0x3036, 0))); }
  int32_t position() { return static_cast<int32_t>(value(0x3037, 0)); }

  /// Node guarding: guard time 100 ms, life time factor 2.
  void lifeTime200ms() {
    ASSERT_EQ(play(R"(
      rx 601 [8] 22 0C 10 00 64 00 00 00
      tx 581 [8] 60 0C 10 00 00 00 00 00
      rx 601 [8] 22 0D 10 00 02 00 00 00
      tx 581 [8] 60 0D 10 00 00 00 00 00
    )"),
              "");
  }

  /// Digital speed control of a BLDC with encoders, as in the manual's first speed example.
  void digitalSpeedMode() {
    ASSERT_EQ(play(R"(
      rx 601 [8] 22 15 30 00 01 00 00 00
      tx 581 [8] 60 15 30 00 00 00 00 00
      rx 601 [8] 22 16 30 00 00 00 00 00
      tx 581 [8] 60 16 30 00 00 00 00 00
      rx 601 [8] 22 13 30 00 01 00 00 00
      tx 581 [8] 60 13 30 00 00 00 00 00
      rx 601 [8] 22 02 30 00 01 00 00 00
      tx 581 [8] 60 02 30 00 00 00 00 00
    )"),
              "");
  }
};

TEST_F(Solo, SpeedRampsWithTheAccelerationAndStopsAtTheReference) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 2A 30 00 00 00 14 00   # acceleration 10 rev/s^2 (Sfxt 0x00140000)
    tx 581 [8] 60 2A 30 00 00 00 00 00
    rx 601 [8] 22 05 30 00 E8 03 00 00   # 1000 rpm
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 500
  )");
  // 10 rev/s^2 = 600 rpm/s: about 300 rpm after 0.5 s.
  EXPECT_NEAR(speed(), 300.0, 10.0);
  EXPECT_GT(sfxt(0x3034), 0.0);  // accelerating takes torque current
  EXPECT_TRANSCRIPT("wait 1500");
  EXPECT_EQ(speed(), 1000.0);
  EXPECT_GT(position(), 0);
  const int32_t before = position();
  EXPECT_TRANSCRIPT("wait 600");
  // 1000 rpm for 0.6 s with 1000 lines (4000 counts per revolution) = 40000 counts.
  EXPECT_NEAR(position() - before, 40000, 700);
}

TEST_F(Solo, SpeedIsCappedByTheSpeedLimitAndFollowsTheDirection) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 11 30 00 F4 01 00 00   # speed limit 500 rpm
    tx 581 [8] 60 11 30 00 00 00 00 00
    rx 601 [8] 22 0C 30 00 01 00 00 00   # clockwise
    tx 581 [8] 60 0C 30 00 00 00 00 00
    rx 601 [8] 22 05 30 00 D0 07 00 00   # 2000 rpm
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 3000
  )");
  EXPECT_EQ(speed(), -500.0);
  EXPECT_LT(position(), 0);
}

TEST_F(Solo, DecelerationAndFastStop) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 05 30 00 E8 03 00 00
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 2000
    rx 601 [8] 22 2B 30 00 00 00 0A 00   # deceleration 5 rev/s^2 = 300 rpm/s
    tx 581 [8] 60 2B 30 00 00 00 00 00
    rx 601 [8] 22 05 30 00 F4 01 00 00   # 500 rpm
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 1000
  )");
  EXPECT_NEAR(speed(), 700.0, 10.0);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 05 30 00 00 00 00 00   # 0: fast stop bypasses the deceleration
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 100
  )");
  EXPECT_EQ(speed(), 0.0);
}

TEST_F(Solo, AnalogueCommandingModeIgnoresTheDigitalReference) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 05 30 00 E8 03 00 00
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 1000
  )");
  EXPECT_EQ(speed(), 0.0);
}

TEST_F(Solo, PositionModeStopsExactlyOnTheReferenceWithinTheSpeedLimit) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 16 30 00 02 00 00 00   # position mode
    tx 581 [8] 60 16 30 00 00 00 00 00
    rx 601 [8] 22 11 30 00 2C 01 00 00   # 300 rpm
    tx 581 [8] 60 11 30 00 00 00 00 00
    rx 601 [8] 22 1B 30 00 20 4E 00 00   # 20000 counts (5 revolutions)
    tx 581 [8] 60 1B 30 00 00 00 00 00
    wait 300
  )");
  EXPECT_GT(position(), 0);
  EXPECT_LE(speed(), 300.0);
  EXPECT_TRANSCRIPT("wait 2000");
  EXPECT_EQ(position(), 20000);
  EXPECT_EQ(speed(), 0.0);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 1F 30 00 01 00 00 00   # home
    tx 581 [8] 60 1F 30 00 00 00 00 00
  )");
  EXPECT_EQ(position(), 0);
  EXPECT_TRANSCRIPT("wait 100");  // the drive rested on the reference; it goes back to it
  EXPECT_GT(position(), 0);
}

TEST_F(Solo, TorqueModeIqFollowsTheReference) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 16 30 00 01 00 00 00   # torque mode
    tx 581 [8] 60 16 30 00 00 00 00 00
    rx 601 [8] 22 04 30 00 00 00 03 00   # Iq reference 1.5 A
    tx 581 [8] 60 04 30 00 00 00 00 00
    wait 100
  )");
  EXPECT_NEAR(sfxt(0x3034), 1.5, 0.01);
  EXPECT_GT(speed(), 0.0);
}

TEST_F(Solo, DisablingTheDriveLetsTheMotorCoast) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 05 30 00 E8 03 00 00
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 2000
    rx 601 [8] 22 08 30 00 00 00 00 00   # disable
    tx 581 [8] 60 08 30 00 00 00 00 00
    wait 500
  )");
  // Coasting at 20 rev/s^2 = 1200 rpm/s: about 400 rpm left after 0.5 s.
  EXPECT_NEAR(speed(), 400.0, 15.0);
}

// A drive at rest is not stepped (process() asks for no step), and a speed written then ramps
// from the next 10 ms step on, as if every step had been taken: 50 steps of 6 rpm in 0.5 s.
// After the setup the test calls the target as costa-slave does: process() after each frame
// and at the deadlines it returns, at no other time.
TEST_F(Solo, ASpeedWrittenAfterARestRampsFromTheNextStep) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 2A 30 00 00 00 14 00   # acceleration 10 rev/s^2
    tx 581 [8] 60 2A 30 00 00 00 00 00
    wait 1000
  )");
  host::DeviceTarget& target = bus_.target();
  Microseconds now = bus_.now();
  EXPECT_EQ(target.process(now), now + solo::SoloDevice::kLongestRest);  // no step before
  now += 1345000U;                                                       // 134.5 steps later
  CanFrame speed1000;
  speed1000.id = 0x601;
  speed1000.dlc = 8;
  const uint8_t write[8] = {0x22, 0x05, 0x30, 0x00, 0xE8, 0x03, 0x00, 0x00};
  std::copy(write, write + 8, speed1000.data);
  target.onFrame(speed1000, now);
  Microseconds next = target.process(now);
  EXPECT_EQ(next, now + 5000U);  // the next step
  const Microseconds end = now + 500000U;
  while (reached(end, next)) {
    next = target.process(next);
  }
  EXPECT_EQ(speed(), 300.0);
}

// The node's own processing can change the drive's command: life guarding stops it. A drive
// at rest then asks for its next step again, so that the stop is stepped as before.
TEST_F(Solo, LifeGuardingExpiringOverADriveAtRestAsksForTheNextStep) {
  digitalSpeedMode();
  lifeTime200ms();
  EXPECT_TRANSCRIPT(R"(
    rx 701 [0] RTR
    tx 701 [1] FF
  )");
  const Microseconds expiry = bus_.now() + 200000U;
  EXPECT_TRANSCRIPT("wait 150");
  EXPECT_EQ(bus_.target().process(bus_.now()), expiry);  // the drive rests: no step
  const Microseconds next = bus_.target().process(expiry);
  EXPECT_NE(value(0x3020, 0) & 0x20U, 0U);  // communication lost: the drive is stopped
  EXPECT_TRUE(next - expiry <= solo::SoloDevice::kStep) << next - expiry;
}

TEST_F(Solo, PwmFrequencyIsWrittenInKilohertzAndReadInHertz) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 09 30 00 00 00 00 00
    tx 581 [8] 42 09 30 00 20 4E 00 00   # 20000 Hz
    rx 601 [8] 22 09 30 00 20 00 00 00   # 32 kHz
    tx 581 [8] 60 09 30 00 00 00 00 00
    rx 601 [8] 40 09 30 00 00 00 00 00
    tx 581 [8] 42 09 30 00 00 7D 00 00   # 32000 Hz
    rx 601 [8] 22 09 30 00 07 00 00 00   # 7 kHz
    tx 581 [8] 80 09 30 00 30 00 09 06
    rx 601 [8] 22 09 30 00 51 00 00 00   # 81 kHz
    tx 581 [8] 80 09 30 00 30 00 09 06
  )");
}

TEST_F(Solo, EveryRangeViolationAbortsWith06090030) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 05 30 00 31 75 00 00   # speed reference 30001
    tx 581 [8] 80 05 30 00 30 00 09 06
    rx 601 [8] 22 0F 30 00 00 00 00 00   # poles 0 < 1
    tx 581 [8] 80 0F 30 00 30 00 09 06
    rx 601 [8] 22 00 40 00 00 00 00 00   # no such object
    tx 581 [8] 80 00 40 00 00 00 02 06
  )");
}

TEST_F(Solo, AnalogueInputChannelComesFromTheRequest) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 4A 30 00 00 00 00 00   # CH0 (S/T)
    tx 581 [8] 42 4A 30 00 00 00 00 00
    rx 601 [8] 40 4A 30 00 01 00 00 00   # CH1 (P/F)
    tx 581 [8] 42 4A 30 00 00 08 00 00   # 2048
    rx 601 [8] 40 4A 30 00 02 00 00 00
    tx 581 [8] 80 4A 30 00 30 00 09 06
  )");
}

TEST_F(Solo, VersionsAndMeasurementsAreReadable) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 3A 30 00 00 00 00 00
    tx 581 [8] 42 3A 30 00 20 B0 00 00
    wait 20
    rx 601 [8] 40 31 30 00 00 00 00 00   # bus voltage 24 V = 0x00300000
    tx 581 [8] 42 31 30 00 00 00 30 00
  )");
  EXPECT_NEAR(sfxt(0x3039), 25.0, 0.5);  // board temperature at rest
}

TEST_F(Solo, OverCurrentSetsTheErrorRegisterStopsTheDriveAndStaysUntilCleared) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 05 30 00 E8 03 00 00
    tx 581 [8] 60 05 30 00 00 00 00 00
    wait 1000
    rx 601 [8] 22 03 30 00 00 00 00 00   # current limit 0: over-current protection
    tx 581 [8] 60 03 30 00 00 00 00 00
    wait 10
    tx 081 [8] 00 00 00 03 00 00 00 00   # EMCY: error register generic + current in byte 4
    rx 601 [8] 40 20 30 00 00 00 00 00
    tx 581 [8] 42 20 30 00 01 00 00 00   # 0x3020 bit 0
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 42 01 10 00 03 00 00 00
    rx 601 [8] 22 20 30 00 00 00 00 00   # overwrite: the cause is still there
    tx 581 [8] 60 20 30 00 00 00 00 00
    wait 10
    tx 081 [8] 00 00 00 03 00 00 00 00   # a new error event
    rx 601 [8] 22 03 30 00 00 00 20 00   # current limit 16 A: cause removed
    tx 581 [8] 60 03 30 00 00 00 00 00
    rx 601 [8] 22 20 30 00 00 00 00 00   # cleared: no EMCY (errata S6)
    tx 581 [8] 60 20 30 00 00 00 00 00
    wait 100
    rx 601 [8] 40 01 10 00 00 00 00 00
    tx 581 [8] 42 01 10 00 00 00 00 00
  )");
}

// A drive at rest with its output disabled and a fault whose cause persists: the host clears
// 0x3020, which does not change what the drive is told (disabled either way), and the fault
// still comes back as a new event at the next step.
TEST_F(Solo, AFaultClearedWhileTheDriveRestsComesBackAtTheNextStep) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 08 30 00 00 00 00 00   # disable
    tx 581 [8] 60 08 30 00 00 00 00 00
    rx 601 [8] 22 03 30 00 00 00 00 00   # current limit 0: over-current protection
    tx 581 [8] 60 03 30 00 00 00 00 00
    wait 10
    tx 081 [8] 00 00 00 03 00 00 00 00
    wait 1000
    rx 601 [8] 22 20 30 00 00 00 00 00   # overwrite: the cause is still there
    tx 581 [8] 60 20 30 00 00 00 00 00
    wait 10
    tx 081 [8] 00 00 00 03 00 00 00 00   # a new error event
    rx 601 [8] 40 20 30 00 00 00 00 00
    tx 581 [8] 42 20 30 00 01 00 00 00
  )");
}

TEST_F(Solo, LifeTimeExpiryStopsTheDriveUntilTheErrorRegisterIsCleared) {
  digitalSpeedMode();
  lifeTime200ms();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 05 30 00 E8 03 00 00
    tx 581 [8] 60 05 30 00 00 00 00 00
    rx 701 [0] RTR
    tx 701 [1] FF
    wait 200
    tx 081 [8] 00 00 00 11 00 00 00 00   # CAN communication lost: generic + communication
    rx 601 [8] 40 20 30 00 00 00 00 00
    tx 581 [8] 42 20 30 00 20 00 00 00   # 0x3020 bit 5
    wait 1000
  )");
  EXPECT_LT(speed(), 100.0);  // coasting down
  EXPECT_TRANSCRIPT(R"(
    rx 701 [0] RTR                       # the master is back; the drive stays stopped
    tx 701 [1] 7F
    wait 500
  )");
  EXPECT_EQ(speed(), 0.0);
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 20 30 00 00 00 00 00
    tx 581 [8] 60 20 30 00 00 00 00 00
    rx 701 [0] RTR
    tx 701 [1] FF
    wait 150
  )");
  EXPECT_GT(speed(), 100.0);  // running again
}

TEST_F(Solo, MotorIdentificationFillsResistanceAndInductanceAfterOneSecond) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 07 30 00 01 00 00 00
    tx 581 [8] 60 07 30 00 00 00 00 00
    rx 601 [8] 40 07 30 00 00 00 00 00   # write-only
    tx 581 [8] 80 07 30 00 01 00 01 06
    wait 999
  )");
  EXPECT_EQ(value(0x300D, 0), 0U);
  EXPECT_TRANSCRIPT("wait 1");
  EXPECT_NEAR(sfxt(0x300D), 0.35, 0.0001);
  EXPECT_GT(sfxt(0x300E), 0.0);
}

TEST_F(Solo, NewDeviceAddressTakesEffectAtTheNextReset) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 01 30 00 05 00 00 00
    tx 581 [8] 60 01 30 00 00 00 00 00
    rx 601 [8] 40 01 30 00 00 00 00 00   # still node 1 until the reset
    tx 581 [8] 42 01 30 00 05 00 00 00
    rx 000 [2] 81 01                     # reset node
    tx 705 [1] 00
    rx 605 [8] 40 01 30 00 00 00 00 00   # kept across the reset (M)
    tx 585 [8] 42 01 30 00 05 00 00 00
    rx 605 [8] 22 01 30 00 00 00 00 00   # 0 is not an address
    tx 585 [8] 80 01 30 00 30 00 09 06
  )");
}

// The SOLO has no LSS: without a node-id (255) it could never be reached. Its composition takes
// any node-id outside 1..127 as 1, like 0, and costa-slave refuses --node-id 255 for it.
// (Found by fuzzing: 255 went into 0x3001, whose limits are 1..127.)
TEST(SoloNodeId, NoNodeIdIsNotAStateASoloCanBeIn) {
  InProcessBus bus([](CanTransmitter& can) -> std::unique_ptr<host::DeviceTarget> {
    return std::make_unique<host::HostedTarget<solo::SoloTarget>>(
        nullptr, can, DeviceConfig{255, true, nullptr, nullptr});
  });
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 40 01 30 00 00 00 00 00
    tx 581 [8] 42 01 30 00 01 00 00 00
  )",
                     bus),
            "");
  host::TargetOptions options;
  options.nodeId = 255;
  port::RecordingCan can;
  std::string error;
  EXPECT_EQ(host::createDevice(*host::findDevice("solo"), can, options, &error), nullptr);
  EXPECT_EQ(error, "solo has no LSS: it needs a node-id (--node-id 1..127)");
}

TEST_F(Solo, PdoCobIdsAreLimitedToTheirRanges) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 14 14 01 01 03 00 80   # RPDO on 0x301: outside 0x200-0x27F
    tx 581 [8] 80 14 14 01 30 00 09 06
    rx 601 [8] 22 14 18 01 01 02 00 80   # TPDO on 0x201: outside 0x280-0x2FF
    tx 581 [8] 80 14 18 01 30 00 09 06
    rx 601 [8] 22 14 18 01 01 03 00 00   # disabled: any id
    tx 581 [8] 60 14 18 01 00 00 00 00
  )");
}

TEST_F(Solo, SpeedFeedbackTpdoRampsAtEverySync) {
  digitalSpeedMode();
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 22 15 18 01 81 02 00 C0   # TPDO2 (speed feedback) on 0x281
    tx 581 [8] 60 15 18 01 00 00 00 00
    rx 601 [8] 22 15 18 02 01 00 00 00
    tx 581 [8] 60 15 18 02 00 00 00 00
    rx 000 [2] 01 01
    rx 601 [8] 22 2A 30 00 00 00 14 00
    tx 581 [8] 60 2A 30 00 00 00 00 00
    rx 601 [8] 22 05 30 00 E8 03 00 00
    tx 581 [8] 60 05 30 00 00 00 00 00
  )");
  int32_t previous = -1;
  for (int i = 0; i < 5; ++i) {
    bus_.wait(200);
    CanFrame sync;
    sync.id = 0x080;
    bus_.send(sync);
    CanFrame frame;
    ASSERT_TRUE(bus_.receive(&frame, 0));
    ASSERT_EQ(frame.id, 0x281U);
    ASSERT_EQ(frame.dlc, 4U);
    const int32_t rpm = static_cast<int32_t>(solo::loadData(frame.data));
    EXPECT_GT(rpm, previous);
    EXPECT_NEAR(rpm, 120 * (i + 1), 10);
    previous = rpm;
  }
}

}  // namespace
}  // namespace costa::test
