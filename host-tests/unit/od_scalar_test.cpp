// A Scalar (an entry resolved once) reads and stores exactly what its EntryRef does, for every
// entry of the example dictionary: each type, ROM and RAM, `$NODEID` constants.
#include <gtest/gtest.h>

#include <cstring>

#include "costa/od/object_dictionary.hpp"
#include "example_od.hpp"

namespace costa::od {
namespace {

class ScalarTest : public ::testing::Test {
 protected:
  ScalarTest()
      : byRef_(gen::example::kDefinition, &refValues_),
        byScalar_(gen::example::kDefinition, &scalarValues_) {
    for (ObjectDictionary* dictionary : {&byRef_, &byScalar_}) {
      dictionary->setNodeId(5);
      dictionary->restoreDefaults(0x0000, 0xFFFF);
    }
  }
  gen::example::Values refValues_{};
  gen::example::Values scalarValues_{};
  ObjectDictionary byRef_;
  ObjectDictionary byScalar_;
};

TEST_F(ScalarTest, ReadsAsItsEntryForEveryEntryAndNodeId) {
  size_t integers = 0;
  for (const EntryRef& ref : Entries(gen::example::kDefinition)) {
    const Scalar scalar = byRef_.scalar(ref);
    ASSERT_TRUE(scalar.valid());
    for (const uint8_t nodeId : {uint8_t{5}, uint8_t{0x7F}}) {
      byRef_.setNodeId(nodeId);  // a `$NODEID` constant follows the node-id of the read
      EXPECT_EQ(byRef_.readUnsigned(scalar), byRef_.readUnsigned(ref))
          << std::hex << ref.index() << ":" << unsigned{ref.subIndex()};
      // The out-of-line path, which a build for size takes for every read.
      EXPECT_EQ(byRef_.readScalar(scalar), byRef_.readUnsigned(ref))
          << std::hex << ref.index() << ":" << unsigned{ref.subIndex()};
    }
    byRef_.setNodeId(5);
    integers += isSigned(ref.type()) || isUnsigned(ref.type()) ? 1U : 0U;
  }
  EXPECT_GT(integers, 50U);
}

TEST_F(ScalarTest, StoresAsItsEntryForEveryEntry) {
  // Negative, wide and single-bit values, into every entry, by the inline path and by the
  // out-of-line one (that of a build for size): the blocks stay equal.
  for (uint64_t value : {0xFFFFFFFFFFFFFF85ULL, 0x0123456789ABCDEFULL, 1ULL}) {
    for (const bool outOfLine : {false, true}) {
      for (const EntryRef& ref : Entries(gen::example::kDefinition)) {
        byRef_.storeUnsigned(ref, value ^ (outOfLine ? 0x10U : 0U));
        const Scalar scalar = byScalar_.scalar(ref);
        if (outOfLine) {
          byScalar_.storeScalar(scalar, value ^ 0x10U);
        } else {
          byScalar_.storeUnsigned(scalar, value);
        }
        ASSERT_EQ(std::memcmp(&refValues_, &scalarValues_, sizeof(refValues_)), 0)
            << std::hex << ref.index() << ":" << unsigned{ref.subIndex()} << " " << outOfLine;
        EXPECT_EQ(byScalar_.readUnsigned(scalar), byRef_.readUnsigned(ref));
      }
    }
  }
}

TEST_F(ScalarTest, SignedValuesAreSignExtendedAndConstantsStayConstant) {
  // 0x1200:01 is the `$NODEID` constant 0x600 + node-id: ROM, read with the node-id.
  const Scalar constant = byRef_.scalar(byRef_.find(0x1200, 1));
  EXPECT_EQ(byRef_.readUnsigned(constant), 0x605U);
  byRef_.storeUnsigned(constant, 0x123);
  EXPECT_EQ(byRef_.readUnsigned(constant), 0x605U);
  for (const EntryRef& ref : Entries(gen::example::kDefinition)) {
    if (isSigned(ref.type()) && byRef_.ramAddress(ref) != nullptr) {
      const Scalar scalar = byRef_.scalar(ref);
      byRef_.storeUnsigned(scalar, static_cast<uint64_t>(-2));
      EXPECT_EQ(static_cast<int64_t>(byRef_.readUnsigned(scalar)), -2)
          << std::hex << ref.index() << ":" << unsigned{ref.subIndex()};
    }
  }
}

TEST_F(ScalarTest, AnAbsentEntryIsNotValidStoresNothingAndAStringReadsAsZero) {
  const Scalar absent = byScalar_.scalar(byScalar_.find(0x1017, 7));
  EXPECT_FALSE(absent.valid());
  EXPECT_FALSE(byRef_.scalar(byRef_.find(0x5FFF, 0)).valid());
  byScalar_.storeUnsigned(absent, 0xA5A5A5A5A5A5A5A5ULL);
  byScalar_.storeScalar(absent, 0xA5A5A5A5A5A5A5A5ULL);
  EXPECT_EQ(std::memcmp(&refValues_, &scalarValues_, sizeof(refValues_)), 0);
  const Scalar name = byRef_.scalar(byRef_.find(0x1008, 0));
  ASSERT_TRUE(name.valid());
  EXPECT_EQ(byRef_.readUnsigned(name), 0U);
}

}  // namespace
}  // namespace costa::od

