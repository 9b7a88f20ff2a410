// 0x1010 / 0x1011 on a dictionary with device-specific storage groups
// (host-tests/data/storage_groups.eds: groups 1, 3 (LSS), 4 and 9, no application group;
// sub-indices 1..4 declared): sub-index 4 saves and restores group 4 alone, a declared
// sub-index without a group aborts 0x08000020, an undeclared one 0x06090011.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "costa/parameter_store.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "dictionary_instance.hpp"
#include "dictionary_node_bus.hpp"
#include "storage_groups_od.hpp"

namespace costa::test {
namespace {

using GroupsBus = DictionaryNodeBus<gen::storage_groups::Values, gen::storage_groups::Capacity>;

class StoreCommandsGroups : public ::testing::Test {
 protected:
  StoreCommandsGroups() { powerOn(); }

  /// A new node over the same storage, as after a power cycle.
  void powerOn() {
    bus_.reset();
    NodeSettings settings;
    settings.nodeId = 1;
    settings.storage = &storage_;
    bus_ = std::make_unique<GroupsBus>(gen::storage_groups::kDefinition, settings);
    ASSERT_EQ(play("tx 701 [1] 00\nsilence"), "");
  }
  std::string play(const std::string& text) { return playText(text, *bus_); }

  /// What a store over the medium finds for `group` (nothing is copied anywhere that matters).
  StoreResult stored(uint8_t group) {
    DictionaryInstance<gen::storage_groups::Values> fresh(gen::storage_groups::kDefinition);
    ParameterStore store(fresh.dictionary, storage_);
    return store.layOut() ? store.load(group) : StoreResult::kNotLaidOut;
  }

  port::MemoryStorageOf<1024> storage_;
  std::unique_ptr<GroupsBus> bus_;
};

// Heartbeat 250 ms (group 1), gain -4000 (group 4), limit 1234 (group 9).
constexpr const char* kChangeValues = R"(
    rx 601 [8] 2B 17 10 00 FA 00 00 00
    tx 581 [8] 60 17 10 00 00 00 00 00
    rx 601 [8] 23 00 21 01 60 F0 FF FF
    tx 581 [8] 60 00 21 01 00 00 00 00
    rx 601 [8] 2B 00 21 03 D2 04 00 00
    tx 581 [8] 60 00 21 03 00 00 00 00
)";

TEST_F(StoreCommandsGroups, CapabilitiesFollowTheGroupsPresent) {
  EXPECT_EQ(play(R"(
    rx 601 [8] 40 10 10 01 00 00 00 00
    tx 581 [8] 43 10 10 01 01 00 00 00   # all: groups 1, 4, 9
    rx 601 [8] 40 10 10 02 00 00 00 00
    tx 581 [8] 43 10 10 02 01 00 00 00   # communication
    rx 601 [8] 40 10 10 03 00 00 00 00
    tx 581 [8] 43 10 10 03 00 00 00 00   # no application group
    rx 601 [8] 40 10 10 04 00 00 00 00
    tx 581 [8] 43 10 10 04 01 00 00 00   # group 4
    rx 601 [8] 40 11 10 04 00 00 00 00
    tx 581 [8] 43 11 10 04 01 00 00 00
  )"),
            "");
}

TEST_F(StoreCommandsGroups, SaveToSubIndex4StoresOnlyGroup4) {
  EXPECT_EQ(play(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 04 73 61 76 65   # "save" group 4
    tx 581 [8] 60 10 10 04 00 00 00 00
  )"),
            "");
  EXPECT_EQ(stored(4), StoreResult::kOk);
  EXPECT_EQ(stored(1), StoreResult::kNoImage);
  EXPECT_EQ(stored(9), StoreResult::kNoImage);  // the same object, another group
  powerOn();
  EXPECT_EQ(play(R"(
    rx 601 [8] 40 00 21 01 00 00 00 00
    tx 581 [8] 43 00 21 01 60 F0 FF FF   # gain: stored
    rx 601 [8] 40 00 21 03 00 00 00 00
    tx 581 [8] 4B 00 21 03 F4 01 00 00   # limit: the default 500
    rx 601 [8] 40 17 10 00 00 00 00 00
    tx 581 [8] 4B 17 10 00 00 00 00 00   # heartbeat: the default 0
  )"),
            "");
}

TEST_F(StoreCommandsGroups, SubIndicesWithoutAGroupOrUndeclaredAbortWithoutWriting) {
  ASSERT_EQ(play(kChangeValues), "");
  storage_.resetCounters();
  EXPECT_EQ(play(R"(
    rx 601 [8] 23 10 10 03 73 61 76 65   # declared, but no application group: 0x08000020
    tx 581 [8] 80 10 10 03 20 00 00 08
    rx 601 [8] 23 11 10 03 6C 6F 61 64
    tx 581 [8] 80 11 10 03 20 00 00 08
    rx 601 [8] 23 10 10 05 73 61 76 65   # not declared: 0x06090011
    tx 581 [8] 80 10 10 05 11 00 09 06
    rx 601 [8] 23 11 10 05 6C 6F 61 64
    tx 581 [8] 80 11 10 05 11 00 09 06
    rx 601 [8] 40 10 10 05 00 00 00 00
    tx 581 [8] 80 10 10 05 11 00 09 06
    rx 601 [8] 23 10 10 09 73 61 76 65   # group 9 exists, its sub-index is not declared
    tx 581 [8] 80 10 10 09 11 00 09 06
  )"),
            "");
  EXPECT_EQ(storage_.modifyingCalls(), 0U);
}

TEST_F(StoreCommandsGroups, SaveAllStoresEveryGroupButLss) {
  EXPECT_EQ(play(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65
    tx 581 [8] 60 10 10 01 00 00 00 00
  )"),
            "");
  EXPECT_EQ(stored(1), StoreResult::kOk);
  EXPECT_EQ(stored(4), StoreResult::kOk);
  EXPECT_EQ(stored(9), StoreResult::kOk);
  EXPECT_EQ(stored(3), StoreResult::kNoImage);
}

TEST_F(StoreCommandsGroups, RestoreOfSubIndex4BringsBackGroup4DefaultsAtResetNode) {
  EXPECT_EQ(play(std::string(kChangeValues) + R"(
    rx 601 [8] 23 10 10 01 73 61 76 65
    tx 581 [8] 60 10 10 01 00 00 00 00
    rx 601 [8] 23 11 10 04 6C 6F 61 64   # "load" group 4
    tx 581 [8] 60 11 10 04 00 00 00 00
    rx 000 [2] 81 01
    tx 701 [1] 00
    rx 601 [8] 40 00 21 01 00 00 00 00
    tx 581 [8] 43 00 21 01 F4 FF FF FF   # gain: the default -12
    rx 601 [8] 40 00 21 03 00 00 00 00
    tx 581 [8] 4B 00 21 03 D2 04 00 00   # limit (group 9): still stored
    rx 601 [8] 40 17 10 00 00 00 00 00
    tx 581 [8] 4B 17 10 00 FA 00 00 00   # heartbeat (group 1): still stored
  )"),
            "");
  EXPECT_EQ(stored(4), StoreResult::kNoImage);
  EXPECT_EQ(stored(9), StoreResult::kOk);
}

}  // namespace
}  // namespace costa::test
