// Raw records (data that is not in the dictionary, such as the LSS node-id and bit timing):
// reservation, layout at the end of the medium (where no change of the groups moves them),
// save/load/invalidate, limits, power loss.
#include <gtest/gtest.h>

#include <vector>

#include "allocation_guard.hpp"
#include "dictionary_instance.hpp"
#include "parameter_store_fixture.hpp"
#include "storage_groups_od.hpp"

namespace costa::test {
namespace {

constexpr uint8_t kLssRecord = 0x05;  // e.g. node-id and bit timing
constexpr uint8_t kOtherRecord = 0x01;

class ParameterStoreRecordTest : public ExampleStoreTest {
 protected:
  void SetUp() override {
    ASSERT_TRUE(store_.reserveRecord(kLssRecord, 2));
    ASSERT_TRUE(store_.reserveRecord(kOtherRecord, 16));
    ASSERT_TRUE(store_.layOut());
  }
  /// Where a record's slot lies: at the end of the medium, records by ascending id.
  size_t recordSlot(uint8_t recordId, size_t slot) const {
    const size_t other = kImageHeaderSize + 16U;
    const size_t lss = kImageHeaderSize + 2U;
    const size_t start = storage_.size() - 2U * other - 2U * lss;
    if (recordId == kOtherRecord) {
      return start + slot * other;
    }
    return start + 2U * other + slot * lss;
  }
  struct Read {
    StoreResult result;
    std::vector<uint8_t> data;
  };
  Read loadRecordFresh(uint8_t recordId) {
    ExampleDictionary fresh(gen::example::kDefinition);
    ParameterStore store(fresh.dictionary, storage_);
    if (!store.reserveRecord(kLssRecord, 2) || !store.reserveRecord(kOtherRecord, 16) ||
        !store.layOut()) {
      return {StoreResult::kNotLaidOut, {}};
    }
    uint8_t buffer[16];
    size_t length = 99;
    const StoreResult result = store.loadRecord(recordId, buffer, sizeof(buffer), &length);
    return {result, std::vector<uint8_t>(buffer, buffer + length)};
  }
};

TEST_F(ParameterStoreRecordTest, RecordsSitAtTheEndOfTheMediumInAscendingIdOrder) {
  const size_t groups = 2U * slotSize(kCommunication) + 2U * slotSize(kApplication);
  EXPECT_EQ(store_.requiredSize(),
            groups + 2U * (kImageHeaderSize + 16U) + 2U * (kImageHeaderSize + 2U));
  const uint8_t lss[2] = {0x20, 0x03};
  ASSERT_EQ(store_.saveRecord(kLssRecord, lss, 2), StoreResult::kOk);
  const SlotInfo info = inspectSlot(storage_, recordSlot(kLssRecord, 0), kImageHeaderSize + 2U);
  ASSERT_EQ(info.state, SlotState::kIntact);
  EXPECT_EQ(info.header.region, 0x0105U);
  EXPECT_EQ(info.header.layout, 0U);
  EXPECT_EQ(info.header.payloadLength, 2U);
}

// A firmware update that stores other parameters lays the groups out anew; the records stay
// where they were, so the LSS node-id and bit rate survive it.
TEST_F(ParameterStoreRecordTest, AnotherSetOfGroupsDoesNotMoveTheRecords) {
  const uint8_t lss[2] = {0x20, 0x03};
  ASSERT_EQ(store_.saveRecord(kLssRecord, lss, 2), StoreResult::kOk);
  DictionaryInstance<gen::storage_groups::Values> other(gen::storage_groups::kDefinition);
  ParameterStore store(other.dictionary, storage_);
  ASSERT_TRUE(store.reserveRecord(kLssRecord, 2));
  ASSERT_TRUE(store.reserveRecord(kOtherRecord, 16));
  ASSERT_TRUE(store.layOut());
  ASSERT_NE(store.requiredSize(), store_.requiredSize());  // other groups indeed
  uint8_t buffer[2] = {};
  size_t length = 0;
  EXPECT_EQ(store.loadRecord(kLssRecord, buffer, sizeof(buffer), &length), StoreResult::kOk);
  EXPECT_EQ(std::vector<uint8_t>(buffer, buffer + length), (std::vector<uint8_t>{0x20, 0x03}));
}

TEST_F(ParameterStoreRecordTest, ASavedRecordComesBackWithItsLength) {
  const uint8_t lss[2] = {0x20, 0x03};
  const uint8_t other[5] = {1, 2, 3, 4, 5};
  {
    NoAllocationScope noAllocation;
    EXPECT_EQ(store_.saveRecord(kLssRecord, lss, 2), StoreResult::kOk);
    EXPECT_EQ(store_.saveRecord(kOtherRecord, other, 5), StoreResult::kOk);
  }
  EXPECT_EQ(loadRecordFresh(kLssRecord).data, (std::vector<uint8_t>{0x20, 0x03}));
  const Read read = loadRecordFresh(kOtherRecord);
  EXPECT_EQ(read.result, StoreResult::kOk);
  EXPECT_EQ(read.data, (std::vector<uint8_t>{1, 2, 3, 4, 5}));

  EXPECT_EQ(store_.saveRecord(kOtherRecord, other, 0), StoreResult::kOk);
  const Read empty = loadRecordFresh(kOtherRecord);
  EXPECT_EQ(empty.result, StoreResult::kOk) << "an empty record is not a missing record";
  EXPECT_EQ(empty.data.size(), 0U);
}

TEST_F(ParameterStoreRecordTest, MissingAndInvalidatedRecordsHaveNoImage) {
  const Read missing = loadRecordFresh(kLssRecord);
  EXPECT_EQ(missing.result, StoreResult::kNoImage);
  EXPECT_EQ(missing.data.size(), 0U);
  const uint8_t lss[2] = {0x20, 0x03};
  ASSERT_EQ(store_.saveRecord(kLssRecord, lss, 2), StoreResult::kOk);
  EXPECT_EQ(store_.invalidateRecord(kLssRecord), StoreResult::kOk);
  EXPECT_EQ(loadRecordFresh(kLssRecord).result, StoreResult::kNoImage);
  ASSERT_EQ(store_.saveRecord(kLssRecord, lss, 1), StoreResult::kOk);
  EXPECT_EQ(loadRecordFresh(kLssRecord).data, (std::vector<uint8_t>{0x20}));
}

TEST_F(ParameterStoreRecordTest, RecordsAndGroupsDoNotDisturbEachOther) {
  const uint8_t lss[2] = {0x7F, 0x04};
  ASSERT_EQ(store_.saveRecord(kLssRecord, lss, 2), StoreResult::kOk);
  ASSERT_EQ(savePattern(kApplication, 3), StoreResult::kOk);
  ASSERT_EQ(store_.invalidate(kApplication), StoreResult::kOk);
  ASSERT_EQ(savePattern(kCommunication, 3), StoreResult::kOk);
  EXPECT_EQ(loadRecordFresh(kLssRecord).data, (std::vector<uint8_t>{0x7F, 0x04}));
  EXPECT_EQ(loadRecordFresh(kOtherRecord).result, StoreResult::kNoImage);
}

TEST_F(ParameterStoreRecordTest, LengthsBeyondTheReservationOrTheBufferAreRefused) {
  const uint8_t data[17] = {};
  EXPECT_EQ(store_.saveRecord(kLssRecord, data, 3), StoreResult::kTooLong);
  EXPECT_EQ(store_.saveRecord(kOtherRecord, data, 17), StoreResult::kTooLong);
  EXPECT_EQ(storage_.modifyingCalls(), 0U);

  ASSERT_EQ(store_.saveRecord(kOtherRecord, data, 16), StoreResult::kOk);
  uint8_t small[15];
  std::fill(small, small + sizeof(small), 0xAA);
  size_t length = 99;
  EXPECT_EQ(store_.loadRecord(kOtherRecord, small, sizeof(small), &length), StoreResult::kTooLong);
  EXPECT_EQ(length, 0U);
  EXPECT_EQ(small[0], 0xAAU) << "nothing copied";
}

TEST_F(ParameterStoreRecordTest, UnknownRecordsAndReservationLimits) {
  const uint8_t data[1] = {};
  uint8_t buffer[4];
  size_t length = 99;
  EXPECT_EQ(store_.saveRecord(0x06, data, 1), StoreResult::kUnknownGroup);
  EXPECT_EQ(store_.loadRecord(0x06, buffer, 4, &length), StoreResult::kUnknownGroup);
  EXPECT_EQ(length, 0U);
  EXPECT_EQ(store_.invalidateRecord(0x06), StoreResult::kUnknownGroup);
  EXPECT_EQ(store_.load(kLssRecord), StoreResult::kUnknownGroup) << "records are not groups";
  EXPECT_EQ(storage_.modifyingCalls(), 0U);

  EXPECT_FALSE(store_.reserveRecord(kLssRecord, 4)) << "already reserved";
  EXPECT_TRUE(store_.isLaidOut());
  for (uint8_t id = 10; id < 10U + ParameterStore::kMaxRecords - 2U; ++id) {
    EXPECT_TRUE(store_.reserveRecord(id, 1));
  }
  EXPECT_FALSE(store_.reserveRecord(100, 1)) << "table full";
  EXPECT_FALSE(store_.isLaidOut()) << "a new reservation needs a new layout";
  EXPECT_EQ(store_.saveRecord(kLssRecord, data, 1), StoreResult::kNotLaidOut);
  EXPECT_EQ(store_.loadRecord(kLssRecord, buffer, 4, &length), StoreResult::kNotLaidOut);
  EXPECT_EQ(store_.invalidateRecord(kLssRecord), StoreResult::kNotLaidOut);
  EXPECT_TRUE(store_.layOut());
  EXPECT_EQ(store_.saveRecord(11, data, 1), StoreResult::kOk);
}

TEST_F(ParameterStoreRecordTest, DamagedRecordsFailingAndTooSmallMedia) {
  const uint8_t lss[2] = {0x20, 0x03};
  ASSERT_EQ(store_.saveRecord(kLssRecord, lss, 2), StoreResult::kOk);
  storage_.bytes()[recordSlot(kLssRecord, 0) + kImageHeaderSize] ^= 0x01U;
  const Read read = loadRecordFresh(kLssRecord);
  EXPECT_EQ(read.result, StoreResult::kCorrupt);
  EXPECT_EQ(read.data.size(), 0U);

  storage_.cutPowerAfter(0);
  EXPECT_EQ(store_.saveRecord(kLssRecord, lss, 2), StoreResult::kMediumError);
  EXPECT_EQ(store_.invalidateRecord(kLssRecord), StoreResult::kMediumError);
  storage_.restorePower();
  port::MemoryStorage truncated(storage_.bytes(), store_.requiredSize() - 1U);
  ExampleDictionary fresh(gen::example::kDefinition);
  ParameterStore store(fresh.dictionary, truncated);
  ASSERT_TRUE(store.reserveRecord(kOtherRecord, 16));
  ASSERT_TRUE(store.reserveRecord(kLssRecord, 2));
  EXPECT_FALSE(store.layOut()) << "a byte short of every region";
}

/// The medium of the fixture, read through a flaw from a given read on: the read fails, or
/// returns its bytes with the first one changed (a medium that went bad after the record's image
/// was examined, before it was read).
class FlawedReads : public NvStorage {
 public:
  enum class Flaw { kNone, kFails, kChangesAByte };
  explicit FlawedReads(NvStorage& medium) : medium_(medium) {}
  void from(size_t read, Flaw flaw) {
    flawFrom_ = read;
    flaw_ = flaw;
    reads_ = 0;
  }
  size_t reads() const { return reads_; }

