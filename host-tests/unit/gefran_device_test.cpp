// The GRA/GRN behind their objects: the angle model, the automatic start, faults with their
// EMCY and error behaviour, parameter checks, the LSS parameters and the bit rate they set,
// stored-parameter errors.
#include <gtest/gtest.h>

#include "angle_model.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "device_fixture.hpp"
#include "frame_text.hpp"
#include "gefran_target.hpp"
#include "gra_od.hpp"
#include "recording_bit_rate.hpp"

namespace costa::test {
namespace {

using gefran::AngleSettings;
using gefran::outputAngle;

TEST(GefranAngleModel, ReproducesTheManualsFrames) {
  const AngleSettings ccw{gefran::kTenthDegree, 0, false};
  const AngleSettings cw{gefran::kTenthDegree, 0, true};
  EXPECT_EQ(outputAngle(2, ccw), 0U);         // line 371: 0.0
  EXPECT_EQ(outputAngle(2, cw), 3599U);       // line 371: 359.9
  EXPECT_EQ(outputAngle(12288, ccw), 2700U);  // line 415: 270.0
  EXPECT_EQ(outputAngle(12288, cw), 900U);    // line 415: 90.0
  const AngleSettings fine{gefran::kHundredthDegree, 0, false};
  EXPECT_EQ(outputAngle(12288, fine), 27000U);  // line 430
  const AngleSettings coarse{gefran::kOneDegree, 0, false};
  EXPECT_EQ(outputAngle(12288, coarse), 270U);
  const AngleSettings zeroed{gefran::kTenthDegree, 613, false};
  EXPECT_EQ(outputAngle(2792, zeroed), 0U);                    // example 5
  EXPECT_EQ(outputAngle(0, zeroed), 2987U);                    // wraps below zero
  EXPECT_EQ(outputAngle(0, AngleSettings{50, 0, false}), 0U);  // unknown resolution
  EXPECT_EQ(gefran::rawFromDegrees(270.0), 12288U);
  EXPECT_EQ(gefran::rawFromDegrees(-90.0), 12288U);
  EXPECT_EQ(gefran::rawFromDegrees(360.0), 0U);
  uint8_t big[4] = {};
  uint8_t little[4] = {};
  gefran::packAngles(0x0A8C, 0x0384, false, big);
  gefran::packAngles(0x0A8C, 0x0384, true, little);
  EXPECT_EQ(host::formatFrame(CanFrame{0x182, {big[0], big[1], big[2], big[3]}, 4, false, false}),
            "182 [4] 0A 8C 03 84");
  EXPECT_EQ(host::formatFrame(
                CanFrame{0x182, {little[0], little[1], little[2], little[3]}, 4, false, false}),
            "182 [4] 8C 0A 84 03");
}

class Gra : public DeviceTest {
 protected:
  Gra() : DeviceTest("gra", -1) {}  // the factory node-id
};

TEST_F(Gra, FactoryNodeIdAutomaticStartAndCyclicTpdo) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00                          # boot-up at 0x7F (E1)
    tx 1FF [8] 00 00 00 00 FF FF FF 00     # operational by itself, TPDO at once
    wait 99
    silence
    wait 1
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 77F [0] RTR                         # no node guarding (E48): ignored
    silence
    sim angle 270
    wait 100
    tx 1FF [8] 0A 8C 03 84 FF FF FF 00
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);
}

TEST_F(Gra, AMagneticFieldFaultIsOneEventAndStopsTheNodeWhenAskedTo) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 2F 00 40 00 02 00 00 00     # error behaviour: stopped
    tx 5FF [8] 60 00 40 00 00 00 00 00
    rx 67F [8] 40 01 40 00 00 00 00 00
    tx 5FF [8] 4F 01 40 00 00 00 00 00
    sim fault magnet on
    tx 0FF [8] 00 10 00 83 00 FF FF FF     # one EMCY for the event, 0x4001 = 0x83 (E15)
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kStopped);
  EXPECT_TRANSCRIPT(R"(
    wait 500
    silence                                # no TPDO, no EMCY while stopped
    sim fault magnet off
    rx 000 [2] 80 7F                       # pre-operational
    tx 0FF [8] 00 00 00 00 00 00 00 00     # the error reset waited for a state allowing EMCY
    rx 67F [8] 40 01 40 00 00 00 00 00
    tx 5FF [8] 4F 01 40 00 00 00 00 00
    rx 000 [2] 01 7F
    tx 1FF [8] 00 00 00 00 FF FF FF 00
  )");
}

