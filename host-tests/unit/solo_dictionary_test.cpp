// The generated SOLO dictionary (targets/solo/solo.eds) against a table written from the SOLO
// CANopen manual (shared/manuals/solo-motor-controller-canopen.txt): every object, its type,
// access, PDO mapping, storage group, limits and default. Sfxt(32-17) figures are raw values
// (x * 2^17, nearest step). Departures from the printed tables are explained in
// docs/errata-solo.md (the ids in the comments).
#include <gtest/gtest.h>

#include <iterator>
#include <set>
#include <utility>
#include <vector>

#include "costa/od/object_dictionary.hpp"
#include "solo_od.hpp"

namespace costa::od {
namespace {

enum class Access { kRo, kWo, kRw, kConst };

constexpr int64_t kNoLimit = INT64_MIN;

struct Row {
  uint16_t index;
  uint8_t sub;
  DataType type;
  Access access;
  bool pdo;
  uint8_t group;
  int64_t low;  // kNoLimit: no limits
  int64_t high;
  int64_t value;  // default
  int line;       // manual line of the object's data row
};

constexpr DataType U8 = DataType::kUnsigned8;
constexpr DataType U32 = DataType::kUnsigned32;
constexpr DataType I32 = DataType::kInteger32;  // INT32 and Sfxt(32-17)
constexpr Access R = Access::kRo;
constexpr Access W = Access::kWo;
constexpr Access RW = Access::kRw;
constexpr uint8_t kV = kGroupNone;
constexpr uint8_t kM = kGroupApplication;
constexpr int64_t NL = kNoLimit;

// clang-format off
const Row kManual[] = {
  // index  sub type acc pdo    group  low          high         default  line
  {0x1001, 0, U32, R,  false, kV, NL, NL, 0, 624},   // D1: Uint32, read-only
  {0x100C, 0, U32, RW, false, kV, 0, 65535, 0, 642},  // D2: Uint32 [0-65535]
  {0x100D, 0, U32, RW, false, kV, 0, 255, 0, 649},    // D2: Uint32 [0-255]
  {0x1017, 0, U32, RW, false, kV, 0, 65535, 0, 656},  // D2
  {0x3001, 0, U32, RW, false, kM, 1, 127, 1, 861},   // D6: [1-254] -> node-ids 1..127
  {0x3002, 0, U32, RW, false, kM, 0, 2, 0, 870},
  {0x3003, 0, I32, RW, false, kM, 0, 4194304, 4194304, 881},  // [0, 32 A] (D7), 32 A
  {0x3004, 0, I32, RW, true,  kV, 0, 4194304, 0, 892},        // [0, 32 A] (D7)
  {0x3005, 0, U32, RW, true,  kV, 0, 30000, 0, 910},
  {0x3006, 0, I32, RW, false, kV, 0, 13107200, 0, 936},       // [0, 100.0]
  {0x3007, 0, U32, W,  false, kV, 0, 1, 0, 943},
  {0x3008, 0, U32, RW, false, kV, 0, 1, 1, 952},
  {0x3009, 0, U32, RW, false, kM, 8000, 80000, 20000, 962},  // D8: held in Hz
  {0x300A, 0, I32, RW, false, kM, 0, 39321600, 0, 971},       // [0, 300.0]
  {0x300B, 0, I32, RW, false, kM, 0, 39321600, 0, 978},
  {0x300C, 0, U32, RW, true,  kV, 0, 1, 0, 987},
  {0x300D, 0, I32, RW, false, kM, 0, 3276800, 0, 999},        // D9: [0, 25.0]
  {0x300E, 0, I32, RW, false, kM, 0, 65536, 0, 1006},         // D10: [0.0000001 -> 0, 0.5]
  {0x300F, 0, U32, RW, false, kM, 1, 254, 8, 1015},
  {0x3010, 0, U32, RW, false, kM, 1, 200000, 1000, 1022},
  {0x3011, 0, U32, RW, false, kM, 0, 30000, 30000, 1029},
  {0x3013, 0, U32, RW, false, kM, 0, 3, 0, 1040},
  {0x3014, 0, U32, RW, false, kV, 0, 1, 0, 1052},             // D11
  {0x3015, 0, U32, RW, false, kM, 0, 3, 0, 1061},
  {0x3016, 0, U32, RW, true,  kM, 0, 2, 1, 1075},
  {0x3017, 0, I32, RW, false, kM, 0, 2097152000, 0, 1086},    // [0, 16000.0]
  {0x3018, 0, I32, RW, false, kM, 0, 2097152000, 0, 1095},
  {0x301A, 0, I32, RW, true,  kV, 0, 4194304, 0, 1102},       // [0, 32 A] (D7)
  {0x301B, 0, I32, RW, true,  kV, -2147483647, 2147483647, 0, 1111},  // A9
  {0x301C, 0, I32, RW, false, kM, 0, 2097152000, 0, 1127},
  {0x301D, 0, I32, RW, false, kM, 0, 2097152000, 0, 1139},
  {0x301F, 0, U32, W,  false, kV, 0, 1, 0, 1146},             // D11
  {0x3020, 0, U32, RW, true,  kV, NL, NL, 0, 1155},
  {0x3021, 0, I32, RW, false, kM, 0, 72090, 19661, 1177},     // [0, 0.55], 0.15
  {0x3022, 0, I32, RW, false, kM, 0, 72090, 32768, 1184},     // [0, 0.55], 0.25
  {0x3023, 0, I32, RW, false, kM, 1311, 131072000, 6553600, 1195},  // [0.01, 1000], 50
  {0x3024, 0, U32, RW, false, kM, 0, 10, 0, 1202},
  {0x3025, 0, U32, RW, false, kM, 1, 5000, 500, 1211},
  {0x3026, 0, U32, RW, false, kM, 0, 1, 0, 1226},             // D12
  {0x3027, 0, U32, W,  false, kV, 0, 2, 0, 1238},
  {0x3028, 0, I32, RW, false, kM, 0, 131072, 0, 1249},        // [0, 1.0]
  {0x3029, 0, I32, RW, false, kM, 0, 131072, 0, 1258},
  {0x302A, 0, I32, RW, false, kM, 0, 209715200, 0, 1265},     // [0, 1600.0]
  {0x302B, 0, I32, RW, false, kM, 0, 209715200, 0, 1274},
  {0x302C, 0, U32, RW, false, kM, 0, 4, 0, 1287},             // D13
  {0x302D, 0, I32, R,  false, kV, -7864320, 7864320, 0, 1300},  // [-60, 60]
  {0x302E, 0, I32, R,  false, kV, -7864320, 7864320, 0, 1309},
  {0x302F, 0, I32, R,  false, kV, -4194304, 4194304, 0, 1316},  // [-32, 32]
  {0x3030, 0, I32, R,  false, kV, -4194304, 4194304, 0, 1323},
  {0x3031, 0, I32, R,  false, kV, 0, 7864320, 0, 1334},         // [0, 60]
  {0x3032, 0, I32, R,  false, kV, -4194304, 4194304, 0, 1341},
  {0x3033, 0, I32, R,  false, kV, -7864320, 7864320, 0, 1348},
  {0x3034, 0, I32, R,  true,  kV, -8388608, 8388608, 0, 1357},  // [-64, 64]
  {0x3035, 0, I32, R,  true,  kV, -8388608, 8388608, 0, 1364},
  {0x3036, 0, I32, R,  true,  kV, -30000, 30000, 0, 1371},
  {0x3037, 0, I32, R,  true,  kV, -2147483647, 2147483647, 0, 1380},  // A9
  {0x3038, 0, I32, R,  false, kV, -262144, 262144, 0, 1387},    // [-2, 2], D14
  {0x3039, 0, I32, R,  true,  kV, -3932160, 19660800, 0, 1394},  // [-30, 150]
  {0x303A, 0, U32, R,  false, kV, NL, NL, 0x0000B020, 1403},    // D15
  {0x303B, 0, U32, R,  false, kV, NL, NL, 0, 1410},             // D15
  {0x303C, 0, U32, RW, false, kM, 1, 10000, 1, 1419},           // D16
  {0x303D, 0, U32, R,  false, kV, 0, 2147483647, 0, 1431},      // D17
  {0x303E, 0, U32, RW, false, kM, 0, 100000, 5000, 1440},
  {0x303F, 0, U32, RW, false, kM, 0, 2, 0, 1449},
  {0x3040, 0, I32, RW, false, kM, 0, 2097152000, 0, 1473},
  {0x3041, 0, I32, RW, false, kM, 0, 2097152000, 0, 1485},
  {0x3042, 0, I32, RW, false, kM, 0, 2097152000, 0, 1501},
  {0x3043, 0, I32, RW, false, kM, 0, 2097152000, 0, 1513},
  {0x3044, 0, I32, RW, false, kM, 0, 2097152000, 0, 1527},
  {0x3047, 0, I32, R,  false, kV, 0, 432538, 0, 1539},          // [0, 3.3]
  {0x3048, 0, U32, RW, false, kV, NL, NL, 0, 1548},
  {0x3049, 0, U32, R,  false, kV, NL, NL, 0, 1562},
  {0x304A, 0, U32, R,  false, kV, 0, 4095, 0, 1576},
  {0x304B, 0, I32, RW, false, kM, 0, 4194304, 0, 1590},         // [0, 32 A] (D7)
  {0x304C, 0, U32, RW, false, kM, 1, 255, 6, 1603},             // D18
};
// clang-format on

// PDO communication parameters (lines 663-853): sub-index 0 (D4), COB-ID and transmission
// type (D3), both "M".
struct PdoRecord {
  uint16_t index;
  int line;  // line of sub-index 1's data row
};
const PdoRecord kPdoRecords[] = {{0x1414, 669}, {0x1415, 685}, {0x1416, 701}, {0x1417, 717},
                                 {0x1418, 733}, {0x1419, 749}, {0x1814, 767}, {0x1815, 783},
                                 {0x1816, 799}, {0x1817, 815}, {0x1818, 831}, {0x1819, 847}};

uint16_t expectedAttributes(Access access, bool pdo) {
  switch (access) {
    case Access::kRo: return static_cast<uint16_t>(kReadable | (pdo ? kTpdoMappable : 0));
    case Access::kWo: return static_cast<uint16_t>(kWritable | (pdo ? kRpdoMappable : 0));
    case Access::kRw:
      return static_cast<uint16_t>(kReadable | kWritable |
                                   (pdo ? kRpdoMappable | kTpdoMappable : 0));
    case Access::kConst: return static_cast<uint16_t>(kReadable | kInRom);
  }
  return 0;
}

std::vector<Row> allRows() {
  std::vector<Row> rows(std::begin(kManual), std::end(kManual));
  for (const PdoRecord& pdo : kPdoRecords) {
    rows.push_back({pdo.index, 0, U8, Access::kConst, false, kGroupNone, NL, NL, 2, pdo.line});
    rows.push_back({pdo.index, 1, U32, RW, false, kGroupCommunication, NL, NL, 0, pdo.line});
    rows.push_back({pdo.index, 2, U32, RW, false, kGroupCommunication, 0, 255, 0, pdo.line + 5});
  }
  return rows;
}

// Little-endian wire bytes of `value` in `size` bytes (two's complement for negatives).
std::vector<uint8_t> wire(int64_t value, size_t size) {
  std::vector<uint8_t> bytes(size);
  for (size_t i = 0; i < size; ++i) {
    bytes[i] = static_cast<uint8_t>(static_cast<uint64_t>(value) >> (8U * i));
  }
  return bytes;
}

class SoloDictionaryTest : public ::testing::Test {
 protected:
  SoloDictionaryTest() : dictionary_(gen::solo::kDefinition, &values_) {
    dictionary_.setNodeId(1);
    dictionary_.restoreDefaults(0x0000, 0xFFFF);
  }
  int64_t value(const EntryRef& entry) const {
    return isSigned(entry.type()) ? dictionary_.readSigned(entry)
                                  : static_cast<int64_t>(dictionary_.readUnsigned(entry));
  }
  gen::solo::Values values_{};
  ObjectDictionary dictionary_;
};

TEST_F(SoloDictionaryTest, EveryEntryOfTheManualHasItsTypeAccessLimitsAndDefault) {
  for (const Row& row : allRows()) {
    SCOPED_TRACE(testing::Message() << std::hex << "0x" << row.index << "." << int{row.sub}
                                    << std::dec << " (manual line " << row.line << ")");
    const EntryRef ref = dictionary_.find(row.index, row.sub);
    ASSERT_TRUE(ref.valid());
    EXPECT_EQ(ref.type(), row.type);
    // (kPlainInteger: the generator's mark of an integer without limits)
    EXPECT_EQ(ref.attributes() & ~(kHasLimits | kPlainInteger),
              expectedAttributes(row.access, row.pdo));
    EXPECT_EQ(ref.group(), row.group);
    EXPECT_EQ(value(ref), row.value);
    if (row.low == kNoLimit) {
      EXPECT_EQ(ref.attributes() & kHasLimits, 0U);
      continue;
    }
    ASSERT_NE(ref.attributes() & kHasLimits, 0U);
    ASSERT_NE(ref.row->limits, 0U);
    const Limits& limits = gen::solo::kDefinition.limits[ref.row->limits - 1U];
    EXPECT_EQ(static_cast<int64_t>(limits.low), row.low);
    EXPECT_EQ(static_cast<int64_t>(limits.high), row.high);
  }
}

TEST_F(SoloDictionaryTest, HoldsNothingTheManualDoesNotList) {
  std::set<std::pair<uint16_t, uint8_t>> expected;
  for (const Row& row : allRows()) {
    EXPECT_TRUE(expected.insert({row.index, row.sub}).second) << std::hex << row.index;
  }
  std::set<std::pair<uint16_t, uint8_t>> actual;
  const Definition& definition = gen::solo::kDefinition;
  for (const EntryRef& ref : Entries(definition)) {
    actual.insert({ref.index(), ref.subIndex()});
  }
  EXPECT_EQ(actual, expected);
  EXPECT_EQ(definition.objectCount, 87U);  // 4 + 12 communication, 71 manufacturer objects
  EXPECT_FALSE(dictionary_.find(0x1000, 0).valid());  // not in the manual (P5)
  EXPECT_FALSE(dictionary_.find(0x1018, 0).valid());
  EXPECT_FALSE(dictionary_.find(0x1414, 3).valid());
  EXPECT_FALSE(dictionary_.find(0x3012, 0).valid());  // gaps in the manual's numbering
}

TEST_F(SoloDictionaryTest, LimitsAcceptTheirBoundsAndRejectTheNextValue) {
  for (const Row& row : allRows()) {
    if (row.low == kNoLimit) {
      continue;
    }
    SCOPED_TRACE(testing::Message() << std::hex << "0x" << row.index);
    const EntryRef entry = dictionary_.find(row.index, row.sub);
    const size_t size = entry.size();
    const int64_t typeMin = isSigned(entry.type()) ? INT32_MIN : 0;
    const int64_t typeMax = isSigned(entry.type()) ? INT32_MAX : UINT32_MAX;
    EXPECT_EQ(dictionary_.write(entry, wire(row.low, size).data(), size), AbortCode::kNone);
    EXPECT_EQ(value(entry), row.low);
    EXPECT_EQ(dictionary_.write(entry, wire(row.high, size).data(), size), AbortCode::kNone);
    EXPECT_EQ(value(entry), row.high);
    if (row.low > typeMin) {
      EXPECT_EQ(dictionary_.write(entry, wire(row.low - 1, size).data(), size),
                AbortCode::kValueTooLow);
    }
    if (row.high < typeMax) {
      EXPECT_EQ(dictionary_.write(entry, wire(row.high + 1, size).data(), size),
                AbortCode::kValueTooHigh);
    }
    EXPECT_EQ(value(entry), row.high);  // a refused write keeps the value
  }
}

TEST_F(SoloDictionaryTest, TheObjectsOfThePdoTableAreMappable) {
  // Lines 548-560: RPDO1..6 carry 0x301B, 0x3005, 0x3004, 0x301A, 0x3016, 0x300C; TPDO1..6
  // carry 0x3037, 0x3036, 0x3034, 0x3035, 0x3020, 0x3039.
  const std::set<uint16_t> rpdo = {0x301B, 0x3005, 0x3004, 0x301A, 0x3016, 0x300C};
  const std::set<uint16_t> tpdo = {0x3037, 0x3036, 0x3034, 0x3035, 0x3020, 0x3039};
  std::set<uint16_t> receivable;
  std::set<uint16_t> transmittable;
  const Definition& definition = gen::solo::kDefinition;
  for (const EntryRef& ref : Entries(definition)) {
    {
      if (ref.has(kRpdoMappable)) {
        receivable.insert(ref.index());
      }
      if (ref.has(kTpdoMappable)) {
        transmittable.insert(ref.index());
      }
    }
  }
  for (const uint16_t index : rpdo) {
    EXPECT_EQ(receivable.count(index), 1U) << std::hex << index;
  }
  for (const uint16_t index : tpdo) {
    EXPECT_EQ(transmittable.count(index), 1U) << std::hex << index;
  }
  std::set<uint16_t> mapped = rpdo;
  mapped.insert(tpdo.begin(), tpdo.end());
  receivable.insert(transmittable.begin(), transmittable.end());
  EXPECT_EQ(receivable, mapped);  // read/write references are also TPDO-mappable (rw)
  EXPECT_EQ(gen::solo::Capacity::kRpdoCount, 6U);
  EXPECT_EQ(gen::solo::Capacity::kTpdoCount, 6U);
}

TEST_F(SoloDictionaryTest, SfxtDefaultsTravelAsRawFixedPoint) {
  uint8_t bytes[4] = {};
  // 0x3003 Current Limit, default 32 A = 0x00400000.
  ASSERT_EQ(dictionary_.read(dictionary_.find(0x3003, 0), 0, bytes, 4), 4U);
  EXPECT_EQ(wire(0x00400000, 4), std::vector<uint8_t>(bytes, bytes + 4));
  // 0x3021 injection amplitude, default 0.15 = 19661 = 0x00004CCD.
  ASSERT_EQ(dictionary_.read(dictionary_.find(0x3021, 0), 0, bytes, 4), 4U);
  EXPECT_EQ(wire(0x00004CCD, 4), std::vector<uint8_t>(bytes, bytes + 4));
  // 0x3023 observer gain, default 50 = 0x00640000.
  ASSERT_EQ(dictionary_.read(dictionary_.find(0x3023, 0), 0, bytes, 4), 4U);
  EXPECT_EQ(wire(0x00640000, 4), std::vector<uint8_t>(bytes, bytes + 4));
}

}  // namespace
}  // namespace costa::od
