// PdoEngine alone, receive side: RPDOs whole or not at all, length EMCYs, SYNC, deadlines, rules.
#include <gtest/gtest.h>

#include "pdo_fixture.hpp"

namespace costa::test {
namespace {

using PdoReceive = PdoEngineTest;
using PdoParameters = PdoEngineTest;

TEST_F(PdoReceive, BindFindsEveryPdoOfTheDictionary) {
  ASSERT_EQ(pdos_.rpdoCount(), 2U);
  ASSERT_EQ(pdos_.tpdoCount(), 2U);
  EXPECT_EQ(pdos_.rpdo(0).communicationIndex(), 0x1400U);
  EXPECT_EQ(pdos_.rpdo(1).communicationIndex(), 0x1401U);
  EXPECT_EQ(pdos_.tpdo(0).communicationIndex(), 0x1800U);
  EXPECT_EQ(pdos_.tpdo(1).communicationIndex(), 0x1801U);
  EXPECT_TRUE(pdos_.rpdo(0).valid());
  EXPECT_EQ(pdos_.rpdo(0).canId(), 0x205U);
  EXPECT_EQ(pdos_.rpdo(0).mappedBytes(), 3U);
  EXPECT_EQ(pdos_.tpdo(1).canId(), 0x285U);
  EXPECT_EQ(pdos_.tpdo(1).transmissionType(), 1U);
  EXPECT_EQ(pdos_.unresolvableMappings(), 0U);
}

TEST_F(PdoReceive, AnEventDrivenRpdoIsWrittenAtOnceBetweenItsTwoNotifications) {
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x07, 0x34, 0x12}), kStart));
  EXPECT_EQ(value(0x2000, 1), 0x07U);
  EXPECT_EQ(value(0x2000, 2), 0x1234U);
  EXPECT_EQ(listener_.take(),
            (std::vector<std::string>{"rpdo writing 1400", "rpdo received 1400"}));
  EXPECT_TRUE(sent().empty());
}

TEST_F(PdoReceive, NothingIsReceivedOutsideOperational) {
  EXPECT_FALSE(pdos_.receive(0, frame(0x205, {0x07, 0x34, 0x12}), kStart));
  pdos_.start(kStart);
  pdos_.stop();
  EXPECT_FALSE(pdos_.receive(0, frame(0x205, {0x07, 0x34, 0x12}), kStart));
  EXPECT_EQ(value(0x2000, 1), 0U);
  EXPECT_TRUE(listener_.take().empty());
}

TEST_F(PdoReceive, ATooShortRpdoRaisesEmcy8210AndWritesNothing) {
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x07, 0x34}), kStart));
  EXPECT_EQ(value(0x2000, 1), 0U);
  EXPECT_TRUE(listener_.take().empty());
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x07, 0x34, 0x12}), kStart));  // clears it
  EXPECT_EQ(value(0x2000, 1), 0x07U);
  EXPECT_EQ(emcySent(), frames({frame8(0x85, {0x10, 0x82, 0x11}), frame8(0x85, {})}));
}

TEST_F(PdoReceive, ALongerRpdoIsWrittenAndRaisesEmcy8220) {
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x07, 0x34, 0x12, 0xFF}), kStart));
  EXPECT_EQ(value(0x2000, 2), 0x1234U);
  EXPECT_TRUE(emcy_.active(RpdoChannel::kEmcyLengthLong, 0x00));
  EXPECT_EQ(pdos_.rpdosRefused(), 0U);
  EXPECT_EQ(emcySent(), frames({frame8(0x85, {0x20, 0x82, 0x11})}));
}

