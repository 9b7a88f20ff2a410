// 0x1010 store parameters and 0x1011 restore default parameters on a node with storage:
// values kept across resets and power cycles, defaults back after "load", signatures, damaged
// images, and nothing written without an explicit save.
#include <memory>

#include "costa/port/memory/memory_storage.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

class RecordingStoreEvents : public NodeEvents {
 public:
  void onStoredParametersInvalid(uint8_t group, StoreResult result) noexcept override {
    lastGroup = group;
    lastResult = result;
    ++count;
  }
  uint8_t lastGroup = 0;
  StoreResult lastResult = StoreResult::kOk;
  int count = 0;
};

class StoreRestore : public ::testing::Test {
 protected:
  StoreRestore() { powerOn(); }

  /// A new node over the same storage, as after a power cycle.
  void powerOn(NodeEvents* events = nullptr) {
    bus_.reset();
    NodeSettings settings = example::ExampleTarget::settings();
    settings.saveParametersOnWrite = savesOnWrite_;
    settings.storage = &storage_;
    settings.storageSlotAlignment = alignment_;
    auto factory = exampleWith(settings);
    bus_ = std::make_unique<InProcessBus>([&](CanTransmitter& can) {
      auto target = factory(can);
      if (events != nullptr) {
        EXPECT_TRUE(target->node().addListener(*events));
      }
      return target;
    });
    ASSERT_EQ(play("tx 701 [1] 00"), "");
  }
  std::string play(const std::string& text) { return playText(text, *bus_); }
  uint64_t value(uint16_t index, uint8_t sub) {
    return bus_->node().dictionary().readUnsigned(index, sub, 0xDEADBEEFU);
  }

  port::MemoryStorageOf<16384> storage_;
  size_t alignment_ = 1;
  bool savesOnWrite_ = false;
  std::unique_ptr<InProcessBus> bus_;
};

constexpr const char* kChangeValues = R"(
    rx 601 [8] 23 05 10 00 90 00 00 00   # SYNC COB-ID 0x090 (communication)
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 601 [8] 23 00 20 00 20 4E 00 00   # setpoint 20000 (application)
    tx 581 [8] 60 00 20 00 00 00 00 00
)";

TEST_F(StoreRestore, CapabilitiesAreReadable) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 10 10 01 00 00 00 00
    tx 581 [8] 43 10 10 01 01 00 00 00   # saves on command
    rx 601 [8] 40 10 10 03 00 00 00 00
    tx 581 [8] 43 10 10 03 01 00 00 00
    rx 601 [8] 40 11 10 02 00 00 00 00
    tx 581 [8] 43 11 10 02 01 00 00 00
  )");
}

TEST_F(StoreRestore, ANodeThatSavesEveryWriteShowsItIn1010) {
  savesOnWrite_ = true;
  powerOn();
  EXPECT_EQ(play(R"(
    rx 601 [8] 40 10 10 01 00 00 00 00
    tx 581 [8] 43 10 10 01 03 00 00 00   # on command and autonomously
    rx 601 [8] 40 10 10 03 00 00 00 00
    tx 581 [8] 43 10 10 03 03 00 00 00
    rx 601 [8] 40 11 10 01 00 00 00 00
    tx 581 [8] 43 11 10 01 01 00 00 00   # restoring stays on command
  )"),
            "");
}

TEST_F(StoreRestore, StoredValuesSurviveResetNodeAndPowerCycles) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65   # "save" all
    tx 581 [8] 60 10 10 01 00 00 00 00
    rx 601 [8] 23 00 20 00 30 75 00 00   # 30000, not saved
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 000 [2] 81 01                     # reset node
    tx 701 [1] 00
  )");
  EXPECT_EQ(value(0x1005, 0), 0x90U);
  EXPECT_EQ(value(0x2000, 0), 20000U);
  powerOn();
  EXPECT_EQ(value(0x1005, 0), 0x90U);
  EXPECT_EQ(value(0x2000, 0), 20000U);
}