TEST_F(Gra, ASecondFaultIsANewEventAndClearingAllResets) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    sim fault chip1 on
    wait 100
    tx 0FF [8] 00 10 00 01 00 FF FF FF
    tx 1FF [8] 00 00 00 00 FF FF FF 01
    sim fault chip2 on
    wait 100
    tx 0FF [8] 00 10 00 03 00 FF FF FF
    tx 1FF [8] 00 00 00 00 FF FF FF 03
    sim fault chip1 off
    wait 100
    tx 1FF [8] 00 00 00 00 FF FF FF 02
    sim fault chip2 off
    wait 100
    tx 0FF [8] 00 00 00 00 00 00 00 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
  )");
  EXPECT_EQ(bus_.node().state(), NmtState::kOperational);  // 0x4000 = 1 (factory): no change
}

TEST_F(Gra, ResolutionAndZeroPointChecks) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 2B 00 21 01 E8 03 00 00     # 1000: 1 deg
    tx 5FF [8] 60 00 21 01 00 00 00 00
    rx 67F [8] 2B 01 21 01 68 01 00 00     # zero point 360 = one turn at 1 deg: too high
    tx 5FF [8] 80 01 21 01 31 00 09 06
    rx 67F [8] 2B 01 21 01 67 01 00 00     # 359 is fine
    tx 5FF [8] 60 01 21 01 00 00 00 00
    rx 67F [8] 2B 00 21 01 C8 00 00 00     # 200: not 1000, 100 or 22
    tx 5FF [8] 80 00 21 01 30 00 09 06
  )");
}

TEST_F(Gra, TheStaticTpdoMappingIsReadOnly_06010002) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 000 [2] 80 7F                       # pre-operational, where CiA 301 allows remapping
    rx 67F [8] 2F 00 1A 00 00 00 00 00     # 0x1A00:00 = 0: const (manual line 487)
    tx 5FF [8] 80 00 1A 00 02 00 01 06     # 0x06010002 attempt to write a read-only object
    rx 67F [8] 23 00 1A 01 08 01 10 21     # 0x1A00:01, even with its own value (line 488)
    tx 5FF [8] 80 00 1A 01 02 00 01 06
    rx 67F [8] 40 00 1A 00 00 00 00 00     # unchanged
    tx 5FF [8] 4F 00 1A 00 08 00 00 00
  )");
  EXPECT_EQ(value(0x1A00, 1), 0x21100108U);
}

TEST_F(Gra, LssParametersAreTheNodesPendingConfiguration) {
  EXPECT_TRANSCRIPT(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 40 99 59 01 00 00 00 00
    tx 5FF [8] 4B 99 59 01 FA 00 00 00     # 250 kbit/s
    rx 67F [8] 2B 99 59 01 64 00 00 00     # 100 kbit/s is not in the list (E26)
    tx 5FF [8] 80 99 59 01 30 00 09 06
    rx 67F [8] 2B 99 59 01 20 03 00 00     # 800
    tx 5FF [8] 60 99 59 01 00 00 00 00
    rx 67F [8] 2F 99 59 02 80 00 00 00     # node-id 128
    tx 5FF [8] 80 99 59 02 31 00 09 06
    rx 67F [8] 23 99 59 03 73 61 76 66     # wrong signature
    tx 5FF [8] 80 99 59 03 20 00 00 08
    rx 000 [2] 81 7F                       # reset without save: the setting is lost
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 40 99 59 01 00 00 00 00
    tx 5FF [8] 4B 99 59 01 FA 00 00 00
  )");
  EXPECT_EQ(bus_.node().bitTiming().tableIndex, 3U);
}

