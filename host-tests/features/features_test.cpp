// The optional services on the wire, with and without them. This file is built against the
// stack with every optional feature (costa_features_on_tests), with none
// (costa_features_off_tests) and with some (costa_features_some_tests). Each test expects what
// CiA 301/305 ask of a device with, or without, the service; the build says which
// (costa/features.hpp).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <type_traits>

#include "bare_node_bus.hpp"
#include "costa/features.hpp"
#include "costa/indicators.hpp"

#ifndef COSTA_EXPECTED_FEATURES
#error "COSTA_EXPECTED_FEATURES (the features CMake compiled in, such as \"LSS,SDO_BLOCK\")"
#endif

namespace costa::test {
namespace {

/// Transcript lines for a device with the feature, or without it.
std::string lines(bool feature, const std::string& with, const std::string& without) {
  return (feature ? with : without) + "\n";
}

class FeaturesTest : public ::testing::Test {
 protected:
  std::string play(const std::string& text) { return playText(text, *bus_); }
  uint32_t ignored() { return bus_->node().statistics().framesIgnored; }

  std::unique_ptr<BareNodeBus> bus_ = std::make_unique<BareNodeBus>();
};

// The executable is built against the stack it claims: otherwise the tests below could check
// one variant several times.
TEST(FeaturesBuild, IsTheVariantCMakeAskedFor) {
  std::string compiledIn;
  const auto add = [&compiledIn](bool feature, const char* name) {
    if (feature) {
      compiledIn += (compiledIn.empty() ? "" : ",") + std::string(name);
    }
  };
  add(features::kSdoBlockTransfer, "SDO_BLOCK");
  add(features::kLss, "LSS");
  add(features::kNodeGuarding, "NODE_GUARDING");
  add(features::kHeartbeatConsumer, "HEARTBEAT_CONSUMER");
  add(features::kParameterStorage, "PARAMETER_STORAGE");
  add(features::kTime, "TIME");
  add(features::kEmcyConsumer, "EMCY_CONSUMER");
  add(features::kSdoServers, "SDO_SERVERS");
  add(features::kSafety, "SAFETY");
  add(features::kIndicators, "INDICATORS");
  add(features::kQuirkProfiles, "QUIRK_PROFILES");
  EXPECT_EQ(compiledIn, COSTA_EXPECTED_FEATURES);
}

TEST_F(FeaturesTest, BlockDownloadInitiateIsAnUnknownCommandWithoutBlockTransfer) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] C6 00 20 00 04 00 00 00  # block download 0x2000:00, CRC, 4 bytes\n" +
                 lines(features::kSdoBlockTransfer,
                       "tx 581 [8] A4 00 20 00 01 00 00 00  # CRC, one segment per sub-block\n"
                       "rx 601 [8] 80 00 20 00 00 00 00 08  # the client gives up",
                       "tx 581 [8] 80 00 20 00 01 00 04 05  # command specifier not valid") +
                 "rx 601 [8] 23 00 20 00 D0 07 00 00  # expedited download 0x2000 = 2000\n"
                 "tx 581 [8] 60 00 20 00 00 00 00 00\n"),
            "");
}

TEST_F(FeaturesTest, BlockUploadInitiateIsAnUnknownCommandWithoutBlockTransfer) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] A4 08 10 00 7F 00 00 00  # block upload 0x1008:00, 127 per block\n" +
                 lines(features::kSdoBlockTransfer,
                       "tx 581 [8] C6 08 10 00 0D 00 00 00  # CRC, size 13\n"
                       "rx 601 [8] 80 08 10 00 00 00 00 08  # the client gives up",
                       "tx 581 [8] 80 08 10 00 01 00 04 05  # command specifier not valid") +
                 "rx 601 [8] 40 08 10 00 00 00 00 00  # segmented upload 0x1008:00\n"
                 "tx 581 [8] 41 08 10 00 0D 00 00 00\n"
                 "rx 601 [8] 60 00 00 00 00 00 00 00\n"
                 "tx 581 [8] 00 43 6F 73 74 61 20 65\n"
                 "rx 601 [8] 70 00 00 00 00 00 00 00\n"
                 "tx 581 [8] 13 78 61 6D 70 6C 65 00\n"),
            "");
}

