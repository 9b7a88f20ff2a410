// "save" to 0x1010:01 (every group) through the wire, with the power cut after every byte the
// save programs or erases: after the next power-on, each storage area is its complete old set
// or its complete new set, value by value, never a mix and never reported as damaged. Groups
// are saved one after the other in ascending order (communication, then application), so a cut
// may leave the communication area new and the application area old (docs/storage.md, "Save
// all").
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "costa/port/memory/memory_storage.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

using Storage = port::MemoryStorageOf<16384>;

class CountingStoreEvents : public NodeEvents {
 public:
  void onStoredParametersInvalid(uint8_t group, StoreResult result) noexcept override {
    (void)group;
    (void)result;
    ++count;
  }
  int count = 0;
};

/// One stored entry: where it is and its RAM bytes.
struct StoredValue {
  uint16_t index;
  uint8_t subIndex;
  std::vector<uint8_t> bytes;
  bool operator==(const StoredValue& other) const {
    return index == other.index && subIndex == other.subIndex && bytes == other.bytes;
  }
};

/// Every entry of `group`, value by value, in dictionary order.
std::vector<StoredValue> groupValues(od::ObjectDictionary& dictionary, uint8_t group) {
  std::vector<StoredValue> values;
  for (const od::EntryRef& ref : od::Entries(dictionary.definition())) {
    const uint8_t* address = dictionary.ramAddress(ref);
    if (ref.group() == group && address != nullptr) {
      values.push_back(
          {ref.index(), ref.subIndex(), std::vector<uint8_t>(address, address + ref.size())});
    }
  }
  return values;
}

/// "old", "new", or the entries that match neither set (a mix: never expected).
std::string classify(const std::vector<StoredValue>& actual, const std::vector<StoredValue>& oldSet,
                     const std::vector<StoredValue>& newSet) {
  if (actual == oldSet) {
    return "old";
  }
  if (actual == newSet) {
    return "new";
  }
  std::ostringstream mix;
  mix << "mixed:";
  for (size_t i = 0; i < actual.size() && i < oldSet.size() && i < newSet.size(); ++i) {
    mix << " " << std::hex << actual[i].index << ":" << int{actual[i].subIndex}
        << (actual[i] == oldSet[i]   ? "=old"
            : actual[i] == newSet[i] ? "=new"
                                     : "=neither");
  }
  return mix.str();
}

/// A node over `storage`, as after a power-on; it must send its boot-up and nothing else.
std::unique_ptr<InProcessBus> powerOn(Storage& storage, NodeEvents* events = nullptr) {
  const auto factory = exampleWith(DeviceConfig{0, false, &storage, nullptr});
  auto bus = std::make_unique<InProcessBus>([&](CanTransmitter& can) {
    auto target = factory(can);
    if (events != nullptr) {
      EXPECT_TRUE(target->node().addListener(*events));
    }
    return target;
  });
  EXPECT_EQ(playText("tx 701 [1] 00\nsilence", *bus), "");
  return bus;
}

// Values of both areas: set A (saved before, for the "over a saved set" case) and set B (the
// values "save all" stores). Every written value differs between A, B and the defaults.
constexpr const char* kSetA = R"(
    rx 601 [8] 23 05 10 00 A0 00 00 00   # COB-ID SYNC 0x0A0
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 601 [8] 23 06 10 00 D0 07 00 00   # communication cycle period 2000 us
    tx 581 [8] 60 06 10 00 00 00 00 00
    rx 601 [8] 2B 0C 10 00 32 00 00 00   # guard time 50 ms
    tx 581 [8] 60 0C 10 00 00 00 00 00
    rx 601 [8] 23 00 20 00 98 3A 00 00   # setpoint 15000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 601 [8] 2F 04 20 02 42 00 00 00   # offset 0x42
    tx 581 [8] 60 04 20 02 00 00 00 00
    rx 601 [8] 2B 06 20 00 78 79 00 00   # label "xy"
    tx 581 [8] 60 06 20 00 00 00 00 00
)";
constexpr const char* kSetB = R"(
    rx 601 [8] 23 05 10 00 90 00 00 00   # COB-ID SYNC 0x090
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 601 [8] 23 06 10 00 88 13 00 00   # communication cycle period 5000 us
    tx 581 [8] 60 06 10 00 00 00 00 00
    rx 601 [8] 2B 0C 10 00 64 00 00 00   # guard time 100 ms
    tx 581 [8] 60 0C 10 00 00 00 00 00
    rx 601 [8] 23 00 20 00 20 4E 00 00   # setpoint 20000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 601 [8] 2F 04 20 02 34 00 00 00   # offset 0x34
    tx 581 [8] 60 04 20 02 00 00 00 00
    rx 601 [8] 2B 06 20 00 61 62 00 00   # label "ab"
    tx 581 [8] 60 06 20 00 00 00 00 00
)";
constexpr const char* kSaveAll = "rx 601 [8] 23 10 10 01 73 61 76 65";  // "save" all
constexpr const char* kSaved = "tx 581 [8] 60 10 10 01 00 00 00 00";
constexpr const char* kCannotStore = "tx 581 [8] 80 10 10 01 20 00 00 08";

