// ParameterStore over the example dictionary: layout, save/load round trips, independence of
// groups, the defaults marker, slot alternation and sequence wrap, and that nothing is written
// unless asked.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "allocation_guard.hpp"
#include "parameter_store_fixture.hpp"

namespace costa::test {
namespace {

void writeWire(od::ObjectDictionary& dictionary, uint16_t index, uint8_t subIndex,
               const std::vector<uint8_t>& wire) {
  const od::EntryRef ref = dictionary.find(index, subIndex);
  ASSERT_TRUE(ref.valid());
  ASSERT_EQ(dictionary.write(ref, wire.data(), wire.size()), AbortCode::kNone);
}

using ParameterStoreTest = ExampleStoreTest;

TEST_F(ParameterStoreTest, LaysOutTwoSlotsPerGroupAndNeedsThatMuchStorage) {
  const size_t expected = 2U * (kImageHeaderSize + defaults(kCommunication).size()) +
                          2U * (kImageHeaderSize + defaults(kApplication).size());
  EXPECT_EQ(store_.requiredSize(), expected);
  EXPECT_TRUE(store_.isLaidOut());
  EXPECT_TRUE(store_.hasGroup(kCommunication));
  EXPECT_TRUE(store_.hasGroup(kApplication));
  EXPECT_FALSE(store_.hasGroup(od::kGroupNone));
  EXPECT_FALSE(store_.hasGroup(od::kGroupLss));

  port::MemoryStorage exact(storage_.bytes(), expected);
  ParameterStore fits(device_.dictionary, exact);
  EXPECT_TRUE(fits.layOut());
  port::MemoryStorage tooSmall(storage_.bytes(), expected - 1U);
  ParameterStore doesNotFit(device_.dictionary, tooSmall);
  EXPECT_FALSE(doesNotFit.layOut());
  EXPECT_FALSE(doesNotFit.isLaidOut());
  EXPECT_EQ(doesNotFit.save(kApplication), StoreResult::kNotLaidOut);
  EXPECT_EQ(doesNotFit.load(kApplication), StoreResult::kNotLaidOut);
  EXPECT_EQ(doesNotFit.invalidate(kApplication), StoreResult::kNotLaidOut);
  EXPECT_EQ(tooSmall.modifyingCalls(), 0U);
}

TEST_F(ParameterStoreTest, SavedValuesComeBackInAFreshDictionary) {
  od::ObjectDictionary& od = device_.dictionary;
  writeWire(od, 0x1017, 0, {0xDC, 0x05});                    // 1500 ms
  writeWire(od, 0x2000, 0, {0x88, 0x13, 0x00, 0x00});        // 5000
  writeWire(od, 0x2004, 2, {0x11});                          // 17
  writeWire(od, 0x2004, 3, {0xC0, 0x1D, 0xFE, 0xFF});        // -123456
  writeWire(od, 0x2004, 4, {0x00, 0x00, 0x20, 0x40});        // 2.5f
  writeWire(od, 0x2006, 0, {'p', 'u', 'm', 'p', ' ', '7'});  // shorter than before
  writeWire(od, 0x2007, 0, {8, 7, 6, 5, 4, 3, 2, 1});
  {
    NoAllocationScope noAllocation;
    EXPECT_EQ(store_.save(kCommunication), StoreResult::kOk);
    EXPECT_EQ(store_.save(kApplication), StoreResult::kOk);
  }

  ExampleDictionary fresh(gen::example::kDefinition);
  ParameterStore store(fresh.dictionary, storage_);
  ASSERT_TRUE(store.layOut());
  EXPECT_EQ(fresh.values.x2000_setpoint, 1000U);
  {
    NoAllocationScope noAllocation;
    EXPECT_EQ(store.load(kCommunication), StoreResult::kOk);
    EXPECT_EQ(store.load(kApplication), StoreResult::kOk);
  }
  EXPECT_EQ(fresh.values.x1017_producer_heartbeat_time, 1500U);
  EXPECT_EQ(fresh.values.x2000_setpoint, 5000U);
  EXPECT_EQ(fresh.values.x2004_mixed_record.offset, 17);
  EXPECT_EQ(fresh.values.x2004_mixed_record.position, -123456);
  EXPECT_FLOAT_EQ(fresh.values.x2004_mixed_record.gain, 2.5F);
  EXPECT_STREQ(fresh.values.x2006_device_label, "pump 7");
  EXPECT_EQ(fresh.values.x2007_calibration[0], 8U);
  EXPECT_EQ(fresh.values.x2007_calibration[7], 1U);
  EXPECT_EQ(fresh.values.x2004_mixed_record.ratio, 0.25) << "unchanged entries keep their value";
  EXPECT_EQ(fresh.values.x2001_uptime_seconds, 0U);
  EXPECT_EQ(groupBytes(fresh.dictionary, kApplication), groupBytes(od, kApplication));
}

TEST_F(ParameterStoreTest, VolatileEntriesAreNeitherSavedNorLoaded) {
  device_.values.x2001_uptime_seconds = 77;  // ro, group none
  device_.values.x1001_error_register = 0x11;
  ASSERT_EQ(store_.save(kApplication), StoreResult::kOk);
  ASSERT_EQ(store_.save(kCommunication), StoreResult::kOk);
  ExampleDictionary fresh(gen::example::kDefinition);
  fresh.values.x2001_uptime_seconds = 5;
  ParameterStore store(fresh.dictionary, storage_);
  ASSERT_TRUE(store.layOut());
  ASSERT_EQ(store.load(kApplication), StoreResult::kOk);
  ASSERT_EQ(store.load(kCommunication), StoreResult::kOk);
  EXPECT_EQ(fresh.values.x2001_uptime_seconds, 5U);
  EXPECT_EQ(fresh.values.x1001_error_register, 0U);
}

TEST_F(ParameterStoreTest, GroupsAreSavedAndLoadedIndependently) {
  ASSERT_EQ(savePattern(kCommunication, 1), StoreResult::kOk);
  ASSERT_EQ(savePattern(kApplication, 2), StoreResult::kOk);
  ASSERT_EQ(savePattern(kApplication, 3), StoreResult::kOk);
  ASSERT_EQ(savePattern(kApplication, 4), StoreResult::kOk);
  EXPECT_EQ(loadFresh(kCommunication).bytes, pattern(kCommunication, 1));
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 4));

