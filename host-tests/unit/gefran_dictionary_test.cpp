// The Gefran GRA and GRN dictionaries (targets/gefran/gra.eds, grn.eds) against a table written
// from the manual's "CANopen features summary" (shared/manuals/gefran-gra-grn-angle-sensor-
// canopen.txt, lines 452-564) and the decisions of docs/errata-gefran.md (E1...).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "costa/od/object_dictionary.hpp"
#include "gra_od.hpp"
#include "grn_od.hpp"

namespace costa::od {
namespace {

enum class Access : uint8_t { kRo, kWo, kRw, kConst };

/// One sub-entry as the manual describes it. Numeric defaults of node-id relative entries are
/// written without the node-id; limits are given only where they narrow the type's range.
struct Expected {
  uint16_t index;
  uint8_t subIndex;
  DataType type;
  Access access;
  uint64_t value;
  uint8_t group;
  const char* text;  ///< VISIBLE_STRING default; nullptr for the variant name ("GRA"/"GRN").
  bool nodeIdRelative;
  bool tpdoMappable;
  bool limited;
  uint64_t low;
  uint64_t high;

  constexpr Expected limits(uint64_t lowLimit, uint64_t highLimit) const {
    Expected e = *this;
    e.limited = true;
    e.low = lowLimit;
    e.high = highLimit;
    return e;
  }
  constexpr Expected plusNodeId() const {
    Expected e = *this;
    e.nodeIdRelative = true;
    return e;
  }
  constexpr Expected mapped() const {
    Expected e = *this;
    e.tpdoMappable = true;
    return e;
  }
};

constexpr Expected number(uint16_t index, uint8_t sub, DataType type, Access access, uint64_t value,
                          uint8_t group = kGroupNone) {
  return Expected{index, sub, type, access, value, group, "", false, false, false, 0, 0};
}

constexpr Expected text(uint16_t index, const char* value) {
  Expected e = number(index, 0, DataType::kVisibleString, Access::kConst, 0);
  e.text = value;
  return e;
}

constexpr DataType kU8 = DataType::kUnsigned8;
constexpr DataType kU16 = DataType::kUnsigned16;
constexpr DataType kU32 = DataType::kUnsigned32;
constexpr Access kRo = Access::kRo;
constexpr Access kWo = Access::kWo;
constexpr Access kRw = Access::kRw;
constexpr Access kConst = Access::kConst;
constexpr uint8_t kComm = kGroupCommunication;
constexpr uint8_t kApp = kGroupApplication;

const Expected kManual[] = {
    number(0x1000, 0, kU32, kConst, 0),                         // 460
    number(0x1001, 0, kU8, kRo, 0),                             // 461, E14
    text(0x1008, nullptr),                                      // 462
    text(0x1009, "1.00"),                                       // 463
    text(0x100A, "1.14"),                                       // 464
    number(0x1010, 0, kU8, kConst, 1),                          // 465
    number(0x1010, 1, kU32, kRw, 1),                            // 466, E19
    number(0x1011, 0, kU8, kConst, 1),                          // 467, E18
    number(0x1011, 1, kU32, kRw, 1),                            // 468, E19, E20
    number(0x1014, 0, kU32, kRw, 0x80, kComm).plusNodeId(),     // 469
    number(0x1017, 0, kU16, kRw, 0, kComm),                     // 470
    number(0x1018, 0, kU8, kConst, 4),                          // 471
    number(0x1018, 1, kU32, kConst, 0x93),                      // 472
    number(0x1018, 2, kU32, kConst, 0x64),                      // 473
    number(0x1018, 3, kU32, kConst, 1),                         // 474
    number(0x1018, 4, kU32, kRo, 0),                            // 475, E12
    number(0x1200, 0, kU8, kConst, 2),                          // 477
    number(0x1200, 1, kU32, kConst, 0x600).plusNodeId(),        // 478
    number(0x1200, 2, kU32, kConst, 0x580).plusNodeId(),        // 479
    number(0x1800, 0, kU8, kConst, 5),                          // 480, E8
    number(0x1800, 1, kU32, kConst, 0x180).plusNodeId(),        // 481
    number(0x1800, 2, kU8, kRw, 254, kComm).limits(254, 255),   // 482, E10
    number(0x1800, 3, kU16, kConst, 0),                         // 483, E7 (sub 4: E9)
    number(0x1800, 5, kU16, kRw, 100, kComm).limits(4, 65535),  // 485, E11
    number(0x1A00, 0, kU8, kConst, 8),                          // 487
    number(0x1A00, 1, kU32, kConst, 0x21100108),                // 488
    number(0x1A00, 2, kU32, kConst, 0x21100208),                // 489
    number(0x1A00, 3, kU32, kConst, 0x21100308),                // 490
    number(0x1A00, 4, kU32, kConst, 0x21100408),                // 491
    number(0x1A00, 5, kU32, kConst, 0x21100508),                // 492
    number(0x1A00, 6, kU32, kConst, 0x21100608),                // 493
    number(0x1A00, 7, kU32, kConst, 0x21100708),                // 494
    number(0x1A00, 8, kU32, kConst, 0x40010008),                // 495
    number(0x2000, 0, kU8, kConst, 2),                          // 507
    number(0x2000, 1, kU16, kRo, 0).limits(0, 16383),           // 508
    number(0x2000, 2, kU16, kRo, 0).limits(0, 16383),           // 509
    number(0x2001, 0, kU8, kConst, 2),                          // 511
    number(0x2001, 1, kU8, kRw, 0, kApp),                       // 512
    number(0x2001, 2, kU8, kRw, 0, kApp),                       // 513
    number(0x2011, 0, kU8, kConst, 3),                          // 515
    number(0x2011, 1, kU16, kRo, 0),                            // 516
    number(0x2011, 2, kU16, kRo, 0),                            // 517
    number(0x2011, 3, kU32, kRo, 0),                            // 518, E25
    number(0x2100, 0, kU8, kConst, 2),                          // 520
    number(0x2100, 1, kU16, kRw, 100, kApp).limits(22, 1000),   // 521, E26
    number(0x2100, 2, kU16, kRw, 100, kApp).limits(22, 1000),   // 522, E26
    number(0x2101, 0, kU8, kConst, 2),                          // 524
    number(0x2101, 1, kU16, kRw, 0, kApp).limits(0, 35999),     // 525, E3, E4
    number(0x2101, 2, kU16, kRw, 0, kApp).limits(0, 35999),     // 526, E3, E4
    number(0x2102, 0, kU8, kConst, 2),                          // 528
    number(0x2102, 1, kU8, kRw, 0, kApp).limits(0, 1),          // 529
    number(0x2102, 2, kU8, kRw, 1, kApp).limits(0, 1),          // 530, E27
    number(0x2103, 0, kU16, kRw, 0, kApp),                      // 531, E28
    number(0x2110, 0, kU8, kConst, 7),                          // 533, E5
    number(0x2110, 1, kU8, kRo, 0).mapped(),                    // 534
    number(0x2110, 2, kU8, kRo, 0).mapped(),                    // 535
    number(0x2110, 3, kU8, kRo, 0).mapped(),                    // 536, E6
    number(0x2110, 4, kU8, kRo, 0).mapped(),                    // 537, E6
    number(0x2110, 5, kU8, kConst, 0xFF).mapped(),              // 353, 492, E5
    number(0x2110, 6, kU8, kConst, 0xFF).mapped(),              // 353, 493, E5
    number(0x2110, 7, kU8, kConst, 0xFF).mapped(),              // 353, 494, E5
    number(0x4000, 0, kU8, kRw, 1, kApp),                       // 550, E29
    number(0x4001, 0, kU8, kRo, 0).mapped(),                    // 551, E15
    number(0x5000, 0, kU8, kRw, 1, kApp).limits(0, 1),          // 552, E16
    number(0x5001, 0, kU8, kRw, 0, kApp).limits(0, 1),          // 553
    number(0x5999, 0, kU8, kConst, 3),                          // 555
    number(0x5999, 1, kU16, kRw, 250).limits(50, 1000),         // 556, E26; the LSS record (E22)
    number(0x5999, 2, kU8, kRw, 0x7F).limits(1, 127),           // 557, E1; the LSS record
    number(0x5999, 3, kU32, kWo, 0),                            // 558
};

struct Variant {
  const char* name;  ///< The ProductName and the default of 0x1008.
  const Definition* definition;
};

void PrintTo(const Variant& variant, std::ostream* out) {
  *out << variant.name;
}

std::string variantName(const ::testing::TestParamInfo<Variant>& info) {
  return info.param.name;
}

class GefranDictionary : public ::testing::TestWithParam<Variant> {
 protected:
  GefranDictionary()
      : values_(GetParam().definition->valuesSize / sizeof(uint64_t) + 1U),
        dictionary_(*GetParam().definition, values_.data()) {
    dictionary_.setNodeId(kNodeId);
    dictionary_.restoreDefaults(0x0000, 0xFFFF);
  }