TEST_F(FeaturesTest, LssFramesAreIgnoredWithoutLss) {
  EXPECT_EQ(play("tx 701 [1] 00\n"), "");
  const uint32_t before = ignored();
  EXPECT_EQ(
      play("rx 7E5 [8] 04 01 00 00 00 00 00 00  # switch state global: configuration\n"
           "rx 7E5 [8] 5E 00 00 00 00 00 00 00  # inquire node-id\n" +
           lines(features::kLss, "tx 7E4 [8] 5E 01 00 00 00 00 00 00", "silence") +
           "rx 7E5 [8] 11 05 00 00 00 00 00 00  # configure node-id 5\n" +
           lines(features::kLss, "tx 7E4 [8] 11 00 00 00 00 00 00 00", "silence") +
           "rx 7E5 [8] 17 00 00 00 00 00 00 00  # store configuration\n" +
           lines(features::kLss,
                 lines(features::kParameterStorage, "tx 7E4 [8] 17 00 00 00 00 00 00 00  # stored",
                       "tx 7E4 [8] 17 01 00 00 00 00 00 00  # not supported"),
                 "silence") +
           "rx 000 [2] 82 01                    # reset communication\n" +
           lines(features::kLss, "tx 705 [1] 00", "tx 701 [1] 00")),
      "");
  EXPECT_EQ(ignored() - before, features::kLss ? 0U : 4U);
}

TEST_F(FeaturesTest, RemoteRequestsAreIgnoredWithoutNodeGuarding) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 2B 0C 10 00 64 00 00 00  # guard time 100 ms\n" +
                 lines(features::kNodeGuarding, "tx 581 [8] 60 0C 10 00 00 00 00 00",
                       "tx 581 [8] 80 0C 10 00 00 00 02 06  # object does not exist") +
                 "rx 601 [8] 2F 0D 10 00 03 00 00 00  # life time factor 3\n" +
                 lines(features::kNodeGuarding, "tx 581 [8] 60 0D 10 00 00 00 00 00",
                       "tx 581 [8] 80 0D 10 00 00 00 02 06") +
                 "rx 601 [8] 40 0C 10 00 00 00 00 00\n" +
                 lines(features::kNodeGuarding, "tx 581 [8] 4B 0C 10 00 64 00 00 00",
                       "tx 581 [8] 80 0C 10 00 00 00 02 06")),
            "");
  const uint32_t before = ignored();
  EXPECT_EQ(
      play("rx 701 [0] RTR                      # guard request\n" +
           lines(features::kNodeGuarding, "tx 701 [1] 7F  # pre-operational, toggle 0", "silence") +
           "wait 300\n" +
           lines(features::kNodeGuarding,
                 "tx 081 [8] 30 81 11 00 00 00 00 00  # life guarding expired", "silence")),
      "");
  EXPECT_EQ(ignored() - before, features::kNodeGuarding ? 0U : 1U);
}

TEST_F(FeaturesTest, HeartbeatsAreIgnoredWithoutHeartbeatConsumer) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 23 16 10 01 64 00 05 00  # 0x1016:01: node 5 within 100 ms\n" +
                 lines(features::kHeartbeatConsumer, "tx 581 [8] 60 16 10 01 00 00 00 00",
                       "tx 581 [8] 80 16 10 01 00 00 02 06  # object does not exist")),
            "");
  const uint32_t before = ignored();
  EXPECT_EQ(
      play("rx 705 [1] 05                      # node 5 is operational\n"
           "wait 150\n" +
           lines(features::kHeartbeatConsumer,
                 "tx 081 [8] 30 81 11 05 00 00 00 00  # node 5 missed its heartbeat", "silence")),
      "");
  EXPECT_EQ(ignored() - before, features::kHeartbeatConsumer ? 0U : 1U);
}

