// ParameterStore alone (groups, markers, damage, power loss, records) and StoreCommands over it.
#include "costa/parameter_store.hpp"

#include <gtest/gtest.h>

#include "costa/port/memory/memory_storage.hpp"
#include "costa/store_commands.hpp"
#include "costa/stored_image.hpp"
#include "service_fixture.hpp"

namespace costa::test {
namespace {

constexpr uint8_t kCommunication = od::kGroupCommunication;
constexpr uint8_t kApplication = od::kGroupApplication;

class ParameterStoreTest : public ServiceTest {
 protected:
  ParameterStoreTest() : store_(dictionary_, medium_) {}
  void SetUp() override { ASSERT_TRUE(store_.layOut()); }

  /// What the next power-on loads: a dictionary at its defaults and a store over the medium.
  struct NextBoot {
    explicit NextBoot(port::MemoryStorage& medium) : store(od.dictionary, medium) {
      EXPECT_TRUE(store.layOut());
    }
    ServiceDictionary od;
    ParameterStore store;
  };

  port::MemoryStorageOf<2048> medium_;
  ParameterStore store_;
};

TEST_F(ParameterStoreTest, TheGroupsAreThoseOfTheDictionary) {
  EXPECT_TRUE(store_.hasGroup(kCommunication));
  EXPECT_TRUE(store_.hasGroup(kApplication));
  EXPECT_FALSE(store_.hasGroup(7));
  EXPECT_FALSE(store_.hasGroup(od::kGroupNone));
  EXPECT_EQ(store_.save(7), StoreResult::kUnknownGroup);
  EXPECT_EQ(store_.saveGroups(groupBit(7)), StoreResult::kUnknownGroup);
  EXPECT_LE(store_.requiredSize(), medium_.size());
}

TEST_F(ParameterStoreTest, TooSmallAMediumIsNeverUsed) {
  port::MemoryStorageOf<64> small;
  ParameterStore tooSmall(dictionary_, small);
  EXPECT_FALSE(tooSmall.layOut());
  EXPECT_EQ(tooSmall.save(kCommunication), StoreResult::kNotLaidOut);
  EXPECT_EQ(tooSmall.load(kCommunication), StoreResult::kNotLaidOut);
  EXPECT_EQ(small.modifyingCalls(), 0U);
}

TEST_F(ParameterStoreTest, ASavedGroupIsLoadedAtTheNextBootAndOnlyThatGroup) {
  store(0x1017, 0, 250);
  store(0x2000, 2, 0x4321);
  EXPECT_EQ(store_.save(kCommunication), StoreResult::kOk);
  NextBoot boot(medium_);
  EXPECT_EQ(boot.store.load(kCommunication), StoreResult::kOk);
  EXPECT_EQ(boot.store.load(kApplication), StoreResult::kNoImage);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x1017, 0, 0), 250U);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x2000, 2, 0), 0U);
}

// Values a firmware with wider limits stored (the same layout): each loads as its default, a
// `$NODEID` one with the node-id of the load; the values within the limits load.
TEST_F(ParameterStoreTest, AValueOutsideItsLimitsLoadsAsItsDefault) {
  store(0x2002, 0, 21);      // 10..20
  store(0x2008, 0, 0x51);    // $NODEID+0x10, 0x11..0x50
  store(0x2000, 2, 0x4321);  // no limits
  EXPECT_EQ(store_.save(kApplication), StoreResult::kOk);
  NextBoot boot(medium_);
  EXPECT_EQ(boot.store.load(kApplication), StoreResult::kOk);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x2002, 0, 0), 15U);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x2008, 0, 0), 0x10U + kNodeId);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x2000, 2, 0), 0x4321U);

  store(0x2002, 0, 20);  // the highest of each: loaded
  store(0x2008, 0, 0x50);
  EXPECT_EQ(store_.save(kApplication), StoreResult::kOk);
  NextBoot same(medium_);
  EXPECT_EQ(same.store.load(kApplication), StoreResult::kOk);
  EXPECT_EQ(same.od.dictionary.readUnsigned(0x2002, 0, 0), 20U);
  EXPECT_EQ(same.od.dictionary.readUnsigned(0x2008, 0, 0), 0x50U);

  // Stored as 0x50 - 5 (without the node-id), loaded with node-id 0x10: 0x5B is above the limit.
  ServiceDictionary other(0x10);
  ParameterStore otherStore(other.dictionary, medium_);
  ASSERT_TRUE(otherStore.layOut());
  EXPECT_EQ(otherStore.load(kApplication), StoreResult::kOk);
  EXPECT_EQ(other.dictionary.readUnsigned(0x2008, 0, 0), 0x20U) << "its default for node-id 0x10";
  EXPECT_EQ(other.dictionary.readUnsigned(0x2002, 0, 0), 20U);
}

TEST_F(ParameterStoreTest, SaveGroupsSavesEveryGroupItHolds) {
  store(0x1017, 0, 250);
  store(0x2000, 2, 0x4321);
  EXPECT_EQ(store_.saveGroups(groupBit(kCommunication) | groupBit(kApplication) | groupBit(7)),
            StoreResult::kOk);
  NextBoot boot(medium_);
  EXPECT_EQ(boot.store.load(kCommunication), StoreResult::kOk);
  EXPECT_EQ(boot.store.load(kApplication), StoreResult::kOk);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x2000, 2, 0), 0x4321U);
}

