// ParameterStore against damaged, foreign and failing media: a damaged image never reaches the
// dictionary, an image made for another layout is reported as such, and medium errors surface.
#include <gtest/gtest.h>

#include <vector>

#include "parameter_store_fixture.hpp"

namespace costa::test {
namespace {

using ParameterStoreDamageTest = ExampleStoreTest;

/// Writes an image with the given header fields and payload into the slot at `slotOffset`.
void craftImage(NvStorage& storage, size_t slotOffset, size_t slotSize, const ImageHeader& header,
                const std::vector<uint8_t>& payload) {
  ImageWriter writer(storage, slotOffset, slotSize);
  ASSERT_TRUE(writer.begin(header));
  ASSERT_TRUE(writer.append(payload.data(), payload.size()));
  ASSERT_TRUE(writer.finish());
}

TEST_F(ParameterStoreDamageTest, ADamagedByteInTheNewestImageFallsBackToTheOlderImage) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  ASSERT_EQ(savePattern(kApplication, 2), StoreResult::kOk);  // newest, in slot 1
  const size_t newest = slotOffset(kApplication, 1);
  const size_t imageSize = kImageHeaderSize + defaults(kApplication).size();
  for (size_t i = 0; i < imageSize; ++i) {
    storage_.bytes()[newest + i] ^= 0x01U;
    const Loaded loaded = loadFresh(kApplication);
    EXPECT_EQ(loaded.result, StoreResult::kOk) << "byte " << i;
    EXPECT_EQ(loaded.bytes, pattern(kApplication, 1)) << "byte " << i;
    storage_.bytes()[newest + i] ^= 0x01U;
  }
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 2));
}

TEST_F(ParameterStoreDamageTest, ADamagedOnlyImageIsCorruptAndTheDefaultsStay) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  const size_t only = slotOffset(kApplication, 0);
  const size_t imageSize = kImageHeaderSize + defaults(kApplication).size();
  for (size_t i = 0; i < imageSize; ++i) {
    storage_.bytes()[only + i] ^= 0x40U;
    const Loaded loaded = loadFresh(kApplication);
    EXPECT_EQ(loaded.result, StoreResult::kCorrupt) << "byte " << i;
    EXPECT_EQ(loaded.bytes, defaults(kApplication)) << "byte " << i;
    storage_.bytes()[only + i] ^= 0x40U;
  }
}

TEST_F(ParameterStoreDamageTest, ADamagedOlderImageDoesNotMatter) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  ASSERT_EQ(savePattern(kApplication, 2), StoreResult::kOk);
  storage_.bytes()[slotOffset(kApplication, 0) + kImageHeaderSize + 3U] ^= 0xFFU;
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 2));
  // The next save replaces the damaged slot and keeps the newest one.
  ASSERT_EQ(savePattern(kApplication, 3), StoreResult::kOk);
  EXPECT_EQ(slot(kApplication, 0).state, SlotState::kIntact);
  EXPECT_EQ(slot(kApplication, 1).header.sequence, 2U);
}

TEST_F(ParameterStoreDamageTest, SavingOverACorruptRegionRepairsIt) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  storage_.bytes()[slotOffset(kApplication, 0) + 5U] ^= 0x01U;
  ASSERT_EQ(loadFresh(kApplication).result, StoreResult::kCorrupt);
  ASSERT_EQ(savePattern(kApplication, 2), StoreResult::kOk);
  EXPECT_EQ(slot(kApplication, 0).state, SlotState::kDamaged) << "the damaged slot is kept";
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 2));
}

TEST_F(ParameterStoreDamageTest, AnotherLayoutIdIsIncompatibleAndTheDefaultsStay) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  ASSERT_EQ(savePattern(kCommunication, 1), StoreResult::kOk);
  od::Definition changed = gen::example::kDefinition;
  changed.layoutId ^= 0x00010000U;
  const Loaded loaded = loadFresh(kApplication, changed);
  EXPECT_EQ(loaded.result, StoreResult::kIncompatible);
  EXPECT_EQ(loaded.bytes, defaults(kApplication));

  // The new firmware saves its own image; from then on it loads.
  ExampleDictionary updated(changed);
  fillGroup(updated.dictionary, kApplication, 7);
  ParameterStore store(updated.dictionary, storage_);
  ASSERT_TRUE(store.layOut());
  ASSERT_EQ(store.save(kApplication), StoreResult::kOk);
  EXPECT_EQ(loadFresh(kApplication, changed).bytes, pattern(kApplication, 7));
  EXPECT_EQ(loadFresh(kApplication).result, StoreResult::kOk)
      << "the old firmware still finds its own, older image";
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 1));
}

