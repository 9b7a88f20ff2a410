// The dictionary runtime against the generated example tables: lookup, types, limits,
// defaults, node-id relative values, restores.
#include <gtest/gtest.h>

#include <cstring>

#include "costa/od/object_dictionary.hpp"
#include "example_od.hpp"

namespace costa::od {
namespace {

class ObjectDictionaryTest : public ::testing::Test {
 protected:
  ObjectDictionaryTest() : dictionary_(gen::example::kDefinition, &values_) {
    dictionary_.setNodeId(5);
    dictionary_.restoreDefaults(0x0000, 0xFFFF);
  }
  gen::example::Values values_{};
  ObjectDictionary dictionary_;
};

TEST_F(ObjectDictionaryTest, ObjectsAreSortedAndEveryEntryIsFound) {
  const Definition& definition = gen::example::kDefinition;
  ASSERT_GT(definition.objectCount, 10U);
  for (uint16_t i = 0; i < definition.objectCount; ++i) {
    const Object& object = definition.objects[i];
    if (i > 0) {
      EXPECT_LT(definition.objects[i - 1].index, object.index);
    }
    const SubEntry* rows = rowsOf(definition, object);
    for (uint8_t r = 0; r < object.rowCount; ++r) {
      const SubEntry& row = rows[r];
      if (r > 0) {
        const SubEntry& previous = rows[r - 1];
        EXPECT_EQ(previous.subIndex + previous.count, row.subIndex);  // no gap, no overlap
      }
      for (unsigned k = 0; k < row.count; ++k) {
        EntryRef ref;
        const auto sub = static_cast<uint8_t>(row.subIndex + k);
        EXPECT_EQ(dictionary_.find(object.index, sub, &ref), AbortCode::kNone);
        EXPECT_EQ(ref.row, &row);
        EXPECT_EQ(ref.subIndex(), sub);
        const unsigned base = row.attributes & kInRom ? 0U : object.ramBase;  // ROM: from the start
        EXPECT_EQ(ref.offset(), base + row.offset + k * row.size);
      }
    }
  }
}

// A definition made by hand has no hash table of its objects (objectSlots null): its sorted
// objects are searched instead, with the same answers.
TEST(ObjectDictionaryWithoutHashTable, FindsEveryObjectBySearchingTheSortedObjects) {
  Definition byHand = gen::example::kDefinition;
  byHand.objectSlots = nullptr;
  byHand.objectSlotShift = 0;
  gen::example::Values values{};
  const ObjectDictionary dictionary(byHand, &values);
  for (uint16_t i = 0; i < byHand.objectCount; ++i) {
    const uint16_t index = byHand.objects[i].index;
    EXPECT_EQ(dictionary.findObject(index), &byHand.objects[i]) << std::hex << index;
    EntryRef ref;
    EXPECT_EQ(dictionary.find(index, rowsOf(byHand, byHand.objects[i])[0].subIndex, &ref),
              AbortCode::kNone);
  }
  const uint16_t first = byHand.objects[0].index;
  const uint16_t last = byHand.objects[byHand.objectCount - 1U].index;
  for (const uint16_t absent :
       {uint16_t{0x0000}, static_cast<uint16_t>(first - 1U), uint16_t{0x1004}, uint16_t{0x3000},
        static_cast<uint16_t>(last + 1U), uint16_t{0xFFFF}}) {
    EXPECT_EQ(dictionary.findObject(absent), nullptr) << std::hex << absent;
    EntryRef ref;
    EXPECT_EQ(dictionary.find(absent, 0, &ref), AbortCode::kNoObject) << std::hex << absent;
  }
  Definition empty = byHand;
  empty.objectCount = 0;
  const ObjectDictionary none(empty, &values);
  EXPECT_EQ(none.findObject(first), nullptr);
}

TEST_F(ObjectDictionaryTest, RowsStandForRunsOfLikeSubIndices) {
  // 0x1016 holds the number of entries and three consumer times: two rows.
  const Object* consumers = dictionary_.findObject(0x1016);
  ASSERT_NE(consumers, nullptr);
  EXPECT_EQ(consumers->rowCount, 2U);
  EXPECT_EQ(dictionary_.entryCount(*consumers), 4U);
  values_.x1016_consumer_heartbeat_time.item[2] = 0x00050064;
  EXPECT_EQ(dictionary_.readUnsigned(0x1016, 3, 0), 0x00050064U);
  size_t visited = 0;
  for (const EntryRef& ref : Entries(gen::example::kDefinition)) {
    EXPECT_TRUE(ref.valid());
    ++visited;
  }
  size_t expected = 0;
  for (uint16_t i = 0; i < gen::example::kDefinition.objectCount; ++i) {
    expected += entryCount(gen::example::kDefinition, gen::example::kDefinition.objects[i]);
  }
  EXPECT_EQ(visited, expected);
}

// The four RPDO communication parameters have one shape: one run of rows, each object's values
// at its own base. A value written through one is the value of that object alone.
TEST_F(ObjectDictionaryTest, ObjectsOfOneShapeShareTheirRowsAndKeepTheirValues) {
  const Object* first = dictionary_.findObject(0x1400);
  const Object* second = dictionary_.findObject(0x1401);
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(first->firstRow, second->firstRow);
  EXPECT_NE(first->ramBase, second->ramBase);
  const uint8_t cobId[4] = {0x21, 0x03, 0x00, 0x00};
  EntryRef ref;
  ASSERT_EQ(dictionary_.find(0x1401, 1, &ref), AbortCode::kNone);
  ASSERT_EQ(dictionary_.write(ref, cobId, sizeof(cobId)), AbortCode::kNone);
  EXPECT_EQ(values_.x1401_rpdo_communication_parameter_2.cob_id_used_by_rpdo, 0x321U);
  EXPECT_EQ(dictionary_.readUnsigned(0x1401, 1, 0), 0x321U);
  EXPECT_NE(dictionary_.readUnsigned(0x1400, 1, 0), 0x321U);
  uint8_t read[4] = {};
  ASSERT_EQ(dictionary_.find(0x1400, 0, &ref), AbortCode::kNone);  // a constant: the ROM block
  EXPECT_EQ(dictionary_.read(ref, 0, read, sizeof(read)), 1U);
  EXPECT_EQ(read[0], dictionary_.entryCount(*first) - 1U);
}

TEST_F(ObjectDictionaryTest, MissingObjectsAndSubIndicesHaveTheirAbortCodes) {
  EntryRef ref;
  EXPECT_EQ(dictionary_.find(0x0FFF, 0, &ref), AbortCode::kNoObject);
  EXPECT_EQ(dictionary_.find(0xFFFF, 0, &ref), AbortCode::kNoObject);
  EXPECT_EQ(dictionary_.find(0x1018, 5, &ref), AbortCode::kNoSubIndex);
  EXPECT_FALSE(dictionary_.find(0x1018, 0xFF).valid());
}

TEST_F(ObjectDictionaryTest, DefaultsAreInRamAndReachableByName) {
  EXPECT_EQ(values_.x2000_setpoint, 1000U);
  EXPECT_EQ(values_.x2004_mixed_record.offset, -5);
  EXPECT_FLOAT_EQ(values_.x2004_mixed_record.gain, 1.5F);
  EXPECT_EQ(values_.x2005_table.item[3], 0x1234U);
  EXPECT_STREQ(values_.x2006_device_label, "unnamed");
  EXPECT_EQ(dictionary_.readUnsigned(0x2000, 0, 0), 1000U);
  EXPECT_EQ(dictionary_.readSigned(dictionary_.find(0x2004, 3)), -100000);
}

TEST_F(ObjectDictionaryTest, NodeIdRelativeConstantsFollowTheNodeId) {
  EXPECT_EQ(dictionary_.readUnsigned(0x1200, 1, 0), 0x605U);
  dictionary_.setNodeId(0x7F);
  EXPECT_EQ(dictionary_.readUnsigned(0x1200, 2, 0), 0x5FFU);
  uint8_t wire[4] = {};
  EXPECT_EQ(dictionary_.read(dictionary_.find(0x1200, 1), 0, wire, 4), 4U);
  EXPECT_EQ(wire[0], 0x7FU);
  EXPECT_EQ(wire[1], 0x06U);
}

TEST_F(ObjectDictionaryTest, ConstantsAreNotInRamAndCannotBeWritten) {
  const EntryRef name = dictionary_.find(0x1008, 0);
  ASSERT_TRUE(name.valid());
  EXPECT_NE(name.attributes() & kInRom, 0U);
  EXPECT_EQ(dictionary_.ramAddress(name), nullptr);
  const uint8_t data[2] = {'x', 0};
  EXPECT_EQ(dictionary_.write(name, data, 1), AbortCode::kWriteOfReadOnly);
  EXPECT_EQ(dictionary_.valueSize(name), 13U);
}

TEST_F(ObjectDictionaryTest, ChecksLengthsAndLimitsBeforeStoring) {
  const EntryRef setpoint = dictionary_.find(0x2000, 0);
  const uint8_t tooHigh[4] = {0xA1, 0x86, 0x01, 0x00};
  const uint8_t ok[4] = {0x10, 0x27, 0x00, 0x00};
  EXPECT_EQ(dictionary_.write(setpoint, tooHigh, 4), AbortCode::kValueTooHigh);
  EXPECT_EQ(dictionary_.write(setpoint, ok, 3), AbortCode::kLengthTooLow);
  EXPECT_EQ(dictionary_.write(setpoint, ok, 5), AbortCode::kLengthTooHigh);
  EXPECT_EQ(values_.x2000_setpoint, 1000U);
  EXPECT_EQ(dictionary_.write(setpoint, ok, 4), AbortCode::kNone);
  EXPECT_EQ(values_.x2000_setpoint, 10000U);
}

TEST_F(ObjectDictionaryTest, RealLimitsRejectNotANumber) {
  const EntryRef gain = dictionary_.find(0x2004, 4);
  const uint8_t nan[4] = {0x00, 0x00, 0xC0, 0x7F};
  EXPECT_EQ(dictionary_.write(gain, nan, 4), AbortCode::kInvalidValue);
}

TEST_F(ObjectDictionaryTest, StringsArePaddedAndReadUpToTheirLength) {
  const EntryRef label = dictionary_.find(0x2006, 0);
  const uint8_t text[3] = {'a', 'b', 'c'};
  EXPECT_EQ(dictionary_.write(label, text, 3), AbortCode::kNone);
  EXPECT_STREQ(values_.x2006_device_label, "abc");
  EXPECT_EQ(dictionary_.valueSize(label), 3U);
  uint8_t out[8] = {};
  EXPECT_EQ(dictionary_.read(label, 1, out, sizeof(out)), 2U);
  EXPECT_EQ(out[0], 'b');
  EXPECT_EQ(dictionary_.read(label, 3, out, sizeof(out)), 0U);
}

TEST_F(ObjectDictionaryTest, RestoresRangesAndGroups) {
  values_.x1017_producer_heartbeat_time = 77;
  values_.x2000_setpoint = 77;
  dictionary_.restoreDefaults(0x1000, 0x1FFF);
  EXPECT_EQ(values_.x1017_producer_heartbeat_time, 0U);
  EXPECT_EQ(values_.x2000_setpoint, 77U);
  dictionary_.restoreGroupDefaults(kGroupApplication);
  EXPECT_EQ(values_.x2000_setpoint, 1000U);
}

// One entry back to its default: an element of an array (its neighbours untouched), a `$NODEID`
// one with the node-id, a string with its terminator; ROM entries and DOMAINs have none.
TEST_F(ObjectDictionaryTest, RestoresOneEntry) {
  values_.x2005_table.item[2] = 7;
  values_.x2005_table.item[3] = 7;
  dictionary_.restoreDefault(dictionary_.find(0x2005, 4));  // sub-index 4: item[3]
  EXPECT_EQ(values_.x2005_table.item[3], 0x1234U);
  EXPECT_EQ(values_.x2005_table.item[2], 7U);
  ASSERT_TRUE(dictionary_.storeUnsigned(0x1014, 0, 0x99));
  dictionary_.restoreDefault(dictionary_.find(0x1014, 0));
  EXPECT_EQ(dictionary_.readUnsigned(0x1014, 0, 0), 0x85U);  // $NODEID+0x80, node-id 5
  const uint8_t text[9] = {'l', 'o', 'n', 'g', 'e', 'r', 'o', 'n', 'e'};
  const EntryRef label = dictionary_.find(0x2006, 0);
  ASSERT_EQ(dictionary_.write(label, text, sizeof(text)), AbortCode::kNone);
  dictionary_.restoreDefault(label);
  EXPECT_STREQ(values_.x2006_device_label, "unnamed");
  EXPECT_EQ(dictionary_.valueSize(label), 7U);
  dictionary_.restoreDefault(dictionary_.find(0x1008, 0));  // ROM: nothing to do
  dictionary_.restoreDefault(dictionary_.find(0x2008, 0));  // DOMAIN: nothing to do
  EXPECT_EQ(dictionary_.valueSize(dictionary_.find(0x1008, 0)), 13U);
}

// A value the dictionary would refuse, put in RAM by other means (a load), gets its default;
// one it takes stays, and entries without limits are not judged.
TEST_F(ObjectDictionaryTest, RestoresADefaultOnlyWhereTheValueIsRefused) {
  values_.x2000_setpoint = 100001;  // 10..100000
  EXPECT_TRUE(dictionary_.restoreDefaultIfRefused(dictionary_.find(0x2000, 0)));
  EXPECT_EQ(values_.x2000_setpoint, 1000U);
  values_.x2000_setpoint = 100000;
  EXPECT_FALSE(dictionary_.restoreDefaultIfRefused(dictionary_.find(0x2000, 0)));
  EXPECT_EQ(values_.x2000_setpoint, 100000U);
  values_.x2004_mixed_record.offset = -101;  // INTEGER8 -100..100
  EXPECT_TRUE(dictionary_.restoreDefaultIfRefused(dictionary_.find(0x2004, 2)));
  EXPECT_EQ(values_.x2004_mixed_record.offset, -5);
  ASSERT_TRUE(dictionary_.storeUnsigned(0x2004, 1, 2));  // BOOLEAN
  EXPECT_TRUE(dictionary_.restoreDefaultIfRefused(dictionary_.find(0x2004, 1)));
  EXPECT_EQ(dictionary_.readUnsigned(0x2004, 1, 9), 0U);
  ASSERT_TRUE(dictionary_.storeUnsigned(0x1014, 0, 0xFFFFFFFFU));  // no limits
  EXPECT_FALSE(dictionary_.restoreDefaultIfRefused(dictionary_.find(0x1014, 0)));
  EXPECT_FALSE(dictionary_.restoreDefaultIfRefused(dictionary_.find(0x1008, 0)));  // ROM
}

TEST_F(ObjectDictionaryTest, AttributesFollowTheAccessTypes) {
  const auto attributes = [&](uint16_t index, uint8_t sub) {
    return dictionary_.find(index, sub).attributes();
  };
  EXPECT_EQ(attributes(0x2001, 0) & (kReadable | kWritable), kReadable);  // ro
  EXPECT_EQ(attributes(0x2002, 0) & (kReadable | kWritable), kWritable);  // wo
  EXPECT_EQ(attributes(0x2000, 0) & (kReadable | kWritable), kReadable | kWritable);
  EXPECT_NE(attributes(0x2004, 3) & kRpdoMappable, 0U);  // rww
  EXPECT_EQ(attributes(0x2004, 3) & kTpdoMappable, 0U);
  EXPECT_NE(attributes(0x2004, 5) & kTpdoMappable, 0U);  // rwr
  EXPECT_EQ(attributes(0x2004, 5) & kRpdoMappable, 0U);
}

TEST(GeneratedCapacity, DescribesTheDictionary) {
  EXPECT_EQ(gen::example::Capacity::kLargestValue, 32U);
  EXPECT_EQ(gen::example::Capacity::kRpdoCount, 4U);
  EXPECT_EQ(gen::example::Capacity::kTpdoCount, 4U);
  EXPECT_EQ(gen::example::Capacity::kHeartbeatConsumers, 3U);
  EXPECT_EQ(gen::example::Capacity::kErrorHistory, 8U);
  EXPECT_EQ(gen::example::Capacity::kObjectCount, gen::example::kDefinition.objectCount);
}

}  // namespace
}  // namespace costa::od