// A firmware whose limits were wider stored values this one refuses (the layout is the same:
// layoutId does not cover limits). Each such value loads as its entry's default; the others load.
TEST_F(StoreRestore, AStoredValueThisFirmwareRefusesLoadsAsItsDefault) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 2F 29 10 01 02 00 00 00   # communication error behaviour 2: its highest
    tx 581 [8] 60 29 10 01 00 00 00 00
    rx 601 [8] 2F 04 20 01 01 00 00 00   # BOOLEAN 0x2004:01 true
    tx 581 [8] 60 04 20 01 00 00 00 00
    rx 601 [8] 2F 29 10 01 03 00 00 00   # above 0x1029:01's limits (0..2)
    tx 581 [8] 80 29 10 01 31 00 09 06   # 0x06090031: value too high
  )");
  // What the wider firmware would have stored: 3, and a BOOLEAN of 2.
  od::ObjectDictionary& dictionary = bus_->node().dictionary();
  ASSERT_TRUE(dictionary.storeUnsigned(0x1029, 1, 3));
  ASSERT_TRUE(dictionary.storeUnsigned(0x2004, 1, 2));
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 10 10 01 73 61 76 65   # "save" all
    tx 581 [8] 60 10 10 01 00 00 00 00
  )");
  powerOn();
  EXPECT_EQ(value(0x1029, 1), 0U) << "the default, not 3";
  EXPECT_EQ(value(0x2004, 1), 0U) << "the default, not 2";
  EXPECT_EQ(value(0x1005, 0), 0x90U) << "the rest of the communication area";
  EXPECT_EQ(value(0x2000, 0), 20000U) << "the rest of the application area";
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 29 10 01 00 00 00 00
    tx 581 [8] 4F 29 10 01 00 00 00 00
    rx 601 [8] 40 04 20 01 00 00 00 00
    tx 581 [8] 4F 04 20 01 00 00 00 00
  )");
}

TEST_F(StoreRestore, CommunicationAndApplicationAreSavedSeparately) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 03 73 61 76 65   # "save" application only
    tx 581 [8] 60 10 10 03 00 00 00 00
    rx 000 [2] 81 01
    tx 701 [1] 00
  )");
  EXPECT_EQ(value(0x1005, 0), 0x80U);
  EXPECT_EQ(value(0x2000, 0), 20000U);
}

TEST_F(StoreRestore, RestoreTakesEffectAtTheNextReset) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65
    tx 581 [8] 60 10 10 01 00 00 00 00
    rx 601 [8] 23 11 10 01 6C 6F 61 64   # "load" all
    tx 581 [8] 60 11 10 01 00 00 00 00
  )");
  EXPECT_EQ(value(0x2000, 0), 20000U);  // not yet
  EXPECT_TRANSCRIPT("rx 000 [2] 81 01\ntx 701 [1] 00");
  EXPECT_EQ(value(0x1005, 0), 0x80U);
  EXPECT_EQ(value(0x2000, 0), 1000U);
  powerOn();
  EXPECT_EQ(value(0x2000, 0), 1000U);
}

TEST_F(StoreRestore, ResetCommunicationReloadsOnlyTheCommunicationArea) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65
    tx 581 [8] 60 10 10 01 00 00 00 00
    rx 601 [8] 23 05 10 00 A0 00 00 00
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 601 [8] 23 00 20 00 30 75 00 00
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
  )");
  EXPECT_EQ(value(0x1005, 0), 0x90U);   // stored communication value
  EXPECT_EQ(value(0x2000, 0), 30000U);  // application untouched
}

TEST_F(StoreRestore, RestoringCommunicationDefaultsAppliesAtResetCommunication) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65   # "save" all: SYNC 0x090, setpoint 20000
    tx 581 [8] 60 10 10 01 00 00 00 00
    rx 601 [8] 23 11 10 02 6C 6F 61 64   # "load" communication
    tx 581 [8] 60 11 10 02 00 00 00 00
    rx 601 [8] 40 05 10 00 00 00 00 00   # nothing changes before the reset
    tx 581 [8] 43 05 10 00 90 00 00 00
    rx 000 [2] 82 01                     # reset communication
    tx 701 [1] 00
    rx 601 [8] 40 05 10 00 00 00 00 00   # SYNC: the default
    tx 581 [8] 43 05 10 00 80 00 00 00
    rx 601 [8] 40 00 20 00 00 00 00 00   # setpoint: still the stored value
    tx 581 [8] 43 00 20 00 20 4E 00 00
    rx 000 [2] 81 01                     # reset node: application loaded from storage again
    tx 701 [1] 00
    rx 601 [8] 40 05 10 00 00 00 00 00
    tx 581 [8] 43 05 10 00 80 00 00 00
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 20 4E 00 00
  )");
  powerOn();
  EXPECT_EQ(value(0x1005, 0), 0x80U);
  EXPECT_EQ(value(0x2000, 0), 20000U);
}