TEST_F(ParameterStoreDamageTest, ADefaultsMarkerHoldsForAnyLayout) {
  ASSERT_EQ(store_.invalidate(kApplication), StoreResult::kOk);
  od::Definition changed = gen::example::kDefinition;
  changed.layoutId += 1U;
  EXPECT_EQ(loadFresh(kApplication, changed).result, StoreResult::kNoImage);
}

class ForeignImageTest : public ExampleStoreTest,
                         public ::testing::WithParamInterface<const char*> {};

TEST_P(ForeignImageTest, IsIncompatibleAndLeavesTheDefaults) {
  const std::string what = GetParam();
  std::vector<uint8_t> payload = pattern(kApplication, 1);
  ImageHeader header{};
  header.formatVersion = kImageFormatVersion;
  header.kind = ImageKind::kValues;
  header.region = kApplication;
  header.layout = gen::example::kDefinition.layoutId;
  header.location = static_cast<uint32_t>(slotOffset(kApplication, 0));
  header.sequence = 1;
  if (what == "format version") {
    header.formatVersion = kImageFormatVersion + 1U;
  } else if (what == "kind") {
    header.kind = static_cast<ImageKind>(0x03);
  } else if (what == "region") {
    header.region = kCommunication;
  } else if (what == "location") {
    header.location += 1U;
  } else if (what == "shorter payload") {
    payload.pop_back();
  } else if (what == "marker with payload") {
    header.kind = ImageKind::kDefaults;
  }
  header.payloadLength = static_cast<uint32_t>(payload.size());
  craftImage(storage_, slotOffset(kApplication, 0), slotSize(kApplication), header, payload);
  ASSERT_EQ(slot(kApplication, 0).state, SlotState::kIntact);
  const Loaded loaded = loadFresh(kApplication);
  EXPECT_EQ(loaded.result, StoreResult::kIncompatible);
  EXPECT_EQ(loaded.bytes, defaults(kApplication));

  // A foreign image outranks a damaged one; the next save goes into the damaged slot.
  const uint8_t garbage[4] = {1, 2, 3, 4};
  ASSERT_TRUE(storage_.write(slotOffset(kApplication, 1), garbage, 4));
  EXPECT_EQ(loadFresh(kApplication).result, StoreResult::kIncompatible);
  ASSERT_EQ(savePattern(kApplication, 2), StoreResult::kOk);
  EXPECT_EQ(slot(kApplication, 1).state, SlotState::kIntact);
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 2));
}

INSTANTIATE_TEST_SUITE_P(Fields, ForeignImageTest,
                         ::testing::Values("format version", "kind", "region", "location",
                                           "shorter payload", "marker with payload"),
                         [](const ::testing::TestParamInfo<const char*>& parameter) {
                           std::string name;
                           for (const char* c = parameter.param; *c != '\0'; ++c) {
                             if (*c != ' ') {
                               name += *c;
                             }
                           }
                           return name;
                         });

/// A medium whose reads fail from a given read on, or that changes a byte after a given read.
// Format version 2 changed only how a $NODEID COB-ID is stored: a version 1 image of a region
// without one (here the application parameters) still counts; one with them is incompatible.
TEST_F(ParameterStoreDamageTest, AVersion1ImageCountsUnlessItHoldsANodeIdCobId) {
  for (const uint8_t group : {kApplication, kCommunication}) {
    const std::vector<uint8_t> payload = pattern(group, 1);
    ImageHeader header{};
    header.formatVersion = 1;
    header.kind = ImageKind::kValues;
    header.region = group;
    header.layout = gen::example::kDefinition.layoutId;
    header.location = static_cast<uint32_t>(slotOffset(group, 0));
    header.sequence = 1;
    header.payloadLength = static_cast<uint32_t>(payload.size());
    craftImage(storage_, slotOffset(group, 0), slotSize(group), header, payload);
    ASSERT_EQ(slot(group, 0).state, SlotState::kIntact);
  }
  const Loaded application = loadFresh(kApplication);
  EXPECT_EQ(application.result, StoreResult::kOk);
  EXPECT_EQ(application.bytes, pattern(kApplication, 1));
  const Loaded communication = loadFresh(kCommunication);
  EXPECT_EQ(communication.result, StoreResult::kIncompatible);
  EXPECT_EQ(communication.bytes, defaults(kCommunication));
}