TEST_F(FeaturesTest, TimeIsIgnoredWithoutTime) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 40 12 10 00 00 00 00 00  # 0x1012, COB-ID TIME\n" +
                 lines(features::kTime, "tx 581 [8] 43 12 10 00 00 01 00 80  # consumer, 0x100",
                       "tx 581 [8] 80 12 10 00 00 00 02 06  # object does not exist")),
            "");
  const uint32_t before = ignored();
  EXPECT_EQ(play("rx 100 [6] 10 27 00 00 2C 01  # 00:00:10.000, day 300\n"), "");
  EXPECT_EQ(ignored() - before, features::kTime ? 0U : 1U);
  TimeOfDay time;
  EXPECT_EQ(bus_->node().timeOfDay(&time), features::kTime);
}

TEST_F(FeaturesTest, OtherNodesEmergenciesAreIgnoredWithoutEmcyConsumer) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 40 28 10 01 00 00 00 00  # 0x1028:01\n" +
                 lines(features::kEmcyConsumer, "tx 581 [8] 43 28 10 01 82 00 00 00  # node 2's",
                       "tx 581 [8] 80 28 10 01 00 00 02 06  # object does not exist")),
            "");
  const uint32_t before = ignored();
  EXPECT_EQ(play("rx 082 [8] 10 81 11 00 00 00 00 00  # node 2: CAN overrun\n"), "");
  EXPECT_EQ(ignored() - before, features::kEmcyConsumer ? 0U : 1U);
}

TEST_F(FeaturesTest, AdditionalSdoServersDoNotExistWithoutThem) {
  // The bare node's dictionary has 0x1201 (not valid); without the feature it does not exist.
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 40 01 12 01 00 00 00 00  # 0x1201:01\n" +
                 lines(features::kSdoServers, "tx 581 [8] 43 01 12 01 00 00 00 80  # not valid",
                       "tx 581 [8] 80 01 12 01 00 00 02 06  # object does not exist") +
                 "rx 601 [8] 23 01 12 01 81 06 00 00  # 0x681, valid\n" +
                 lines(features::kSdoServers, "tx 581 [8] 60 01 12 01 00 00 00 00",
                       "tx 581 [8] 80 01 12 01 00 00 02 06") +
                 "rx 601 [8] 23 01 12 02 C1 06 00 00  # 0x6C1, valid\n" +
                 lines(features::kSdoServers, "tx 581 [8] 60 01 12 02 00 00 00 00",
                       "tx 581 [8] 80 01 12 02 00 00 02 06") +
                 "rx 681 [8] 40 00 10 00 00 00 00 00  # to the additional server\n" +
                 lines(features::kSdoServers, "tx 6C1 [8] 43 00 10 00 xx xx xx xx", "")),
            "");
}

TEST_F(FeaturesTest, GlobalFailSafeIsIgnoredWithoutSafety) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 40 00 13 00 00 00 00 00  # 0x1300, GFC valid\n" +
                 lines(features::kSafety, "tx 581 [8] 4F 00 13 00 01 00 00 00",
                       "tx 581 [8] 80 00 13 00 00 00 02 06  # object does not exist")),
            "");
  const uint32_t before = ignored();
  EXPECT_EQ(play("rx 001 [0]\n"), "");
  EXPECT_EQ(ignored() - before, features::kSafety ? 0U : 1U);
  EXPECT_EQ(bus_->node().sendGlobalFailSafe(), features::kSafety);
  EXPECT_EQ(play(lines(features::kSafety, "tx 001 [0]", "")), "");
}