  size_t size() const noexcept override { return medium_.size(); }
  bool read(size_t offset, uint8_t* destination, size_t length) noexcept override {
    const bool flawed = flaw_ != Flaw::kNone && reads_++ >= flawFrom_;
    if (flawed && flaw_ == Flaw::kFails) {
      return false;
    }
    if (!medium_.read(offset, destination, length)) {
      return false;
    }
    if (flawed && length > 0U) {
      destination[0] ^= 0x01U;
    }
    return true;
  }
  bool write(size_t offset, const uint8_t* source, size_t length) noexcept override {
    return medium_.write(offset, source, length);
  }
  bool erase(size_t offset, size_t length) noexcept override {
    return medium_.erase(offset, length);
  }
  bool commit() noexcept override { return medium_.commit(); }

 private:
  NvStorage& medium_;
  size_t reads_ = 0;
  size_t flawFrom_ = 0;
  Flaw flaw_ = Flaw::kNone;
};

TEST_F(ParameterStoreRecordTest, AMediumThatFailsWhileARecordIsReadLoadsNothing) {
  const uint8_t other[5] = {1, 2, 3, 4, 5};
  ASSERT_EQ(store_.saveRecord(kOtherRecord, other, sizeof(other)), StoreResult::kOk);
  FlawedReads medium(storage_);
  ExampleDictionary fresh(gen::example::kDefinition);
  ParameterStore store(fresh.dictionary, medium);
  ASSERT_TRUE(store.reserveRecord(kLssRecord, 2));
  ASSERT_TRUE(store.reserveRecord(kOtherRecord, 16));
  ASSERT_TRUE(store.layOut());
  uint8_t buffer[16] = {};
  size_t length = 99;
  // Unflawed, counting the reads: the image is examined, then its payload read, last.
  medium.from(SIZE_MAX, FlawedReads::Flaw::kFails);
  ASSERT_EQ(store.loadRecord(kOtherRecord, buffer, sizeof(buffer), &length), StoreResult::kOk);
  ASSERT_EQ(length, sizeof(other));
  const size_t reads = medium.reads();
  ASSERT_GE(reads, 2U);

  medium.from(0, FlawedReads::Flaw::kFails);  // the examination fails
  length = 99;
  EXPECT_EQ(store.loadRecord(kOtherRecord, buffer, sizeof(buffer), &length),
            StoreResult::kMediumError);
  EXPECT_EQ(length, 0U);
  medium.from(reads - 1U, FlawedReads::Flaw::kFails);  // only the payload's read fails
  length = 99;
  EXPECT_EQ(store.loadRecord(kOtherRecord, buffer, sizeof(buffer), &length),
            StoreResult::kMediumError);
  EXPECT_EQ(length, 0U);
  medium.from(reads - 1U, FlawedReads::Flaw::kChangesAByte);  // its bytes no longer match
  length = 99;
  EXPECT_EQ(store.loadRecord(kOtherRecord, buffer, sizeof(buffer), &length), StoreResult::kCorrupt);
  EXPECT_EQ(length, 0U);
  medium.from(SIZE_MAX, FlawedReads::Flaw::kNone);  // the medium itself was never changed
  EXPECT_EQ(store.loadRecord(kOtherRecord, buffer, sizeof(buffer), &length), StoreResult::kOk);
  EXPECT_EQ(std::vector<uint8_t>(buffer, buffer + length), std::vector<uint8_t>(other, other + 5));
}

TEST_F(ParameterStoreRecordTest, PowerLossDuringASaveOrInvalidateKeepsAWholeRecord) {
  const uint8_t first[2] = {0x11, 0x11};
  const uint8_t second[2] = {0x22, 0x22};
  ASSERT_EQ(store_.saveRecord(kLssRecord, first, 2), StoreResult::kOk);
  storage_.resetCounters();
  ASSERT_EQ(store_.saveRecord(kLssRecord, second, 2), StoreResult::kOk);
  const size_t total = storage_.bytesWritten() + storage_.bytesErased();
  ASSERT_EQ(store_.saveRecord(kLssRecord, first, 2), StoreResult::kOk);
  // Slot state now: "first" newest, "second" older. Alternate between the two sets.
  std::vector<uint8_t> current{0x11, 0x11};
  for (size_t cut = 0; cut <= total; ++cut) {
    const bool toSecond = current[0] == 0x11;
    storage_.cutPowerAfter(cut);
    const StoreResult result = store_.saveRecord(kLssRecord, toSecond ? second : first, 2);
    storage_.restorePower();
    EXPECT_EQ(result == StoreResult::kOk, cut == total) << "cut after " << cut;
    if (result == StoreResult::kOk) {
      current = toSecond ? std::vector<uint8_t>{0x22, 0x22} : std::vector<uint8_t>{0x11, 0x11};
    }
    EXPECT_EQ(loadRecordFresh(kLssRecord).data, current) << "cut after " << cut;
  }
  // An invalidate programs the erase of the slot and the header.
  const size_t invalidateTotal = kImageHeaderSize + 2U + kImageHeaderSize;
  for (size_t cut = 0; cut < invalidateTotal; ++cut) {
    storage_.cutPowerAfter(cut);
    EXPECT_EQ(store_.invalidateRecord(kLssRecord), StoreResult::kMediumError);
    storage_.restorePower();
    EXPECT_EQ(loadRecordFresh(kLssRecord).data, current) << "cut after " << cut;
  }
  storage_.cutPowerAfter(invalidateTotal);
  EXPECT_EQ(store_.invalidateRecord(kLssRecord), StoreResult::kOk);
  storage_.restorePower();
  EXPECT_EQ(loadRecordFresh(kLssRecord).result, StoreResult::kNoImage);
}

}  // namespace
}  // namespace costa::test