TEST_F(PdoReceive, AnRpdoWithARefusedEntryIsNotWrittenAtAllAndIsCounted) {
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.receive(1, frame(0x305, {0x07, 25}), kStart));  // 0x2002 is 10..20
  EXPECT_EQ(value(0x2000, 1), 0U);  // the first entry was fine, but nothing is written
  EXPECT_EQ(value(0x2002, 0), 15U);
  EXPECT_EQ(pdos_.rpdosRefused(), 1U);
  EXPECT_TRUE(listener_.take().empty());
  EXPECT_TRUE(pdos_.receive(1, frame(0x305, {0x07, 12}), kStart));
  EXPECT_EQ(value(0x2000, 1), 0x07U);
  EXPECT_EQ(value(0x2002, 0), 12U);
  EXPECT_EQ(pdos_.rpdosRefused(), 1U);
  EXPECT_EQ(listener_.take(),
            (std::vector<std::string>{"rpdo writing 1401", "rpdo received 1401"}));
}

// A hook whose check passes what its write then refuses (a device state that changed between the
// two, a medium that failed): the entries written before it get their old values back.
class RefusingWrites : public ObjectHook {
 public:
  AbortCode write(od::ObjectDictionary& /*dictionary*/, const od::EntryRef& /*ref*/,
                  const uint8_t* /*data*/, size_t /*length*/) noexcept override {
    ++writes;
    return AbortCode::kCannotStoreState;
  }
  int writes = 0;
};

TEST_F(PdoReceive, AnEntryRefusedAtItsWriteUndoesTheEntriesWrittenBeforeIt) {
  RefusingWrites refusing;
  ASSERT_TRUE(hooks_.attach(0x2002, 0x2002, refusing));
  pdos_.refreshMappings();  // 0x2002 now goes through its hook
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.receive(1, frame(0x305, {0x07, 12}), kStart));  // 12: within 10..20
  EXPECT_EQ(refusing.writes, 1);
  EXPECT_EQ(value(0x2000, 1), 0U);  // written first, then restored
  EXPECT_EQ(value(0x2002, 0), 15U);
  EXPECT_EQ(pdos_.rpdosRefused(), 1U);
  // Its checks had passed: the device heard the writing begin, but never that it was received.
  EXPECT_EQ(listener_.take(), (std::vector<std::string>{"rpdo writing 1401"}));
  // RPDO 1 maps 0x2000:01 too, without the hook: written as ever.
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x09, 0x34, 0x12}), kStart));
  EXPECT_EQ(value(0x2000, 1), 0x09U);
  EXPECT_EQ(pdos_.rpdosRefused(), 1U);
}

TEST_F(PdoReceive, ASynchronousRpdoIsHeldUntilTheNextSync) {
  EXPECT_EQ(write(pdos_, 0x1400, 2, 1, 1), AbortCode::kNone);
  pdos_.start(kStart);
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x01, 0x00, 0x00}), kStart));
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x02, 0x00, 0x00}), kStart));  // the latest counts
  EXPECT_EQ(value(0x2000, 1), 0U);
  EXPECT_TRUE(pdos_.rpdo(0).holding());
  pdos_.onSync(0, after(100), kNever);
  EXPECT_EQ(value(0x2000, 1), 0x02U);
  EXPECT_FALSE(pdos_.rpdo(0).holding());
  EXPECT_EQ(listener_.take(),
            (std::vector<std::string>{"rpdo writing 1400", "rpdo received 1400"}));
}

TEST_F(PdoReceive, AMissedDeadlineRaisesEmcy8250OnceAndTheNextRpdoClearsIt) {
  EXPECT_EQ(write(pdos_, 0x1400, 5, 100, 2), AbortCode::kNone);
  pdos_.start(kStart);
  EXPECT_EQ(pdos_.nextDeadline(), kNever);  // monitoring starts with the first RPDO
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x01, 0x00, 0x00}), kStart));
  EXPECT_EQ(pdos_.nextDeadline(), afterMs(100));
  (void)listener_.take();
  pdos_.process(afterMs(100) - 1U);
  EXPECT_TRUE(listener_.take().empty());
  pdos_.process(afterMs(100));
  pdos_.process(afterMs(300));
  EXPECT_EQ(listener_.take(), (std::vector<std::string>{"rpdo timeout 1400"}));
  EXPECT_TRUE(pdos_.receive(0, frame(0x205, {0x02, 0x00, 0x00}), afterMs(400)));
  EXPECT_EQ(emcySent(), frames({frame8(0x85, {0x50, 0x82, 0x11}), frame8(0x85, {})}));
}