TEST_F(FeaturesTest, SrdosDoNotExistWithoutSafety) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 2F FE 13 00 A5 00 00 00  # 0x13FE, configuration valid\n" +
                 lines(features::kSafety, "tx 581 [8] 60 FE 13 00 00 00 00 00",
                       "tx 581 [8] 80 FE 13 00 00 00 02 06  # object does not exist") +
                 "rx 000 [2] 01 00\n" +
                 lines(features::kSafety,
                       "tx 101 [6] 00 00 00 00 34 12\ntx 102 [6] FF FF FF FF CB ED", "")),
            "");
  // Without the service nothing supervises the working state: it is always allowed.
  EXPECT_TRUE(bus_->node().workingStateAllowed());
  const uint32_t before = ignored();
  EXPECT_EQ(play("rx 104 [4] EE DD CC BB  # SRDO 2's inverted frame alone\n" +
                 lines(features::kSafety, "tx 081 [8] 00 82 11 04 02 00 00 00", "")),
            "");
  EXPECT_EQ(bus_->node().workingStateAllowed(), !features::kSafety);
  EXPECT_EQ(ignored() - before, features::kSafety ? 0U : 1U);
}

TEST_F(FeaturesTest, NothingIsStoredWithoutParameterStorage) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 40 10 10 01 00 00 00 00  # 0x1010:01, save all\n" +
                 lines(features::kParameterStorage,
                       "tx 581 [8] 43 10 10 01 01 00 00 00  # saves on command",
                       "tx 581 [8] 80 10 10 01 00 00 02 06  # object does not exist") +
                 "rx 601 [8] 23 00 20 00 D0 07 00 00  # 0x2000 = 2000\n"
                 "tx 581 [8] 60 00 20 00 00 00 00 00\n"
                 "rx 601 [8] 23 10 10 01 73 61 76 65  # \"save\"\n" +
                 lines(features::kParameterStorage, "tx 581 [8] 60 10 10 01 00 00 00 00",
                       "tx 581 [8] 80 10 10 01 00 00 02 06") +
                 "rx 000 [2] 81 01                    # reset node\n"
                 "tx 701 [1] 00\n"
                 "rx 601 [8] 40 00 20 00 00 00 00 00\n" +
                 lines(features::kParameterStorage,
                       "tx 581 [8] 43 00 20 00 D0 07 00 00  # the stored value",
                       "tx 581 [8] 43 00 20 00 E8 03 00 00  # the default, 1000") +
                 "rx 601 [8] 23 11 10 01 6C 6F 61 64  # \"load\" to 0x1011:01\n" +
                 lines(features::kParameterStorage, "tx 581 [8] 60 11 10 01 00 00 00 00",
                       "tx 581 [8] 80 11 10 01 00 00 02 06")),
            "");
}

// A standard frame with an identifier beyond 11 bits, which no controller delivers, is ignored,
// also while the routing table waits to be rebuilt after a COB-ID changed (a build without
// additional SDO servers rebuilds it at the next frame).
TEST_F(FeaturesTest, AStandardFrameBeyondElevenBitsIsIgnoredWhileTheRoutesAreStale) {
  EXPECT_EQ(play("tx 701 [1] 00\n"
                 "rx 601 [8] 23 00 14 01 01 02 00 80  # RPDO 1 not valid: its route goes\n"
                 "tx 581 [8] 60 00 14 01 00 00 00 00\n"),
            "");
  const uint32_t before = ignored();
  CanFrame frame;
  frame.id = 0xFFFFFFFFU;
  frame.dlc = 8;
  frame.data[0] = 0x40;  // an upload request of 0x1000:00
  bus_->send(frame);
  EXPECT_EQ(play("silence\n"), "");
  EXPECT_EQ(ignored() - before, 1U);
}

/// Each switch of the two LEDs, as "1" (on) and "0" (off).
class RecordingLeds final : public IndicatorOutputs {
 public:
  void setRun(bool on) noexcept override { run += on ? "1" : "0"; }
  void setError(bool on) noexcept override { error += on ? "1" : "0"; }
  std::string run;
  std::string error;
};