  // Loading one group leaves the other group's values alone.
  ExampleDictionary fresh(gen::example::kDefinition);
  fillGroup(fresh.dictionary, kCommunication, 9);
  ParameterStore store(fresh.dictionary, storage_);
  ASSERT_TRUE(store.layOut());
  ASSERT_EQ(store.load(kApplication), StoreResult::kOk);
  EXPECT_EQ(groupBytes(fresh.dictionary, kCommunication), pattern(kCommunication, 9));
}

TEST_F(ParameterStoreTest, WithNothingStoredALoadKeepsTheDefaults) {
  const Loaded loaded = loadFresh(kApplication);
  EXPECT_EQ(loaded.result, StoreResult::kNoImage);
  EXPECT_EQ(loaded.bytes, defaults(kApplication));
  fillGroup(device_.dictionary, kApplication, 5);
  EXPECT_EQ(store_.load(kApplication), StoreResult::kNoImage);
  EXPECT_EQ(groupBytes(device_.dictionary, kApplication), pattern(kApplication, 5));
}

TEST_F(ParameterStoreTest, InvalidateMakesTheNextBootUseDefaultsWithoutTouchingTheValues) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  ASSERT_EQ(savePattern(kCommunication, 1), StoreResult::kOk);
  EXPECT_EQ(store_.invalidate(kApplication), StoreResult::kOk);
  EXPECT_EQ(groupBytes(device_.dictionary, kApplication), pattern(kApplication, 1));
  const Loaded loaded = loadFresh(kApplication);
  EXPECT_EQ(loaded.result, StoreResult::kNoImage);
  EXPECT_EQ(loaded.bytes, defaults(kApplication));
  EXPECT_EQ(loadFresh(kCommunication).bytes, pattern(kCommunication, 1));

  const SlotInfo marker = slot(kApplication, 1);
  ASSERT_EQ(marker.state, SlotState::kIntact);
  EXPECT_EQ(marker.header.kind, ImageKind::kDefaults);
  EXPECT_EQ(marker.header.payloadLength, 0U);

  EXPECT_EQ(store_.invalidate(kApplication), StoreResult::kOk);  // twice is fine
  EXPECT_EQ(loadFresh(kApplication).result, StoreResult::kNoImage);
  ASSERT_EQ(savePattern(kApplication, 2), StoreResult::kOk);
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 2));
}

