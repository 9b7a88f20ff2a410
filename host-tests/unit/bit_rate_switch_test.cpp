// The node re-times its CAN controller through NodeSettings::bitRateControl: once, at the LSS
// switch moment, with nothing sent during the switch; at power-on when a stored LSS bit timing
// differs from the settings; never when nothing changes. A refused switch keeps the bit timing
// in use. A device's own bit timing table (selector 128) gives rates outside CiA 305's.
#include <memory>

#include "costa/port/memory/memory_storage.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "example_fixture.hpp"
#include "recording_bit_rate.hpp"

namespace costa::test {
namespace {

constexpr Microseconds kMs = 1000;

/// The example (node-id 1) with a recording bit rate control and `storage`.
DeviceConfig configWith(RecordingBitRate* rate, NvStorage* storage = nullptr) {
  DeviceConfig config;
  config.storage = storage;
  config.bitRateControl = rate;
  return config;
}

class TimingEvents : public NodeEvents {
 public:
  void onBitTimingActivation(LssBitTiming timing) noexcept override {
    ++activations;
    activated = timing;
  }
  int activations = 0;
  LssBitTiming activated{0xFF, 0xFF};
};

/// An example node (node-id 1, 250 kbit/s, heartbeat every 10 ms) with a recording bit rate
/// control, in LSS configuration state with 500 kbit/s configured (CiA 305 index 2).
class LssBitRateSwitch : public ::testing::Test {
 protected:
  LssBitRateSwitch() : bus_(exampleWith(configWith(&rate_))) {
    rate_.clock = [this] { return bus_.now(); };
    rate_.framesSent = [this] { return bus_.can().count(); };
    EXPECT_TRUE(bus_.node().addListener(events_));
  }

  void SetUp() override {
    ASSERT_EQ(playText(R"(
      tx 701 [1] 00
      rx 601 [8] 2B 17 10 00 0A 00 00 00   # heartbeat 10 ms
      tx 581 [8] 60 17 10 00 00 00 00 00
      rx 7E5 [8] 04 01 00 00 00 00 00 00   # switch state global: configuration
      rx 7E5 [8] 13 00 02 00 00 00 00 00   # configure bit timing: 500 kbit/s
      tx 7E4 [8] 13 00 00 00 00 00 00 00
    )",
                       bus_),
              "");
    ASSERT_EQ(rate_.count(), 0U);  // configuring changes nothing yet
  }

  /// Sends activate bit timing with a switch delay of 100 ms; returns the time it arrived.
  Microseconds activate() {
    const Microseconds at = bus_.now();
    EXPECT_EQ(playText("rx 7E5 [8] 15 64 00 00 00 00 00 00", bus_), "");
    return at;
  }

  /// Reads the frames sent so far (heartbeats), so that a transcript starts after them.
  void drain() {
    CanFrame frame;
    while (bus_.receive(&frame, 0)) {
    }
  }
  /// NMT reset communication: the boot-up follows.
  std::string resetCommunication() {
    drain();
    return playText("rx 000 [2] 82 01\ntx 701 [1] 00", bus_);
  }