class FlakyStorage : public port::MemoryStorage {
 public:
  FlakyStorage(uint8_t* bytes, size_t size) : MemoryStorage(bytes, size) {}
  bool read(size_t offset, uint8_t* destination, size_t length) noexcept override {
    ++reads_;
    if (failFrom_ != 0U && reads_ >= failFrom_) {
      return false;
    }
    if (flipAfter_ != 0U && reads_ == flipAfter_) {
      bytes()[flipOffset_] ^= 0x01U;
    }
    return MemoryStorage::read(offset, destination, length);
  }
  size_t reads_ = 0;
  size_t failFrom_ = 0;
  size_t flipAfter_ = 0;
  size_t flipOffset_ = 0;
};

TEST_F(ParameterStoreDamageTest, AMediumThatRefusesReadsIsAMediumErrorAndChangesNothing) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  FlakyStorage flaky(storage_.bytes(), storage_.size());
  ExampleDictionary fresh(gen::example::kDefinition);
  ParameterStore store(fresh.dictionary, flaky);
  ASSERT_TRUE(store.layOut());
  flaky.failFrom_ = 1;
  EXPECT_EQ(store.load(kApplication), StoreResult::kMediumError);
  EXPECT_EQ(store.save(kApplication), StoreResult::kMediumError);
  EXPECT_EQ(store.invalidate(kApplication), StoreResult::kMediumError);
  EXPECT_EQ(groupBytes(fresh.dictionary, kApplication), defaults(kApplication));
  EXPECT_EQ(flaky.modifyingCalls(), 0U);
}

TEST_F(ParameterStoreDamageTest, AReadFailingDuringTheCopyRestoresTheGroupDefaults) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  FlakyStorage flaky(storage_.bytes(), storage_.size());
  ExampleDictionary fresh(gen::example::kDefinition);
  ParameterStore store(fresh.dictionary, flaky);
  ASSERT_TRUE(store.layOut());
  ASSERT_EQ(store.load(kApplication), StoreResult::kOk);
  const size_t readsPerLoad = flaky.reads_;
  fillGroup(fresh.dictionary, kApplication, 5);
  flaky.reads_ = 0;
  flaky.failFrom_ = readsPerLoad - 1U;  // a read of the copy, after both slots were checked
  EXPECT_EQ(store.load(kApplication), StoreResult::kMediumError);
  EXPECT_EQ(groupBytes(fresh.dictionary, kApplication), defaults(kApplication));
}

TEST_F(ParameterStoreDamageTest, AMediumThatChangesAfterTheCheckRestoresTheGroupDefaults) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  FlakyStorage flaky(storage_.bytes(), storage_.size());
  ExampleDictionary fresh(gen::example::kDefinition);
  ParameterStore store(fresh.dictionary, flaky);
  ASSERT_TRUE(store.layOut());
  ASSERT_EQ(store.load(kApplication), StoreResult::kOk);
  // The last read of a load copies the last entry, long after both slots were checked: the
  // last payload byte changes right before it.
  const size_t readsPerLoad = flaky.reads_;
  flaky.reads_ = 0;
  flaky.flipAfter_ = readsPerLoad;
  flaky.flipOffset_ = slotOffset(kApplication, 0) + slotSize(kApplication) - 1U;
  EXPECT_EQ(store.load(kApplication), StoreResult::kCorrupt);
  EXPECT_EQ(groupBytes(fresh.dictionary, kApplication), defaults(kApplication));
}

TEST_F(ParameterStoreDamageTest, AFailedSaveKeepsThePreviousImage) {
  ASSERT_EQ(savePattern(kApplication, 1), StoreResult::kOk);
  storage_.cutPowerAfter(0);
  EXPECT_EQ(savePattern(kApplication, 2), StoreResult::kMediumError);
  EXPECT_EQ(store_.invalidate(kApplication), StoreResult::kMediumError);
  storage_.restorePower();
  EXPECT_EQ(loadFresh(kApplication).bytes, pattern(kApplication, 1));
}

}  // namespace
}  // namespace costa::test