// Manual example 1 (host-tests/transcripts/gefran/example-1-baud-rate.transcript): 500 kbit/s
// written to 0x5999:01 and saved reaches the CAN controller at the reset, before the boot-up.
TEST(GefranBitRate, Example1TheSavedBitRateReachesTheControllerAtTheReset) {
  RecordingBitRate rate;
  host::TargetOptions options;
  options.bitRate = &rate;
  InProcessBus bus("gra", 3, options);
  rate.framesSent = [&bus] { return bus.can().count(); };
  EXPECT_EQ(playText(R"(
    ignore 183
    tx 703 [1] 00                          # boot-up at 250 kbit/s
    tx 183 [8] 00 00 00 00 FF FF FF 00
    rx 603 [8] 2B 99 59 01 F4 01 00 00     # 0x5999:01 = 500
    tx 583 [8] 60 99 59 01 00 00 00 00
    rx 603 [8] 23 99 59 03 73 61 76 65     # 0x5999:03 = "save"
    tx 583 [8] 60 99 59 03 00 00 00 00
  )",
                     bus),
            "");
  EXPECT_EQ(rate.count(), 0U);  // before the reset the node stays at 250 kbit/s (E23)
  EXPECT_EQ(bus.node().bitTiming(), (LssBitTiming{0, 3}));
  const size_t sentBeforeReset = bus.can().count();
  EXPECT_EQ(playText(R"(
    ignore 183
    rx 000 [2] 81 03                       # reset node 3
    tx 703 [1] 00                          # boot-up, now at 500 kbit/s
    tx 183 [8] 00 00 00 00 FF FF FF 00
  )",
                     bus),
            "");
  ASSERT_EQ(rate.count(), 1U);
  EXPECT_EQ(rate.at(0).bitsPerSecond, 500000U);
  EXPECT_EQ(rate.at(0).framesBefore, sentBeforeReset);  // switched before the boot-up
  EXPECT_EQ(bus.node().bitTiming(), (LssBitTiming{0, 2}));
}

TEST(GefranStorage, ADamagedLssRecordIsReportedAsALssParameterChecksumError) {
  port::MemoryStorageOf<4096> storage;
  const DeviceConfig config{0, false, &storage, nullptr};  // node-id 0x7F, or a stored one
  {
    port::RecordingCan can;
    gefran::GraTarget target(can, config);
    target.start(0);
    EXPECT_EQ(target.node().storeLssConfiguration(5, LssBitTiming{0, 3}), LssStoreResult::kStored);
  }
  for (size_t i = 0; i < storage.size(); ++i) {  // damage the LSS record's payload bytes
    if (storage.bytes()[i] == 5U) {
      storage.bytes()[i] = 6U;
    }
  }
  port::RecordingCan can;
  gefran::GraTarget target(can, config);
  target.start(0);
  EXPECT_EQ(target.node().nodeId(), 0x7FU);  // defaults
  EXPECT_EQ(target.node().dictionary().readUnsigned(0x4001, 0, 0), 0x40U);
  bool emcy = false;
  for (size_t i = 0; i < can.count(); ++i) {
    emcy = emcy || host::formatFrame(can.at(i)) == "0FF [8] 00 10 00 40 00 FF FF FF";
  }
  EXPECT_TRUE(emcy);
}

TEST(GefranErrors, AProgramChecksumErrorFromTheSensorsPortGivesItsEmcy) {
  // E56: the simulated chips never report 0x10; firmware would, through HallSensors::faults().
  port::MemoryStorageOf<4096> storage;
  port::RecordingCan can;
  gefran::GraTarget target(can, DeviceConfig{0, false, &storage, nullptr});
  target.start(0);
  target.sensors().setFault(gefran::kProgramChecksum, true);
  target.process(0);
  ASSERT_EQ(can.count(), 3U);
  EXPECT_EQ(host::formatFrame(can.at(0)), "77F [1] 00");
  EXPECT_EQ(host::formatFrame(can.at(1)), "1FF [8] 00 00 00 00 FF FF FF 00");
  EXPECT_EQ(host::formatFrame(can.at(2)), "0FF [8] 00 10 00 10 00 FF FF FF");
  EXPECT_EQ(target.node().dictionary().readUnsigned(0x4001, 0, 0), 0x10U);
}

}  // namespace
}  // namespace costa::test