  RecordingBitRate rate_;
  TimingEvents events_;
  InProcessBus bus_;
};

TEST_F(LssBitRateSwitch, ThePortSwitchesOnceAtTheSwitchMomentAndNothingIsSentMeanwhile) {
  const size_t sent = bus_.can().count();
  const Microseconds activatedAt = activate();
  bus_.advance(100 * kMs - 1);  // the first switch delay: silent, old rate
  EXPECT_EQ(rate_.count(), 0U);
  EXPECT_EQ(bus_.can().count(), sent);
  EXPECT_EQ(bus_.node().bitTiming(), (LssBitTiming{0, 3}));
  bus_.advance(1);  // the switch
  ASSERT_EQ(rate_.count(), 1U);
  EXPECT_EQ(rate_.at(0).bitsPerSecond, 500000U);
  EXPECT_EQ(rate_.at(0).at, activatedAt + 100 * kMs);
  EXPECT_EQ(rate_.at(0).framesBefore, sent);
  EXPECT_EQ(bus_.node().bitTiming(), (LssBitTiming{0, 2}));
  EXPECT_EQ(events_.activations, 1);  // the application is told as before
  EXPECT_EQ(events_.activated, (LssBitTiming{0, 2}));
  bus_.advance(100 * kMs - 1);  // the second switch delay: still silent
  EXPECT_EQ(bus_.can().count(), sent);
  bus_.advance(1);  // transmission resumes, at the new rate
  ASSERT_GT(bus_.can().count(), sent);
  EXPECT_EQ(bus_.can().at(sent).id, 0x701U);
  bus_.advance(1000 * kMs);
  EXPECT_EQ(rate_.count(), 1U);
  // A reset communication keeps the rate: the bit timing in use is already the pending one.
  EXPECT_EQ(resetCommunication(), "");
  EXPECT_EQ(rate_.count(), 1U);
}

TEST_F(LssBitRateSwitch, ARefusedSwitchKeepsTheBitTimingInUseAndIsTriedAgainAtReset) {
  rate_.accept = false;
  activate();
  bus_.advance(100 * kMs);
  ASSERT_EQ(rate_.count(), 1U);
  EXPECT_EQ(rate_.at(0).bitsPerSecond, 500000U);
  EXPECT_EQ(bus_.node().bitTiming(), (LssBitTiming{0, 3}));
  EXPECT_EQ(events_.activations, 1);
  bus_.advance(100 * kMs);
  EXPECT_EQ(resetCommunication(), "");
  ASSERT_EQ(rate_.count(), 2U);
  EXPECT_EQ(rate_.at(1).bitsPerSecond, 500000U);
  EXPECT_EQ(bus_.node().bitTiming(), (LssBitTiming{0, 3}));
  rate_.accept = true;
  EXPECT_EQ(resetCommunication(), "");
  ASSERT_EQ(rate_.count(), 3U);
  EXPECT_EQ(bus_.node().bitTiming(), (LssBitTiming{0, 2}));
}

/// Stores LSS node-id 1 and bit timing `index` in `storage`, as an LSS master would.
void storeBitTiming(NvStorage& storage, uint8_t index) {
  InProcessBus bus(exampleWith(DeviceConfig{0, false, &storage, nullptr}));
  const std::string configure = "rx 7E5 [8] 13 00 0" + std::to_string(index) + " 00 00 00 00 00";
  EXPECT_EQ(playText("tx 701 [1] 00\nrx 7E5 [8] 04 01 00 00 00 00 00 00\n" + configure +
                         "\ntx 7E4 [8] 13 00 00 00 00 00 00 00\n"
                         "rx 7E5 [8] 17 00 00 00 00 00 00 00\n"
                         "tx 7E4 [8] 17 00 00 00 00 00 00 00",
                     bus),
            "");
}

TEST(PowerOnBitRate, AStoredLssBitTimingIsAppliedBeforeTheBootUp) {
  port::MemoryStorageOf<16384> storage;
  storeBitTiming(storage, 4);  // 125 kbit/s
  port::RecordingCan can;
  RecordingBitRate rate;
  rate.framesSent = [&can] { return can.count(); };
  auto target = std::make_unique<example::ExampleTarget>(can, configWith(&rate, &storage));
  {
    NoAllocationScope scope;
    target->start(0);
  }
  ASSERT_EQ(rate.count(), 1U);
  EXPECT_EQ(rate.at(0).bitsPerSecond, 125000U);
  EXPECT_EQ(rate.at(0).framesBefore, 0U);
  ASSERT_GE(can.count(), 1U);
  EXPECT_EQ(can.at(0).id, 0x701U);  // the boot-up, at 125 kbit/s
  EXPECT_EQ(target->node().bitTiming(), (LssBitTiming{0, 4}));
}

TEST(PowerOnBitRate, WithoutAStoredBitTimingThePortKeepsTheRateItWasStartedWith) {
  port::MemoryStorageOf<16384> storage;
  port::RecordingCan can;
  RecordingBitRate rate;
  auto target = std::make_unique<example::ExampleTarget>(can, configWith(&rate, &storage));
  target->start(0);
  EXPECT_EQ(rate.count(), 0U);
  EXPECT_EQ(target->node().bitTiming(), (LssBitTiming{0, 3}));
  storeBitTiming(storage, 3);  // the same rate as the settings: nothing to switch
  auto again = std::make_unique<example::ExampleTarget>(can, configWith(&rate, &storage));
  again->start(0);
  EXPECT_EQ(rate.count(), 0U);
}

/// Rates of a device's own bit timing table (selector 128): 25 kbit/s, and a rate beside it.
constexpr uint32_t kOwnRates[] = {25000, 33333};
constexpr BitRateTable kOwnTable{kOwnRates, 2};

/// An example node whose pending bit timing is `pending` when reset communication runs, with a
/// recording bit rate control and, when `ownTable`, kOwnRates as its table 128.
class OwnBitTimingTable : public ::testing::Test {
 protected:
  std::string resetWith(LssBitTiming pending, bool ownTable) {
    NodeSettings settings;
    settings.bitRateControl = &rate_;
    if (ownTable) {
      settings.manufacturerBitRates = &kOwnTable;
    }
    bus_ = std::make_unique<InProcessBus>(exampleWith(settings));
    bus_->node().setPendingBitTiming(pending);
    return playText("tx 701 [1] 00\nrx 000 [2] 82 01\ntx 701 [1] 00", *bus_);
  }
  RecordingBitRate rate_;
  std::unique_ptr<InProcessBus> bus_;
};

TEST_F(OwnBitTimingTable, AnEntryOfTable128SwitchesToItsRate) {
  EXPECT_EQ(resetWith(LssBitTiming{128, 0}, true), "");
  ASSERT_EQ(rate_.count(), 1U);
  EXPECT_EQ(rate_.at(0).bitsPerSecond, 25000U);
  EXPECT_EQ(bus_->node().bitTiming(), (LssBitTiming{128, 0}));
}

TEST_F(OwnBitTimingTable, CiaEntriesStillHaveTheirRates) {
  EXPECT_EQ(resetWith(LssBitTiming{0, 6}, true), "");
  ASSERT_EQ(rate_.count(), 1U);
  EXPECT_EQ(rate_.at(0).bitsPerSecond, 50000U);
}

TEST_F(OwnBitTimingTable, AnIndexBeyondTheTableOrAnotherTableHasNoRate) {
  EXPECT_EQ(resetWith(LssBitTiming{128, 2}, true), "");
  EXPECT_EQ(resetWith(LssBitTiming{129, 0}, true), "");
  EXPECT_EQ(rate_.count(), 0U);
  EXPECT_EQ(bus_->node().bitTiming(), (LssBitTiming{0, 3}));  // unchanged
}

TEST_F(OwnBitTimingTable, WithoutATableTable128HasNoRate) {
  EXPECT_EQ(resetWith(LssBitTiming{128, 0}, false), "");
  EXPECT_EQ(rate_.count(), 0U);
  EXPECT_EQ(bus_->node().bitTiming(), (LssBitTiming{0, 3}));
}

}  // namespace
}  // namespace costa::test
