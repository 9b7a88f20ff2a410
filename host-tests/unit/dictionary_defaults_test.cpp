// Restoring defaults by range over a dictionary whose objects without RAM values come first,
// between others and last (data/defaults_layout.eds), with a default longer than 255 bytes
// (held in pieces) and a `$NODEID` default of 0.
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
  dictionary_.restoreDefaults(0x2003, 0x20FF);  // up to the constant after the last values
  EXPECT_EQ(values_.x2003_plain, 5U);
}

TEST_F(DictionaryDefaultsTest, RangesOfConstantsOrOfNoObjectsRestoreNothing) {
  dictionary_.restoreDefaults(0x1000, 0x1FFF);
  dictionary_.restoreDefaults(0x2100, 0xFFFF);
  dictionary_.restoreDefaults(0x3000, 0x3FFF);
  dictionary_.restoreDefaults(0x2004, 0x20FF);
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
}

}  // namespace
}  // namespace costa::od