TEST_F(ParameterStoreTest, ARestoreMarkerLeavesTheDefaultsAtTheNextLoad) {
  store(0x1017, 0, 250);
  EXPECT_EQ(store_.save(kCommunication), StoreResult::kOk);
  EXPECT_EQ(store_.invalidate(kCommunication), StoreResult::kOk);
  EXPECT_EQ(value(0x1017, 0), 250U);  // the dictionary itself is not changed
  NextBoot boot(medium_);
  EXPECT_EQ(boot.store.load(kCommunication), StoreResult::kNoImage);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x1017, 0, 0), 0U);
}

TEST_F(ParameterStoreTest, ADamagedImageIsReportedAndNothingIsLoaded) {
  store(0x1017, 0, 250);
  EXPECT_EQ(store_.save(kCommunication), StoreResult::kOk);
  medium_.bytes()[kImageHeaderSize] ^= 0x01U;  // the first payload byte of group 1, slot 0
  store(0x1017, 0, 300);
  EXPECT_EQ(store_.load(kCommunication), StoreResult::kCorrupt);
  EXPECT_EQ(value(0x1017, 0), 300U);
}

TEST_F(ParameterStoreTest, APowerLossDuringASaveKeepsThePreviousImage) {
  store(0x1017, 0, 250);
  EXPECT_EQ(store_.save(kCommunication), StoreResult::kOk);
  store(0x1017, 0, 300);
  medium_.cutPowerAfter(10);
  EXPECT_EQ(store_.save(kCommunication), StoreResult::kMediumError);
  medium_.restorePower();
  NextBoot boot(medium_);
  EXPECT_EQ(boot.store.load(kCommunication), StoreResult::kOk);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x1017, 0, 0), 250U);
}

TEST_F(ParameterStoreTest, ARecordKeepsRawBytesUpToItsReservation) {
  ParameterStore records(dictionary_, medium_);
  ASSERT_TRUE(records.reserveRecord(1, 3));
  EXPECT_FALSE(records.reserveRecord(1, 3));  // once
  EXPECT_EQ(records.saveRecord(1, nullptr, 0), StoreResult::kNotLaidOut);
  ASSERT_TRUE(records.layOut());
  const uint8_t data[4] = {0x22, 0x00, 0x02, 0xEE};
  EXPECT_EQ(records.saveRecord(1, data, 4), StoreResult::kTooLong);
  EXPECT_EQ(records.saveRecord(2, data, 3), StoreResult::kUnknownGroup);
  EXPECT_EQ(records.saveRecord(1, data, 3), StoreResult::kOk);
  uint8_t buffer[8] = {};
  size_t length = 0;
  EXPECT_EQ(records.loadRecord(1, buffer, sizeof(buffer), &length), StoreResult::kOk);
  EXPECT_EQ(length, 3U);
  EXPECT_EQ(buffer[0], 0x22U);
  EXPECT_EQ(buffer[2], 0x02U);
  EXPECT_EQ(records.invalidateRecord(1), StoreResult::kOk);
  EXPECT_EQ(records.loadRecord(1, buffer, sizeof(buffer), &length), StoreResult::kNoImage);
  EXPECT_EQ(length, 0U);
}

class StoreCommandsTest : public ParameterStoreTest {
 protected:
  StoreCommandsTest() : commands_(&store_, groupBit(kCommunication) | groupBit(kApplication), 0) {}

  /// The capability 0x1010/0x1011 sub-index `sub` reads (prepareRead refreshes it).
  uint64_t capability(StoreCommands& commands, uint16_t index, uint8_t sub) {
    EXPECT_EQ(commands.prepareRead(dictionary_, entry(index, sub), ReadRequest{}),
              AbortCode::kNone);
    return value(index, sub);
  }

  StoreCommands commands_;
};

TEST_F(StoreCommandsTest, SaveOn1010SavesTheGroupsOfItsSubIndex) {
  store(0x1017, 0, 250);
  EXPECT_EQ(write(commands_, 0x1010, 1, StoreCommands::kSaveSignature, 4), AbortCode::kNone);
  NextBoot boot(medium_);
  EXPECT_EQ(boot.store.load(kCommunication), StoreResult::kOk);
  EXPECT_EQ(boot.store.load(kApplication), StoreResult::kOk);
  EXPECT_EQ(boot.od.dictionary.readUnsigned(0x1017, 0, 0), 250U);
}

TEST_F(StoreCommandsTest, AnythingButTheSignatureIsRefused) {
  EXPECT_EQ(write(commands_, 0x1010, 1, StoreCommands::kLoadSignature, 4), AbortCode::kCannotStore);
  EXPECT_EQ(write(commands_, 0x1010, 1, StoreCommands::kSaveSignature, 2), AbortCode::kCannotStore);
  EXPECT_EQ(write(commands_, 0x1011, 1, StoreCommands::kSaveSignature, 4),
            AbortCode::kCannotStore);  // restore wants "load"; and "all" restores nothing here
  EXPECT_EQ(medium_.modifyingCalls(), 0U);
}

TEST_F(StoreCommandsTest, ReadingTellsWhetherTheSubIndexSavesAnything) {
  EXPECT_EQ(capability(commands_, 0x1010, 1), 1U);
  EXPECT_EQ(capability(commands_, 0x1011, 1), 0U);  // no group to restore
  StoreCommands without(nullptr, groupBit(kCommunication), groupBit(kCommunication));
  EXPECT_EQ(capability(without, 0x1010, 1), 0U);
  EXPECT_EQ(write(without, 0x1010, 1, StoreCommands::kSaveSignature, 4), AbortCode::kCannotStore);
}

}  // namespace
}  // namespace costa::test