namespace costa::od {
namespace {

// readUnsigned32() of (index, sub-index), which the stack's services read their objects with, is
// the low half of what the out-of-line read of a Scalar (loadNative(), signExtend()) gives, and
// readUnsigned() too: for every entry of the example, values with the sign bit of each size set,
// wide values, both node-ids of a `$NODEID` constant; a missing entry gives the fallback, a
// string 0.
TEST_F(ScalarTest, ReadUnsigned32IsTheLowHalfOfTheScalarReadForEveryEntry) {
  size_t signedEntries = 0;
  for (uint64_t value : {0x0ULL, 0x80ULL, 0xFFULL, 0x8000ULL, 0xFFFEULL, 0x80000000ULL,
                         0xFFFFFFFFFFFFFF85ULL, 0x0123456789ABCDEFULL}) {
    for (const EntryRef& ref : Entries(gen::example::kDefinition)) {
      byRef_.storeUnsigned(ref, value);
      for (const uint8_t nodeId : {uint8_t{5}, uint8_t{0x7F}}) {
        byRef_.setNodeId(nodeId);
        const bool integer = isSigned(ref.type()) || isUnsigned(ref.type());
        const auto expected =
            integer ? static_cast<uint32_t>(byRef_.readScalar(byRef_.scalar(ref))) : 0U;
        EXPECT_EQ(byRef_.readUnsigned32(ref.index(), ref.subIndex(), 0xDEADBEEFU), expected)
            << std::hex << ref.index() << ":" << unsigned{ref.subIndex()} << " " << value;
        EXPECT_EQ(static_cast<uint32_t>(byRef_.readUnsigned(ref)), expected)
            << std::hex << ref.index() << ":" << unsigned{ref.subIndex()} << " " << value;
      }
      signedEntries += isSigned(ref.type()) ? 1U : 0U;
    }
  }
  EXPECT_GT(signedEntries, 0U);
  EXPECT_EQ(byRef_.readUnsigned32(0x5FFF, 0, 0xDEADBEEFU), 0xDEADBEEFU);
  EXPECT_EQ(byRef_.readUnsigned32(0x1008, 0, 0xDEADBEEFU), 0U);
}

// A `$NODEID` constant read with the node-id stays within its type's width, as its SDO upload
// does: 0xF0 + 0x20 in an UNSIGNED8 is 0x10, by every read.
TEST(NodeIdConstant, WrapsWithinItsWidthOnEveryRead) {
  static constexpr uint8_t kConstants[1] = {0xF0};
  static constexpr SubEntry kRows[1] = {
      {0, 1, DataType::kUnsigned8, kReadable | kInRom | kNodeIdRelative, 1, kGroupNone, 0, 0}};
  static constexpr Object kObjects[1] = {{0x2000, ObjectCode::kVar, 1, 0, 0}};
  const Definition definition{kObjects, 1,      kRows,   kConstants, nullptr, nullptr, 0, 1,
                              0,        "wrap", nullptr, nullptr,    nullptr, 0,       0};
  uint8_t values[1] = {};
  ObjectDictionary dictionary(definition, values);
  dictionary.setNodeId(0x20);
  const EntryRef ref = dictionary.find(0x2000, 0);
  ASSERT_TRUE(ref.valid());
  EXPECT_EQ(dictionary.readUnsigned(ref), 0x10U);
  EXPECT_EQ(dictionary.readScalar(dictionary.scalar(ref)), 0x10U);
  EXPECT_EQ(dictionary.readUnsigned32(0x2000, 0, 0xDEADBEEFU), 0x10U);
  uint8_t wire[1] = {};
  EXPECT_EQ(dictionary.read(ref, 0, wire, sizeof(wire)), 1U);
  EXPECT_EQ(wire[0], 0x10U);
}

// storeUnsigned32() stores what the out-of-line store of a Scalar (storeNative() of the value,
// zero-extended) does into every integer in RAM (an entry of 8 bytes gets a zero high half over
// the ones before), and nothing into any other entry or a missing one.
TEST_F(ScalarTest, StoreUnsigned32StoresTheValueZeroExtendedIntoEveryInteger) {
  size_t wide = 0;
  for (const uint32_t value : {0x0U, 0x85U, 0xFFFEU, 0x80000000U, 0xFEDCBA98U}) {
    for (const EntryRef& ref : Entries(gen::example::kDefinition)) {
      const bool integer = isSigned(ref.type()) || isUnsigned(ref.type());
      for (ObjectDictionary* dictionary : {&byRef_, &byScalar_}) {
        dictionary->storeScalar(dictionary->scalar(ref), ~uint64_t{0});
      }
      if (integer) {
        byRef_.storeScalar(byRef_.scalar(ref), uint64_t{value});
      }
      EXPECT_TRUE(byScalar_.storeUnsigned32(ref.index(), ref.subIndex(), value));
      ASSERT_EQ(std::memcmp(&refValues_, &scalarValues_, sizeof(refValues_)), 0)
          << std::hex << ref.index() << ":" << unsigned{ref.subIndex()} << " " << value;
      if (integer) {
        byRef_.storeScalar(byRef_.scalar(ref), uint64_t{value ^ 1U});
      }
      byScalar_.storeUnsigned32(ref, value ^ 1U);
      ASSERT_EQ(std::memcmp(&refValues_, &scalarValues_, sizeof(refValues_)), 0)
          << std::hex << ref.index() << ":" << unsigned{ref.subIndex()} << " " << value;
      wide += integer && ref.size() == 8U ? 1U : 0U;
    }
  }
  EXPECT_GT(wide, 0U);
  EXPECT_FALSE(byScalar_.storeUnsigned32(0x5FFF, 0, 1));
  EXPECT_EQ(std::memcmp(&refValues_, &scalarValues_, sizeof(refValues_)), 0);
}

}  // namespace
}  // namespace costa::od
