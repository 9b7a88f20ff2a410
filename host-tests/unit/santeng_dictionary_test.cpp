// The generated Santeng dictionary (targets/santeng/santeng.eds) against tables 3, 4 and 5 of
// the manual (shared/manuals/santeng-motor-controller-canopen.txt, lines 426-493): every
// runtime command and query with its channel sub-indices and sub-index 0, type, access, PDO
// mapping, storage group, the ranges the descriptions give and the defaults; and no other
// object between 0x2000 and 0x21FF but the user variables (docs/errata-santeng.md D11).
#include <gtest/gtest.h>

#include <set>

#include "costa/od/object_dictionary.hpp"
#include "santeng_od.hpp"

namespace costa::od {
namespace {

constexpr int64_t kNoLimit = INT64_MIN;
constexpr DataType S8 = DataType::kInteger8;
constexpr DataType S16 = DataType::kInteger16;
constexpr DataType S32 = DataType::kInteger32;
constexpr DataType U8 = DataType::kUnsigned8;
constexpr DataType U16 = DataType::kUnsigned16;
constexpr DataType U32 = DataType::kUnsigned32;

struct Row {
  uint16_t index;
  uint8_t subs;  // 0: a VAR at sub-index 0; n: sub-indices 1..n and sub-index 0 = n
  DataType type;
  bool writeOnly;  // WO (a command: RPDO-mappable) or RO (a query: TPDO-mappable)
  int64_t low;     // kNoLimit: none
  int64_t high;
  int64_t value;  // default
  int line;
};

// clang-format off
const Row kManual[] = {
  {0x2000, 2, S16, true,  -1000, 1000, 0, 429},    // D21
  {0x200C, 0, U8,  true,  kNoLimit, 0, 0, 431},
  {0x200D, 0, U8,  true,  kNoLimit, 0, 0, 432},
  {0x200E, 2, U8,  true,  kNoLimit, 0, 0, 433},    // D1
  {0x2017, 0, U8,  true,  kNoLimit, 0, 0, 434},    // D8
  {0x2001, 2, S32, true,  kNoLimit, 0, 0, 441},    // D5
  {0x2002, 2, S16, true,  kNoLimit, 0, 0, 443},    // D4
  {0x2003, 2, S32, true,  kNoLimit, 0, 0, 445},    // D9
  {0x2006, 2, S32, true,  0, 500000, 10000, 447},  // D7, B2
  {0x2007, 2, S32, true,  0, 500000, 10000, 449},  // D7, B2
  {0x2100, 2, S16, false, kNoLimit, 0, 0, 455},
  {0x2101, 2, S16, false, kNoLimit, 0, 0, 458},
  {0x2103, 2, S16, false, kNoLimit, 0, 0, 460},
  {0x2104, 2, S32, false, kNoLimit, 0, 0, 463},
  {0x2105, 2, S32, false, kNoLimit, 0, 0, 465},
  {0x2107, 2, S16, false, kNoLimit, 0, 0, 468},
  {0x2108, 2, S32, false, kNoLimit, 0, 0, 471},
  {0x2109, 2, S32, false, kNoLimit, 0, 0, 473},
  {0x210A, 2, S16, false, kNoLimit, 0, 0, 476},
  {0x210C, 2, S16, false, kNoLimit, 0, 0, 478},
  {0x210D, 3, U16, false, kNoLimit, 0, 0, 481},    // D6
  {0x210E, 0, U32, false, kNoLimit, 0, 0, 484},
  {0x210F, 3, S8,  false, kNoLimit, 0, 0, 485},    // D15
  {0x2111, 0, U8,  false, kNoLimit, 0, 0, 488},
  {0x2112, 0, U8,  false, kNoLimit, 0, 0, 489},
  {0x2113, 0, U8,  false, kNoLimit, 0, 0, 491},
  {0x2119, 0, U32, false, kNoLimit, 0, 0, 492},
  {0x2121, 2, U8,  false, kNoLimit, 0, 0, 493},    // D3
  {0x2005, 16, S32, true,  kNoLimit, 0, 0, 186},   // D11: user variables
  {0x2106, 16, S32, false, kNoLimit, 0, 0, 180},   // D11
};
// clang-format on

class SantengDictionary : public ::testing::Test {
 protected:
  SantengDictionary() : dictionary_(gen::santeng::kDefinition, &values_) {
    dictionary_.setNodeId(1);
    dictionary_.restoreDefaults(0x0000, 0xFFFF);
  }
  void expectEntry(const Row& row, uint8_t sub) {
    SCOPED_TRACE(testing::Message() << std::hex << "0x" << row.index << "." << int{sub} << std::dec
                                    << " (manual line " << row.line << ")");
    const EntryRef ref = dictionary_.find(row.index, sub);
    ASSERT_TRUE(ref.valid());
    EXPECT_EQ(ref.type(), row.type);
    const uint16_t access =
        row.writeOnly ? (kWritable | kRpdoMappable) : (kReadable | kTpdoMappable);
    const bool save = row.index == 0x2017;  // a command, but no PDO's (D8)
    // (kPlainInteger: the generator's mark of an integer without limits, below)
    EXPECT_EQ(ref.attributes() & ~(kHasLimits | kPlainInteger),
              save ? static_cast<uint16_t>(kWritable) : access);
    EXPECT_EQ(ref.group(), kGroupNone);  // nothing of the commands and queries is stored
    const int64_t value = isSigned(ref.type())
                              ? dictionary_.readSigned(ref)
                              : static_cast<int64_t>(dictionary_.readUnsigned(ref));
    EXPECT_EQ(value, row.value);
    if (row.low == kNoLimit) {
      EXPECT_EQ(ref.attributes() & kHasLimits, 0U);
      EXPECT_NE(ref.attributes() & kPlainInteger, 0U);
      return;
    }
    EXPECT_EQ(ref.attributes() & kPlainInteger, 0U);
    ASSERT_NE(ref.row->limits, 0U);
    const Limits& limits = gen::santeng::kDefinition.limits[ref.row->limits - 1U];
    EXPECT_EQ(static_cast<int64_t>(limits.low), row.low);
    EXPECT_EQ(static_cast<int64_t>(limits.high), row.high);
  }
  gen::santeng::Values values_{};
  ObjectDictionary dictionary_;
};

TEST_F(SantengDictionary, EveryCommandAndQueryOfTheTables) {
  for (const Row& row : kManual) {
    if (row.subs == 0U) {
      expectEntry(row, 0);
      EXPECT_FALSE(dictionary_.find(row.index, 1).valid());
      continue;
    }
    const EntryRef count = dictionary_.find(row.index, 0);
    ASSERT_TRUE(count.valid()) << std::hex << row.index;
    EXPECT_EQ(count.type(), U8);
    EXPECT_EQ(count.attributes() & kWritable, 0U);  // D22: the highest sub-index, read only
    EXPECT_EQ(dictionary_.readUnsigned(count), row.subs);
    for (uint8_t sub = 1; sub <= row.subs; ++sub) {
      expectEntry(row, sub);
    }
    EXPECT_FALSE(dictionary_.find(row.index, static_cast<uint8_t>(row.subs + 1U)).valid());
  }
}

TEST_F(SantengDictionary, NoOtherObjectInTheRuntimeRange) {
  std::set<uint16_t> listed;
  for (const Row& row : kManual) {
    listed.insert(row.index);
  }
  for (size_t i = 0; i < gen::santeng::kDefinition.objectCount; ++i) {
    const uint16_t index = gen::santeng::kDefinition.objects[i].index;
    if (index >= 0x2000 && index <= 0x21FF) {
      EXPECT_EQ(listed.count(index), 1U) << std::hex << index;
    }
  }
  EXPECT_EQ(listed.size(), sizeof(kManual) / sizeof(kManual[0]));
}

TEST_F(SantengDictionary, TheConfigurationIsStoredInGroup4AndTheCommunicationObjectsIn1) {
  EXPECT_EQ(dictionary_.find(0x5000, 0).group(), 4U);  // D13
  EXPECT_EQ(dictionary_.find(0x5001, 1).group(), 4U);
  EXPECT_EQ(dictionary_.find(0x5003, 2).group(), 4U);
  EXPECT_EQ(dictionary_.find(0x1017, 0).group(), kGroupCommunication);
  EXPECT_EQ(dictionary_.find(0x1800, 5).group(), kGroupCommunication);
  EXPECT_EQ(dictionary_.find(0x1A03, 2).group(), kGroupCommunication);
  EXPECT_EQ(dictionary_.readUnsigned(dictionary_.find(0x1014, 0)), 0x80000081U);  // W9
  EXPECT_EQ(dictionary_.readUnsigned(dictionary_.find(0x1017, 0)), 1000U);        // W6
  EXPECT_EQ(dictionary_.readUnsigned(dictionary_.find(0x1800, 5)), 1500U);        // W10
}

}  // namespace
}  // namespace costa::od
