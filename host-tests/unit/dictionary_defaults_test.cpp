// Restoring defaults by range over a dictionary whose objects without RAM values come first,
// between others and last (data/defaults_layout.eds), with a default longer than 255 bytes
// (held in pieces), `$NODEID` defaults of 0 and of 64 bits, and a default of 0.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "costa/od/object_dictionary.hpp"
#include "defaults_layout_od.hpp"

namespace costa::od {
namespace {

std::string longText() {
  std::string text;
  for (int i = 0; i < 300; ++i) {
    text += static_cast<char>('a' + i % 26);
  }
  return text;
}

class DictionaryDefaultsTest : public ::testing::Test {
 protected:
  DictionaryDefaultsTest() : dictionary_(gen::defaults_layout::kDefinition, &values_) {
    dictionary_.setNodeId(9);
    std::memset(&values_, 0xEE, sizeof(values_));  // every byte: not a default
  }
  gen::defaults_layout::Values values_{};
  ObjectDictionary dictionary_;
};

TEST_F(DictionaryDefaultsTest, TheWholeRangeGetsEveryDefault) {
  dictionary_.restoreDefaults(0x0000, 0xFFFF);
  EXPECT_EQ(std::string(values_.x2000_long_text), longText());
  EXPECT_EQ(values_.x2002_node_id_copy, 9U);  // $NODEID+0
  EXPECT_EQ(values_.x2003_plain, 5U);
  EXPECT_EQ(values_.x2004_wide_node_id, 0x100000008U);  // $NODEID+0xFFFFFFFF: a carry
  EXPECT_EQ(values_.x2005_zero, 0U);                    // no record: zeroed
  EXPECT_EQ(dictionary_.readUnsigned(0x2001, 0, 0), 0x1234U);
  EXPECT_EQ(dictionary_.readUnsigned(0x2100, 0, 0), 0x55AAU);
}

TEST_F(DictionaryDefaultsTest, ARangeRestoresItsObjectsAndNothingElse) {
  dictionary_.restoreDefaults(0x2000, 0x2000);  // a string of two pieces, its terminator
  EXPECT_EQ(std::string(values_.x2000_long_text), longText());
  EXPECT_EQ(values_.x2002_node_id_copy, 0xEEEEU);
  EXPECT_EQ(values_.x2003_plain, 0xEEU);
  dictionary_.restoreDefaults(0x2001, 0x2001);  // a constant only: no RAM bytes
  EXPECT_EQ(values_.x2002_node_id_copy, 0xEEEEU);
  dictionary_.restoreDefaults(0x2001, 0x2002);  // from a constant on: the object after it
  EXPECT_EQ(values_.x2002_node_id_copy, 9U);
  EXPECT_EQ(values_.x2003_plain, 0xEEU);
  dictionary_.restoreDefaults(0x2003, 0x2004);
  EXPECT_EQ(values_.x2003_plain, 5U);
  EXPECT_EQ(values_.x2004_wide_node_id, 0x100000008U);
  EXPECT_EQ(values_.x2005_zero, 0xEEEEEEEEU);
  dictionary_.restoreDefaults(0x2005, 0x20FF);  // up to the constant after the last values
  EXPECT_EQ(values_.x2005_zero, 0U);
}

TEST_F(DictionaryDefaultsTest, RangesOfConstantsOrOfNoObjectsRestoreNothing) {
  dictionary_.restoreDefaults(0x1000, 0x1FFF);
  dictionary_.restoreDefaults(0x2100, 0xFFFF);
  dictionary_.restoreDefaults(0x3000, 0x3FFF);
  dictionary_.restoreDefaults(0x2006, 0x20FF);
  dictionary_.restoreDefaults(0x2003, 0x2002);  // an empty range
  const auto* bytes = reinterpret_cast<const uint8_t*>(&values_);
  for (size_t i = 0; i < sizeof(values_); ++i) {
    EXPECT_EQ(bytes[i], 0xEEU) << i;
  }
}

TEST_F(DictionaryDefaultsTest, OneEntryAndItsDefaultWithoutTheNodeId) {
  const EntryRef text = dictionary_.find(0x2000, 0);
  dictionary_.restoreDefault(text);
  EXPECT_EQ(std::string(values_.x2000_long_text), longText());
  uint8_t copy[301];
  std::memset(copy, 0xEE, sizeof(copy));
  copyDefault(gen::defaults_layout::kDefinition, text, copy);
  EXPECT_EQ(0, std::memcmp(copy, longText().c_str(), sizeof(copy)));  // with its terminator
  uint8_t id[2] = {0xEE, 0xEE};
  copyDefault(gen::defaults_layout::kDefinition, dictionary_.find(0x2002, 0), id);
  EXPECT_EQ(id[0], 0U);  // held without the node-id
  EXPECT_EQ(id[1], 0U);
  dictionary_.restoreDefault(dictionary_.find(0x2002, 0));
  EXPECT_EQ(values_.x2002_node_id_copy, 9U);
  EXPECT_EQ(values_.x2003_plain, 0xEEU);
  uint64_t wide = 0;
  copyDefault(gen::defaults_layout::kDefinition, dictionary_.find(0x2004, 0),
              reinterpret_cast<uint8_t*>(&wide));
  EXPECT_EQ(wide, 0xFFFFFFFFU);
}

// The layout rule restoring by range relies on, which the generator checks of its tables: the
// values in index order, each object's between its base and the next object's.
constexpr SubEntry kLayoutRows[] = {
    {0, 1, DataType::kUnsigned8, kReadable | kWritable, 1, kGroupNone, 0, 0},
    {0, 1, DataType::kUnsigned8, kReadable | kInRom, 1, kGroupNone, 0, 0},
};
constexpr Object kInOrder[] = {{0x2000, ObjectCode::kVar, 1, 1, 0},  // a constant: next base
                               {0x2001, ObjectCode::kVar, 1, 0, 0},
                               {0x2002, ObjectCode::kVar, 1, 0, 1}};
constexpr Object kBasesDown[] = {{0x2000, ObjectCode::kVar, 1, 1, 4},  // beyond the next one's
                                 {0x2001, ObjectCode::kVar, 1, 0, 0}};
constexpr Object kOverlapping[] = {{0x2000, ObjectCode::kVar, 1, 0, 1},
                                   {0x2001, ObjectCode::kVar, 1, 0, 1}};
constexpr Object kValuesDown[] = {{0x2000, ObjectCode::kVar, 1, 0, 1},
                                  {0x2001, ObjectCode::kVar, 1, 0, 0}};
static_assert(ramInIndexOrder(kInOrder, kLayoutRows));
static_assert(!ramInIndexOrder(kBasesDown, kLayoutRows));
static_assert(!ramInIndexOrder(kOverlapping, kLayoutRows));
static_assert(!ramInIndexOrder(kValuesDown, kLayoutRows));

TEST(DictionaryLayoutTest, RestoringARangeOfATableOutOfOrderWritesNothingOutsideTheBlock) {
  // A table made by hand that breaks the rule (the base of 0x2001 below that of 0x2000).
  const Definition definition{kValuesDown, 2,       kLayoutRows, nullptr, nullptr, nullptr, 0, 2,
                              0,           "order", nullptr,     nullptr, nullptr, 0,       0};
  uint8_t values[2] = {0xEE, 0xEE};
  ObjectDictionary dictionary(definition, values);
  dictionary.restoreDefaults(0x2000, 0x2000);  // from base 1 to base 0: nothing
  EXPECT_EQ(values[0], 0xEEU);
  EXPECT_EQ(values[1], 0xEEU);
}

}  // namespace
}  // namespace costa::od