struct Sets {
  std::vector<StoredValue> communication;
  std::vector<StoredValue> application;
};

Sets setsOf(InProcessBus& bus) {
  od::ObjectDictionary& dictionary = bus.node().dictionary();
  return {groupValues(dictionary, od::kGroupCommunication),
          groupValues(dictionary, od::kGroupApplication)};
}

class SaveAllPowerLoss : public ::testing::TestWithParam<bool> {
 protected:
  /// A fresh medium; with the parameter, set A saved on it (and the node power-cycled).
  std::unique_ptr<Storage> prepared() {
    auto storage = std::make_unique<Storage>();
    if (GetParam()) {
      auto bus = powerOn(*storage);
      EXPECT_EQ(playText(std::string(kSetA) + kSaveAll + "\n" + kSaved, *bus), "");
    }
    return storage;
  }
  /// Powers a node on `storage`, writes set B, then the store command `save` (expecting
  /// `response`), with the medium cut after `cut` bytes when `cut` >= 0.
  void saveSetB(Storage& storage, const std::string& save, const std::string& response, long cut) {
    auto bus = powerOn(storage);
    ASSERT_EQ(playText(kSetB, *bus), "");
    storage.resetCounters();
    if (cut >= 0) {
      storage.cutPowerAfter(static_cast<size_t>(cut));
    }
    EXPECT_EQ(playText(save + "\n" + response, *bus), "") << "cut after " << cut;
    storage.restorePower();
  }
  /// Bytes programmed and erased by `save` (uncut).
  size_t bytesOf(const std::string& save, const std::string& response) {
    auto storage = prepared();
    saveSetB(*storage, save, response, -1);
    return storage->bytesWritten() + storage->bytesErased();
  }
};

TEST_P(SaveAllPowerLoss, EachAreaIsCompletelyOldOrCompletelyNewAfterEveryCut) {
  Sets oldSets;
  {
    auto storage = prepared();
    oldSets = setsOf(*powerOn(*storage));
  }
  Sets newSets;
  {
    auto storage = prepared();
    auto bus = powerOn(*storage);
    ASSERT_EQ(playText(kSetB, *bus), "");
    newSets = setsOf(*bus);
  }
  ASSERT_NE(oldSets.communication, newSets.communication);
  ASSERT_NE(oldSets.application, newSets.application);

  // Communication is saved first: its share is what "save" to 0x1010:02 programs.
  const size_t communicationBytes =
      bytesOf("rx 601 [8] 23 10 10 02 73 61 76 65", "tx 581 [8] 60 10 10 02 00 00 00 00");
  const size_t total = bytesOf(kSaveAll, kSaved);
  ASSERT_GT(communicationBytes, 2U * kImageHeaderSize);
  ASSERT_GT(total, communicationBytes + 2U * kImageHeaderSize);

  for (size_t cut = 0; cut <= total; ++cut) {
    auto storage = prepared();
    // The node may answer before the power fails completely: a failed write aborts 0x08000020.
    saveSetB(*storage, kSaveAll, cut == total ? kSaved : kCannotStore, static_cast<long>(cut));
    CountingStoreEvents events;
    auto bus = powerOn(*storage, &events);
    EXPECT_EQ(events.count, 0) << "cut after " << cut;  // an interrupted save is no damage
    const Sets after = setsOf(*bus);
    EXPECT_EQ(classify(after.communication, oldSets.communication, newSets.communication),
              cut >= communicationBytes ? "new" : "old")
        << "communication, cut after " << cut << " of " << total;
    EXPECT_EQ(classify(after.application, oldSets.application, newSets.application),
              cut == total ? "new" : "old")
        << "application, cut after " << cut << " of " << total;

    // The medium keeps working: set B saved again survives the next power-on.
    ASSERT_EQ(playText(std::string(kSetB) + kSaveAll + "\n" + kSaved, *bus), "");
    bus.reset();
    auto again = powerOn(*storage);
    const Sets saved = setsOf(*again);
    EXPECT_EQ(saved.communication, newSets.communication) << "cut after " << cut;
    EXPECT_EQ(saved.application, newSets.application) << "cut after " << cut;
  }
}

INSTANTIATE_TEST_SUITE_P(All, SaveAllPowerLoss, ::testing::Bool(), [](const auto& parameters) {
  return parameters.param ? std::string("OverASavedSet") : std::string("FirstSave");
});

}  // namespace
}  // namespace costa::test