TEST_F(ParameterStoreTest, SavesAlternateBetweenTheSlotsWithRisingSequences) {
  for (unsigned n = 1; n <= 4; ++n) {
    ASSERT_EQ(savePattern(kApplication, n), StoreResult::kOk);
    const SlotInfo written = slot(kApplication, (n - 1U) % 2U);
    ASSERT_EQ(written.state, SlotState::kIntact) << "save " << n;
    EXPECT_EQ(written.header.sequence, n);
    EXPECT_EQ(written.header.region, kApplication);
    EXPECT_EQ(written.header.layout, gen::example::kDefinition.layoutId);
    EXPECT_EQ(written.header.location, slotOffset(kApplication, (n - 1U) % 2U));
    EXPECT_EQ(written.header.kind, ImageKind::kValues);
  }
  EXPECT_EQ(slot(kCommunication, 0).state, SlotState::kBlank);
  EXPECT_EQ(slot(kCommunication, 1).state, SlotState::kBlank);
}

TEST_F(ParameterStoreTest, TheNewestImageWinsAcrossTheSequenceWrap) {
  // Slot 0 holds pattern 1 with the last sequence before the wrap.
  const std::vector<uint8_t> old = pattern(kApplication, 1);
  ImageHeader header{};
  header.formatVersion = kImageFormatVersion;
  header.kind = ImageKind::kValues;
  header.region = kApplication;
  header.layout = gen::example::kDefinition.layoutId;
  header.location = static_cast<uint32_t>(slotOffset(kApplication, 0));
  header.payloadLength = static_cast<uint32_t>(old.size());
  header.sequence = 0xFFFFFFFFU;
  ImageWriter writer(storage_, slotOffset(kApplication, 0), slotSize(kApplication));
  ASSERT_TRUE(writer.begin(header) && writer.append(old.data(), old.size()) && writer.finish());
  EXPECT_EQ(loadFresh(kApplication).bytes, old);

  ASSERT_EQ(savePattern(kApplication, 2), StoreResult::kOk);
  EXPECT_EQ(slot(kApplication, 1).header.sequence, 0U);
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 2));
  ASSERT_EQ(savePattern(kApplication, 3), StoreResult::kOk);
  EXPECT_EQ(slot(kApplication, 0).header.sequence, 1U);
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 3));
}

TEST_F(ParameterStoreTest, NothingIsWrittenExceptBySaveAndInvalidate) {
  EXPECT_GT(store_.requiredSize(), 0U);
  EXPECT_TRUE(store_.layOut());
  EXPECT_EQ(store_.load(kCommunication), StoreResult::kNoImage);
  EXPECT_EQ(store_.load(kApplication), StoreResult::kNoImage);
  EXPECT_EQ(store_.save(od::kGroupLss), StoreResult::kUnknownGroup);
  EXPECT_EQ(store_.invalidate(200), StoreResult::kUnknownGroup);
  EXPECT_EQ(store_.load(od::kGroupNone), StoreResult::kUnknownGroup);
  EXPECT_EQ(storage_.modifyingCalls(), 0U);

  ASSERT_EQ(store_.save(kCommunication), StoreResult::kOk);
  EXPECT_EQ(storage_.commits(), 1U);
  EXPECT_EQ(storage_.eraseCalls(), 1U);
  storage_.resetCounters();
  EXPECT_EQ(loadFresh(kCommunication).result, StoreResult::kOk);
  EXPECT_EQ(store_.load(kCommunication), StoreResult::kOk);
  EXPECT_EQ(storage_.modifyingCalls(), 0U);
  ASSERT_EQ(store_.invalidate(kCommunication), StoreResult::kOk);
  EXPECT_EQ(storage_.commits(), 1U);
}

TEST_F(ParameterStoreTest, ASaveProgramsOneSlotAndCommitsOnce) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  EXPECT_EQ(storage_.bytesErased(), slotSize(kApplication));
  EXPECT_EQ(storage_.bytesWritten(), slotSize(kApplication));
  EXPECT_EQ(storage_.commits(), 1U);
  // Everything outside the written slot is still erased.
  for (size_t i = 0; i < storage_.size(); ++i) {
    if (i < slotOffset(kApplication, 0) || i >= slotOffset(kApplication, 1)) {
      ASSERT_EQ(storage_.bytes()[i], 0xFFU) << "byte " << i;
    }
  }
}

}  // namespace
}  // namespace costa::test