TEST_F(FeaturesTest, IndicatorsDriveTheLedsOnlyInABuildWithThem) {
  RecordingLeds leds;
  IndicatorsChoice indicators(bus_->node(), leds);
  EXPECT_EQ(play("tx 701 [1] 00  # boot-up: pre-operational\n"), "");
  constexpr Microseconds kStart = 5000000;
  EXPECT_EQ(indicators.process(kStart), features::kIndicators ? kStart + 200000U : kNever);
  EXPECT_EQ(indicators.process(kStart + 200000U),
            features::kIndicators ? kStart + 400000U : kNever);
  // Blinking: on, then off 200 ms later; no error. Without the feature, nothing is driven.
  EXPECT_EQ(leds.run, features::kIndicators ? "10" : "");
  EXPECT_EQ(leds.error, "");
  EXPECT_EQ(indicators.attached(), features::kIndicators);
  EXPECT_EQ(indicators.run(),
            features::kIndicators ? IndicatorState::kBlinking : IndicatorState::kOff);
}

TEST_F(FeaturesTest, EveryBuildHasNmtHeartbeatSdoAndPdos) {
  EXPECT_EQ(play(R"(
    tx 701 [1] 00
    rx 601 [8] 2B 17 10 00 64 00 00 00  # heartbeat every 100 ms
    tx 581 [8] 60 17 10 00 00 00 00 00
    wait 100
    tx 701 [1] 7F
    rx 000 [2] 01 01                    # start
    wait 100
    tx 701 [1] 05
    rx 601 [8] 40 00 10 00 00 00 00 00  # device type
    tx 581 [8] 43 00 10 00 xx xx xx xx
  )"),
            "");
}

// A quirk profile changes the wire only in a build with quirk profiles. Without them every field
// of the profile is a constant (there is nothing to set), and the node answers as CiA 301 says.
TEST(QuirkProfiles, ChangeTheWireOnlyInABuildWithThem) {
  static_assert((std::is_empty_v<SdoProfile> && std::is_empty_v<PdoProfile> &&
                 std::is_empty_v<EmcyProfile> && std::is_empty_v<ErrorControlProfile>) ==
                !features::kQuirkProfiles);
  static_assert(SdoProfile{}.expeditedUpload == ExpeditedUploadFormat::kSizeIndicated &&
                SdoProfile{}.shortestRequest == 8U && EmcyProfile{}.errorResetFrame &&
                PdoProfile{}.cobIdPolarity == PdoCobIdPolarity::kCia301);
  DeviceProfile profile{};
#if COSTA_QUIRK_PROFILES
  profile.sdo.expeditedUpload = ExpeditedUploadFormat::kFourBytesSizeNotIndicated;
#endif
  BareNodeBus bus(profile);
  EXPECT_EQ(playText("tx 701 [1] 00\n"
                     "rx 601 [8] 40 00 10 00 00 00 00 00  # device type\n" +
                         lines(features::kQuirkProfiles, "tx 581 [8] 42 00 10 00 xx xx xx xx",
                               "tx 581 [8] 43 00 10 00 xx xx xx xx"),
                     bus),
            "");
}

// Node::setPendingBitTiming() is the application's, whatever LSS and storage: its timing becomes
// the one in use at the next reset communication (not before; a reset node would first read
// the configured or stored timing again).
TEST_F(FeaturesTest, AnApplicationsPendingBitTimingAppliesAtResetCommunicationInEveryBuild) {
  ASSERT_EQ(play("tx 701 [1] 00"), "");
  const LssBitTiming before = bus_->node().bitTiming();
  LssBitTiming pending;
  pending.tableIndex = before.tableIndex == 2U ? 3U : 2U;  // 500 or 250 kbit/s
  bus_->node().setPendingBitTiming(pending);
  EXPECT_EQ(bus_->node().bitTiming(), before);  // not yet
  EXPECT_EQ(play(R"(
    rx 000 [2] 82 01                    # reset communication
    tx 701 [1] 00
  )"),
            "");
  EXPECT_EQ(bus_->node().bitTiming(), pending);
}

}  // namespace
}  // namespace costa::test