TEST_F(StoreRestore, RestoringApplicationDefaultsAppliesAtResetNode) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65   # "save" all: SYNC 0x090, setpoint 20000
    tx 581 [8] 60 10 10 01 00 00 00 00
    rx 601 [8] 23 11 10 03 6C 6F 61 64   # "load" application
    tx 581 [8] 60 11 10 03 00 00 00 00
    rx 000 [2] 82 01                     # reset communication leaves the application alone
    tx 701 [1] 00
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 20 4E 00 00
    rx 000 [2] 81 01                     # reset node
    tx 701 [1] 00
    rx 601 [8] 40 00 20 00 00 00 00 00   # setpoint: the default 1000
    tx 581 [8] 43 00 20 00 E8 03 00 00
    rx 601 [8] 40 05 10 00 00 00 00 00   # SYNC: still the stored value
    tx 581 [8] 43 05 10 00 90 00 00 00
  )");
  powerOn();
  EXPECT_EQ(value(0x1005, 0), 0x90U);
  EXPECT_EQ(value(0x2000, 0), 1000U);
}

TEST_F(StoreRestore, WrongSignaturesAbort_08000020) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 10 10 01 73 61 76 66   # "savf"
    tx 581 [8] 80 10 10 01 20 00 00 08
    rx 601 [8] 23 11 10 01 73 61 76 65   # "save" is not "load"
    tx 581 [8] 80 11 10 01 20 00 00 08
    rx 601 [8] 2B 10 10 01 73 61 00 00   # 2 bytes
    tx 581 [8] 80 10 10 01 20 00 00 08
    rx 601 [8] 2F 10 10 00 03 00 00 00   # sub-index 0 is read-only
    tx 581 [8] 80 10 10 00 02 00 01 06
  )");
  EXPECT_EQ(storage_.modifyingCalls(), 0U);
}

TEST_F(StoreRestore, NothingIsWrittenWithoutAnExplicitSave) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 000 [2] 01 01
    rx 201 [5] 10 27 00 00 F6
    rx 000 [2] 81 01
    tx 701 [1] 00
    rx 000 [2] 82 01
    tx 701 [1] 00
  )");
  powerOn();
  EXPECT_EQ(storage_.modifyingCalls(), 0U);
}

TEST_F(StoreRestore, ADamagedImageGivesDefaultsAndAReportedError) {
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65
    tx 581 [8] 60 10 10 01 00 00 00 00
  )");
  // Flip one byte in every slot's payload: the images no longer match their CRC.
  for (size_t offset = 40; offset < storage_.size(); offset += 97) {
    storage_.bytes()[offset] ^= 0x5AU;
  }
  RecordingStoreEvents events;
  powerOn(&events);
  EXPECT_EQ(value(0x1005, 0), 0x80U);
  EXPECT_EQ(value(0x2000, 0), 1000U);
  EXPECT_GE(events.count, 1);
  EXPECT_EQ(events.lastResult, StoreResult::kCorrupt);
}

TEST_F(StoreRestore, SlotsFollowTheConfiguredFlashPageAlignment) {
  alignment_ = 256;
  powerOn();
  const ParameterStore* store = bus_->node().parameterStore();
  ASSERT_NE(store, nullptr);
  EXPECT_EQ(store->requiredSize() % 256U, 0U);
  EXPECT_TRANSCRIPT(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65
    tx 581 [8] 60 10 10 01 00 00 00 00
  )");
  // Every image ("CSTP" first) starts on a 256-byte page; nothing else does.
  size_t images = 0;
  for (size_t offset = 0; offset + 4 <= storage_.size(); ++offset) {
    const uint8_t* at = storage_.bytes() + offset;
    if (at[0] == 0x43 && at[1] == 0x53 && at[2] == 0x54 && at[3] == 0x50) {
      EXPECT_EQ(offset % 256U, 0U) << "image at " << offset;
      ++images;
    }
  }
  EXPECT_GE(images, 2U);  // communication and application
  powerOn();
  EXPECT_EQ(value(0x1005, 0), 0x90U);
  EXPECT_EQ(value(0x2000, 0), 20000U);
}

TEST(StoreWithoutStorage, CapabilitiesAreZeroAndSavesAbort) {
  InProcessBus bus("example", 1);
  EXPECT_EQ(playText(R"(
    tx 701 [1] 00
    rx 601 [8] 40 10 10 01 00 00 00 00
    tx 581 [8] 43 10 10 01 00 00 00 00
    rx 601 [8] 23 10 10 01 73 61 76 65
    tx 581 [8] 80 10 10 01 20 00 00 08
  )",
                     bus),
            "");
}

}  // namespace
}  // namespace costa::test
