// ParameterStore over dictionaries with other group sets: groups 1, 3, 4 and 9 (a record split
// over two groups, a string, a volatile entry), slot alignment, and too many regions.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "costa/parameter_store.hpp"
#include "costa/port/memory/memory_storage.hpp"
#include "dictionary_instance.hpp"
#include "storage_groups_od.hpp"

namespace costa::test {
namespace {

using GroupsDictionary = DictionaryInstance<gen::storage_groups::Values>;
const od::Definition& kGroups = gen::storage_groups::kDefinition;

TEST(ParameterStoreGroupsTest, OneRegionPerGroupPresentInAscendingOrder) {
  GroupsDictionary device(kGroups);
  port::MemoryStorageOf<512> storage;
  ParameterStore store(device.dictionary, storage);
  EXPECT_TRUE(store.hasGroup(1));
  EXPECT_FALSE(store.hasGroup(2));
  EXPECT_TRUE(store.hasGroup(3));
  EXPECT_TRUE(store.hasGroup(4));
  EXPECT_TRUE(store.hasGroup(9));
  EXPECT_FALSE(store.hasGroup(5));
  // Payloads: group 1 = 0x1017 (2), 3 = 0x2000 (1), 4 = 0x2100:1..2 (4 + 12), 9 = 0x2100:3 (2).
  const size_t sizes[] = {2, 1, 16, 2};
  size_t required = 0;
  for (size_t payload : sizes) {
    required += 2U * (kImageHeaderSize + payload);
  }
  EXPECT_EQ(store.requiredSize(), required);
  ASSERT_TRUE(store.layOut());

  ASSERT_EQ(store.save(9), StoreResult::kOk);
  const size_t group9 = required - 2U * (kImageHeaderSize + 2U);
  const SlotInfo info = inspectSlot(storage, group9, kImageHeaderSize + 2U);
  ASSERT_EQ(info.state, SlotState::kIntact);
  EXPECT_EQ(info.header.region, 9U);
  EXPECT_EQ(store.save(2), StoreResult::kUnknownGroup);
}

TEST(ParameterStoreGroupsTest, EachGroupRoundTripsAndVolatileEntriesStayVolatile) {
  port::MemoryStorageOf<512> storage;
  GroupsDictionary device(kGroups);
  ParameterStore store(device.dictionary, storage);
  ASSERT_TRUE(store.layOut());
  device.values.x1017_producer_heartbeat_time = 250;
  device.values.x2000_pending_node_id = 0x22;
  device.values.x2001_volatile_setpoint = 99;
  device.values.x2100_tuning.gain = -4000;
  std::strcpy(device.values.x2100_tuning.name, "fast ramp");
  device.values.x2100_tuning.limit = 1234;
  for (const uint8_t group : std::vector<uint8_t>{1, 3, 4, 9}) {
    ASSERT_EQ(store.save(group), StoreResult::kOk) << "group " << int{group};
  }

  GroupsDictionary fresh(kGroups);
  ParameterStore reloaded(fresh.dictionary, storage);
  ASSERT_TRUE(reloaded.layOut());
  ASSERT_EQ(reloaded.load(4), StoreResult::kOk);
  EXPECT_EQ(fresh.values.x2100_tuning.gain, -4000);
  EXPECT_STREQ(fresh.values.x2100_tuning.name, "fast ramp");
  EXPECT_EQ(fresh.values.x2100_tuning.limit, 500U) << "sub 3 is in group 9";
  EXPECT_EQ(fresh.values.x2000_pending_node_id, 0x7FU);
  ASSERT_EQ(reloaded.load(9), StoreResult::kOk);
  EXPECT_EQ(fresh.values.x2100_tuning.limit, 1234U);
  ASSERT_EQ(reloaded.load(3), StoreResult::kOk);
  EXPECT_EQ(fresh.values.x2000_pending_node_id, 0x22U);
  ASSERT_EQ(reloaded.load(1), StoreResult::kOk);
  EXPECT_EQ(fresh.values.x1017_producer_heartbeat_time, 250U);
  EXPECT_EQ(fresh.values.x2001_volatile_setpoint, 7U);
}

TEST(ParameterStoreGroupsTest, SlotsAreAlignedToTheGivenBoundary) {
  port::MemoryStorageOf<4096> storage;
  GroupsDictionary device(kGroups);
  ParameterStore store(device.dictionary, storage, 64);
  EXPECT_EQ(store.requiredSize(), 4U * 2U * 64U);
  ASSERT_TRUE(store.layOut());
  for (const uint8_t group : std::vector<uint8_t>{1, 3, 4, 9}) {
    ASSERT_EQ(store.save(group), StoreResult::kOk);
    ASSERT_EQ(store.save(group), StoreResult::kOk);
  }
  EXPECT_EQ(storage.bytesErased(), 8U * 64U) << "every erase covers a whole slot";
  const size_t groupOrder[] = {1, 3, 4, 9};
  for (size_t region = 0; region < 4U; ++region) {
    for (size_t slot = 0; slot < 2U; ++slot) {
      const SlotInfo info = inspectSlot(storage, (2U * region + slot) * 64U, 64U);
      ASSERT_EQ(info.state, SlotState::kIntact) << "region " << region << " slot " << slot;
      EXPECT_EQ(info.header.region, groupOrder[region]);
    }
  }
  port::MemoryStorage tooSmall(storage.bytes(), 8U * 64U - 1U);
  ParameterStore doesNotFit(device.dictionary, tooSmall, 64);
  EXPECT_FALSE(doesNotFit.layOut());
  ParameterStore unaligned(device.dictionary, storage, 0);
  EXPECT_EQ(unaligned.requiredSize(), ParameterStore(device.dictionary, storage).requiredSize());
}

// A dictionary with one byte in each of the groups 1..kMaxRegions: as many regions as a store
// holds.
struct ManyGroupsTables {
  static constexpr size_t kCount = ParameterStore::kMaxRegions;
  ManyGroupsTables() {
    for (uint8_t i = 0; i < kCount; ++i) {
      subs[i] = od::SubEntry{0,
                             1,
                             od::DataType::kUnsigned8,
                             od::kReadable | od::kWritable,
                             1,
                             static_cast<uint8_t>(i + 1U),
                             0,
                             0};
      // Value i at offset i: its object's base (the tables satisfy od::ramInIndexOrder()).
      objects[i] = od::Object{static_cast<uint16_t>(0x2000U + i), od::ObjectCode::kVar, 1, i, i};
    }
    definition = od::Definition{objects, kCount,   subs,    constants, nullptr, nullptr, 0, kCount,
                                0x1234U, "groups", nullptr, nullptr,   nullptr, 0,       0};
  }
  od::SubEntry subs[kCount]{};
  od::Object objects[kCount]{};
  uint8_t constants[kCount]{};
  od::Definition definition{};
};

TEST(ParameterStoreGroupsTest, MoreRegionsThanTheStoreHoldsCannotBeLaidOut) {
  ManyGroupsTables tables;
  uint8_t values[ManyGroupsTables::kCount] = {};
  od::ObjectDictionary dictionary(tables.definition, values);
  port::MemoryStorageOf<4096> storage;
  ParameterStore store(dictionary, storage);
  EXPECT_EQ(store.requiredSize(), ManyGroupsTables::kCount * 2U * (kImageHeaderSize + 1U));
  ASSERT_TRUE(store.layOut());
  EXPECT_EQ(store.save(ManyGroupsTables::kCount), StoreResult::kOk);

  ASSERT_TRUE(store.reserveRecord(1, 1));
  EXPECT_EQ(store.requiredSize(), SIZE_MAX);
  EXPECT_FALSE(store.layOut());
  EXPECT_EQ(store.save(1), StoreResult::kNotLaidOut);
}

TEST(ParameterStoreGroupsTest, AHugeRecordCannotBeLaidOut) {
  GroupsDictionary device(kGroups);
  port::MemoryStorageOf<64> storage;
  ParameterStore store(device.dictionary, storage);
  ASSERT_TRUE(store.reserveRecord(1, SIZE_MAX - 8U));
  EXPECT_EQ(store.requiredSize(), SIZE_MAX);
  EXPECT_FALSE(store.layOut());
  ParameterStore hugeAlignment(device.dictionary, storage, SIZE_MAX);
  EXPECT_EQ(hugeAlignment.requiredSize(), SIZE_MAX);
}

}  // namespace
}  // namespace costa::test