  EntryRef entry(const Expected& row) {
    const EntryRef ref = dictionary_.find(row.index, row.subIndex);
    EXPECT_TRUE(ref.valid()) << where(row);
    return ref;
  }

  static std::string where(const Expected& row) {
    char buffer[16];
    std::snprintf(buffer, sizeof(buffer), "0x%04X:%02X", row.index, row.subIndex);
    return buffer;
  }

  static constexpr uint8_t kNodeId = 5;
  std::vector<uint64_t> values_;  // The RAM block, aligned for any scalar.
  ObjectDictionary dictionary_;
};

size_t typeSize(DataType type) {
  return type == DataType::kUnsigned8 ? 1U : type == DataType::kUnsigned16 ? 2U : 4U;
}

uint64_t typeMaximum(DataType type) {
  return (uint64_t{1} << (8U * typeSize(type))) - 1U;
}

/// Checks a value in wire form against an entry's limits, without storing it.
AbortCode checkValue(const ObjectDictionary& dictionary, const EntryRef& entry, uint64_t value) {
  uint8_t wire[4] = {};
  for (size_t i = 0; i < typeSize(entry.type()); ++i) {
    wire[i] = static_cast<uint8_t>(value >> (8U * i));
  }
  return dictionary.check(entry, wire, typeSize(entry.type()));
}

TEST_P(GefranDictionary, EveryEntryHasTheManualsTypeAccessAndGroup) {
  for (const Expected& row : kManual) {
    const EntryRef sub = entry(row);
    SCOPED_TRACE(where(row));
    EXPECT_EQ(sub.type(), row.type);
    const uint16_t access = sub.attributes() & (kReadable | kWritable | kInRom);
    switch (row.access) {
      case Access::kRo: EXPECT_EQ(access, kReadable); break;
      case Access::kWo: EXPECT_EQ(access, kWritable); break;
      case Access::kRw: EXPECT_EQ(access, kReadable | kWritable); break;
      case Access::kConst: EXPECT_EQ(access, kReadable | kInRom); break;
    }
    EXPECT_EQ(sub.attributes() & (kRpdoMappable | kTpdoMappable),
              row.tpdoMappable ? static_cast<unsigned>(kTpdoMappable) : 0U);
    EXPECT_EQ((sub.attributes() & kNodeIdRelative) != 0U, row.nodeIdRelative);
    EXPECT_EQ(sub.group(), row.group);
  }
}

TEST_P(GefranDictionary, HoldsNothingBeyondTheManualsEntries) {
  const Definition& definition = *GetParam().definition;
  size_t count = 0;
  for (const EntryRef& ref : Entries(definition)) {
    bool listed = false;
    for (const Expected& row : kManual) {
      listed = listed || (row.index == ref.index() && row.subIndex == ref.subIndex());
    }
    EXPECT_TRUE(listed) << "0x" << std::hex << ref.index() << ":" << +ref.subIndex();
    ++count;
  }
  EXPECT_EQ(count, sizeof(kManual) / sizeof(kManual[0]));
  EXPECT_FALSE(dictionary_.find(0x1800, 4).valid());  // E9: reserved, not implemented
  EXPECT_STREQ(definition.deviceName, GetParam().name);
}

TEST_P(GefranDictionary, DefaultsAreTheManuals) {
  for (const Expected& row : kManual) {
    const EntryRef sub = entry(row);
    SCOPED_TRACE(where(row));
    if (row.type == DataType::kVisibleString) {
      const char* expected = row.text != nullptr ? row.text : GetParam().name;
      char actual[8] = {};
      ASSERT_EQ(dictionary_.valueSize(sub), std::strlen(expected));
      dictionary_.read(sub, 0, reinterpret_cast<uint8_t*>(actual), sizeof(actual) - 1U);
      EXPECT_STREQ(actual, expected);
    } else {
      EXPECT_EQ(dictionary_.readUnsigned(sub), row.value + (row.nodeIdRelative ? kNodeId : 0U));
    }
  }
}

TEST_P(GefranDictionary, LimitsAreTheManualsAndRefuseTheValuesJustOutside) {
  for (const Expected& row : kManual) {
    const EntryRef sub = entry(row);
    SCOPED_TRACE(where(row));
    ASSERT_EQ((sub.attributes() & kHasLimits) != 0U, row.limited);
    if (!row.limited) {
      continue;
    }
    const Limits& limits = GetParam().definition->limits[sub.row->limits - 1U];
    EXPECT_EQ(limits.low, row.low);
    EXPECT_EQ(limits.high, row.high);
    EXPECT_EQ(checkValue(dictionary_, sub, row.low), AbortCode::kNone);
    EXPECT_EQ(checkValue(dictionary_, sub, row.high), AbortCode::kNone);
    if (row.low > 0U) {
      EXPECT_EQ(checkValue(dictionary_, sub, row.low - 1U), AbortCode::kValueTooLow);
    }
    if (row.high < typeMaximum(row.type)) {
      EXPECT_EQ(checkValue(dictionary_, sub, row.high + 1U), AbortCode::kValueTooHigh);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, GefranDictionary,
                         ::testing::Values(Variant{"GRA", &gen::gra::kDefinition},
                                           Variant{"GRN", &gen::grn::kDefinition}),
                         variantName);

TEST(GefranVariants, ShareOneParameterLayout) {
  EXPECT_EQ(gen::gra::kDefinition.layoutId, gen::grn::kDefinition.layoutId);
  EXPECT_EQ(gen::gra::kDefinition.valuesSize, gen::grn::kDefinition.valuesSize);
  EXPECT_EQ(sizeof(gen::gra::Values), sizeof(gen::grn::Values));
}

std::vector<std::string> readLines(const std::string& path) {
  std::ifstream file(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) {
    lines.push_back(line);
  }
  return lines;
}

/// The GRN spelling of a GRA line.
std::string toGrn(std::string line) {
  const std::pair<const char*, const char*> swaps[] = {
      {"GRA", "GRN"}, {"gra.eds", "grn.eds"}, {"with shaft", "without shaft"}};
  for (const auto& [from, to] : swaps) {
    for (size_t at = line.find(from); at != std::string::npos;
         at = line.find(from, at + std::strlen(to))) {
      line.replace(at, std::strlen(from), to);
    }
  }
  return line;
}

TEST(GefranVariants, EdsFilesDifferOnlyInTheVariantLines) {
  const std::vector<std::string> gra = readLines(COSTA_GEFRAN_DIR "/gra.eds");
  const std::vector<std::string> grn = readLines(COSTA_GEFRAN_DIR "/grn.eds");
  ASSERT_GT(gra.size(), 500U);
  ASSERT_EQ(gra.size(), grn.size());
  std::vector<std::string> differing;
  for (size_t i = 0; i < gra.size(); ++i) {
    if (gra[i] != grn[i]) {
      EXPECT_EQ(toGrn(gra[i]), grn[i]) << "line " << i + 1U;
      differing.push_back(gra[i]);
    }
  }
  const std::vector<std::string> expected = {
      "; Gefran GRA: contactless angle sensor with shaft (CANopen, CiA 301 v4.2, LSS CiA 305).",
      "FileName=gra.eds", "Description=Gefran GRA contactless angle sensor with shaft",
      "ProductName=GRA", "DefaultValue=GRA"};
  EXPECT_EQ(differing, expected);
}

}  // namespace
}  // namespace costa::od