TEST_F(PdoParameters, TheCobIdChangesOnlyWhileThePdoIsInvalid) {
  router_.clear();
  EXPECT_EQ(write(pdos_, 0x1400, 1, 0x206, 4), AbortCode::kInvalidValue);
  invalidate(0x1400, 0x205);
  EXPECT_FALSE(pdos_.rpdo(0).valid());
  EXPECT_TRUE(router_.stale());  // the node rebuilds its routes
  EXPECT_EQ(write(pdos_, 0x1400, 1, 0x80000206U, 4), AbortCode::kNone);
  validate(0x1400, 0x206);
  EXPECT_EQ(pdos_.rpdo(0).canId(), 0x206U);
  EXPECT_EQ(value(0x1400, 1), 0x206U);
}

TEST_F(PdoParameters, CobIdsWith29BitsOrARestrictedCanIdAreRefused) {
  invalidate(0x1800, 0x185);
  EXPECT_EQ(write(pdos_, 0x1800, 1, 0x20000185U, 4), AbortCode::kInvalidValue);
  EXPECT_EQ(write(pdos_, 0x1800, 1, 0x00000985U, 4), AbortCode::kInvalidValue);  // bits 11..28
  EXPECT_EQ(write(pdos_, 0x1800, 1, 0x705U, 4), AbortCode::kInvalidValue);       // error control
  EXPECT_EQ(write(pdos_, 0x1800, 1, 0x80000705U, 4), AbortCode::kNone);          // unless invalid
  EXPECT_FALSE(pdos_.tpdo(0).valid());
}

TEST_F(PdoParameters, TransmissionTypesReservedByCia301AreRefused) {
  EXPECT_EQ(write(pdos_, 0x1400, 2, 241, 1), AbortCode::kInvalidValue);
  EXPECT_EQ(write(pdos_, 0x1400, 2, 252, 1), AbortCode::kInvalidValue);  // RTR-only: TPDOs
  EXPECT_EQ(write(pdos_, 0x1400, 2, 254, 1), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1800, 2, 251, 1), AbortCode::kInvalidValue);
  EXPECT_EQ(write(pdos_, 0x1800, 2, 252, 1), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1800, 2, 240, 1), AbortCode::kNone);
  EXPECT_EQ(pdos_.tpdo(0).transmissionType(), 240U);
}

TEST_F(PdoParameters, ATpdosInhibitTimeAndSyncStartChangeOnlyWhileItIsInvalid) {
  EXPECT_EQ(write(pdos_, 0x1800, 3, 10, 2), AbortCode::kInvalidValue);
  EXPECT_EQ(write(pdos_, 0x1800, 6, 2, 1), AbortCode::kInvalidValue);
  EXPECT_EQ(write(pdos_, 0x1400, 3, 10, 2), AbortCode::kNone);  // an RPDO ignores its own
  invalidate(0x1800, 0x185);
  EXPECT_EQ(write(pdos_, 0x1800, 3, 10, 2), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1800, 6, 2, 1), AbortCode::kNone);
}

TEST_F(PdoParameters, TheMappingChangesOnlyWhileThePdoIsInvalidAndDisabled) {
  EXPECT_EQ(write(pdos_, 0x1600, 0, 1, 1), AbortCode::kCannotStoreState);
  invalidate(0x1400, 0x205);
  EXPECT_EQ(write(pdos_, 0x1600, 1, 0x20020008U, 4), AbortCode::kCannotStoreState);
  EXPECT_EQ(write(pdos_, 0x1600, 0, 0, 1), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1600, 1, 0x20020008U, 4), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1600, 0, 1, 1), AbortCode::kNone);
  validate(0x1400, 0x205);
  EXPECT_EQ(pdos_.rpdo(0).mappedBytes(), 1U);
}

TEST_F(PdoParameters, MappingEntriesMustNameAWholeMappableEntry) {
  invalidate(0x1400, 0x205);
  EXPECT_EQ(write(pdos_, 0x1600, 0, 0, 1), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1600, 1, 0x20070008U, 4), AbortCode::kNotMappable);
  EXPECT_EQ(write(pdos_, 0x1600, 1, 0x20000110U, 4), AbortCode::kParameterIncompatible);
  EXPECT_EQ(write(pdos_, 0x1600, 1, 0x30000008U, 4), AbortCode::kNoObject);
  EXPECT_EQ(write(pdos_, 0x1600, 1, 0x20000908U, 4), AbortCode::kNoSubIndex);
  EXPECT_EQ(write(pdos_, 0x1600, 1, 0x20050020U, 4), AbortCode::kNotMappable);  // not PDO-mappable
  EXPECT_EQ(value(0x1600, 1), 0x20000108U);
}

TEST_F(PdoParameters, DummyEntriesAreRefusedWhereTheDictionaryDeclaresNone) {
  // service_objects.eds has no [DummyUsage]: no dummy entry may be mapped (the example's EDS,
  // which declares 0x0002..0x0007, maps them: transcript example/rpdo-shared-can-id-and-dummies).
  ASSERT_EQ(dictionary_.definition().dummyUsage, 0U);
  invalidate(0x1400, 0x205);
  EXPECT_EQ(write(pdos_, 0x1600, 0, 0, 1), AbortCode::kNone);
  for (const uint32_t dummy :
       {0x00020008U, 0x00030010U, 0x00040020U, 0x00050008U, 0x00060010U, 0x00070020U}) {
    EXPECT_EQ(write(pdos_, 0x1600, 1, dummy, 4), AbortCode::kNotMappable) << std::hex << dummy;
  }
  EXPECT_EQ(value(0x1600, 1), 0x20000108U);
}

TEST_F(PdoParameters, OnlyTheDummyEntriesTheDictionaryDeclaresMayBeMapped) {
  od::Definition onlyUnsigned8 = gen::service_objects::kDefinition;
  onlyUnsigned8.dummyUsage = 1U << 0x0005U;  // [DummyUsage] Dummy0005=1, the others 0
  const od::ObjectDictionary dictionary(onlyUnsigned8, &od_.values);
  EXPECT_EQ(PdoMap::checkEntry(dictionary, 0x00050008U, PdoDirection::kReceive), AbortCode::kNone);
  EXPECT_EQ(PdoMap::checkEntry(dictionary, 0x00050010U, PdoDirection::kReceive),
            AbortCode::kParameterIncompatible);
  EXPECT_EQ(PdoMap::checkEntry(dictionary, 0x00050008U, PdoDirection::kTransmit),
            AbortCode::kNotMappable);
  for (const uint32_t other : {0x00020008U, 0x00030010U, 0x00040020U, 0x00060010U, 0x00070020U}) {
    EXPECT_EQ(PdoMap::checkEntry(dictionary, other, PdoDirection::kReceive),
              AbortCode::kNotMappable)
        << std::hex << other;
  }
}

TEST_F(PdoParameters, TheNumberOfEntriesMustFitAndMapSomething) {
  invalidate(0x1400, 0x205);
  EXPECT_EQ(write(pdos_, 0x1600, 0, 0, 1), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1600, 0, 5, 1), AbortCode::kMappingTooLong);     // 4 entries exist
  EXPECT_EQ(write(pdos_, 0x1600, 0, 0xFF, 1), AbortCode::kMappingTooLong);  // the most a byte holds
  EXPECT_EQ(write(pdos_, 0x1600, 0, 3, 1), AbortCode::kParameterIncompatible);  // entry 3 is 0
  invalidate(0x1800, 0x185);
  EXPECT_EQ(write(pdos_, 0x1A00, 0, 0, 1), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1A00, 3, 0x20010220U, 4), AbortCode::kNone);
  EXPECT_EQ(write(pdos_, 0x1A00, 0, 3, 1), AbortCode::kMappingTooLong);  // 80 bits
  EXPECT_EQ(value(0x1A00, 0), 0U);
}

}  // namespace
}  // namespace costa::test
