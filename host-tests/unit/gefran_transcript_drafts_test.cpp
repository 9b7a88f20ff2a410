// The draft transcripts of the Gefran GRA/GRN (targets/gefran/transcripts-draft) are not
// replayed yet: the device does not exist. This checks what can be checked without it: they
// parse, and every SDO exchange, TPDO, EMCY and boot-up frame in them agrees with the generated
// dictionaries (objects, access, sizes, limits, constant values) and with the manual's frame
// layouts.
#include <gtest/gtest.h>

#include <string>

#include "costa/od/object_dictionary.hpp"
#include "gra_od.hpp"
#include "grn_od.hpp"
#include "transcript.hpp"

namespace costa::test {
namespace {

using od::EntryRef;
using od::ObjectDictionary;

const std::string kDraftDir = COSTA_GEFRAN_DIR "/transcripts-draft";

const od::Definition* definitionOf(const std::string& device) {
  if (device == "gra") {
    return &gen::gra::kDefinition;
  }
  if (device == "grn") {
    return &gen::grn::kDefinition;
  }
  return nullptr;
}

uint32_t little32(const uint8_t* bytes) {
  return static_cast<uint32_t>(bytes[0]) | static_cast<uint32_t>(bytes[1]) << 8U |
         static_cast<uint32_t>(bytes[2]) << 16U | static_cast<uint32_t>(bytes[3]) << 24U;
}

bool inRange(uint32_t id, uint32_t base) {
  return id > base && id <= base + 0x7FU;
}

/// Checks one SDO request and the server's answer against the dictionary. `dictionary` holds
/// the defaults; its node-id is the one the frames address.
void checkSdoExchange(ObjectDictionary& dictionary, const TranscriptStep& request,
                      const TranscriptStep& response) {
  SCOPED_TRACE("line " + std::to_string(request.line) + ": " + request.text);
  const uint8_t* rq = request.frame.data;
  const uint8_t* rs = response.frame.data;
  ASSERT_EQ(request.frame.dlc, 8U);
  ASSERT_EQ(response.frame.dlc, 8U);
  EXPECT_EQ(response.wildcards, 0U);
  EXPECT_EQ(rs[1], rq[1]);  // the multiplexer is echoed
  EXPECT_EQ(rs[2], rq[2]);
  EXPECT_EQ(rs[3], rq[3]);
  const uint16_t index = static_cast<uint16_t>(rq[1] | rq[2] << 8U);
  EntryRef ref;
  const AbortCode found = dictionary.find(index, rq[3], &ref);
  if (rs[0] == 0x80U) {
    const auto abort = static_cast<AbortCode>(little32(rs + 4));
    switch (abort) {
      case AbortCode::kNoObject:
      case AbortCode::kNoSubIndex: EXPECT_EQ(found, abort); return;
      case AbortCode::kReadOfWriteOnly:
        ASSERT_EQ(found, AbortCode::kNone);
        EXPECT_EQ(ref.entry->attributes & od::kReadable, 0U);
        return;
      case AbortCode::kValueTooHigh:
      case AbortCode::kValueTooLow:
        ASSERT_EQ(found, AbortCode::kNone);
        EXPECT_EQ(dictionary.check(*ref.entry, rq + 4, ref.entry->size), abort);
        return;
      case AbortCode::kInvalidValue:  // refused by the device, not by the limits
      case AbortCode::kCannotStore:   // a wrong save/load signature
        ASSERT_EQ(found, AbortCode::kNone);
        EXPECT_EQ(dictionary.check(*ref.entry, rq + 4, ref.entry->size), AbortCode::kNone);
        return;
      default: ADD_FAILURE() << "abort code not covered by this check"; return;
    }
  }
  ASSERT_EQ(found, AbortCode::kNone);
  const od::SubEntry& entry = *ref.entry;
  if ((rq[0] & 0xE0U) == 0x20U) {  // expedited download, size indicated
    ASSERT_EQ(rq[0] & 0x03U, 0x03U);
    EXPECT_EQ(rs[0], 0x60U);
    EXPECT_NE(entry.attributes & od::kWritable, 0U);
    const size_t size = 4U - ((rq[0] >> 2U) & 0x03U);
    EXPECT_EQ(size, entry.size);
    EXPECT_EQ(dictionary.check(entry, rq + 4, size), AbortCode::kNone);
    return;
  }
  ASSERT_EQ(rq[0], 0x40U);  // upload; every value fits an expedited response (E2)
  ASSERT_EQ(rs[0] & 0xF3U, 0x43U) << "expedited, size indicated";
  EXPECT_NE(entry.attributes & od::kReadable, 0U);
  const size_t size = 4U - ((rs[0] >> 2U) & 0x03U);
  EXPECT_EQ(size, dictionary.valueSize(entry));
  for (size_t i = size; i < 4U; ++i) {
    EXPECT_EQ(rs[4 + i], 0U) << "unused byte " << i;
  }
  if ((entry.attributes & od::kInRom) != 0U) {
    uint8_t value[4] = {};
    dictionary.read(entry, 0, value, size);
    for (size_t i = 0; i < size; ++i) {
      EXPECT_EQ(rs[4 + i], value[i]) << "byte " << i << " of a constant";
    }
  }
}

/// TPDO, EMCY and boot-up frames: the layouts of manual lines 252-253, 271-276 and 352-358.
void checkProducedFrame(const TranscriptStep& step) {
  SCOPED_TRACE("line " + std::to_string(step.line) + ": " + step.text);
  const CanFrame& frame = step.frame;
  const auto byteIs = [&](size_t i, uint8_t value) {
    return (step.wildcards & (1U << i)) != 0U || frame.data[i] == value;
  };
  if (inRange(frame.id, 0x700U)) {
    EXPECT_EQ(frame.dlc, 1U);
    EXPECT_TRUE(byteIs(0, 0x00U)) << "boot-up";
  } else if (inRange(frame.id, 0x180U)) {
    ASSERT_EQ(frame.dlc, 8U);
    EXPECT_TRUE(byteIs(4, 0xFFU) && byteIs(5, 0xFFU) && byteIs(6, 0xFFU)) << "0x2110.5-.7";
  } else if (inRange(frame.id, 0x080U)) {
    ASSERT_EQ(frame.dlc, 8U);
    EXPECT_TRUE(byteIs(0, 0x00U) && byteIs(1, 0x10U)) << "error code 0x1000";
    EXPECT_TRUE(byteIs(2, 0x00U)) << "error register always 0 (E14)";
    EXPECT_TRUE(byteIs(4, 0x00U) && byteIs(5, 0xFFU) && byteIs(6, 0xFFU) && byteIs(7, 0xFFU));
  } else if (!inRange(frame.id, 0x580U)) {
    ADD_FAILURE() << "unexpected frame";
  }
}

class GefranDraft : public ::testing::TestWithParam<std::string> {};

TEST_P(GefranDraft, AgreesWithTheDictionary) {
  Transcript transcript;
  std::string error;
  ASSERT_TRUE(loadTranscript(GetParam(), &transcript, &error)) << error;
  const od::Definition* definition = definitionOf(transcript.device);
  ASSERT_NE(definition, nullptr) << "device " << transcript.device;
  std::vector<uint64_t> values(definition->valuesSize / sizeof(uint64_t) + 1U);
  ObjectDictionary dictionary(*definition, values.data());
  dictionary.restoreDefaults(0x0000, 0xFFFF);

  const std::vector<TranscriptStep>& steps = transcript.steps;
  ASSERT_FALSE(steps.empty());
  ASSERT_EQ(steps[0].kind, TranscriptStep::Kind::kTransmit);
  EXPECT_EQ(steps[0].frame.id, 0x700U + static_cast<uint32_t>(transcript.nodeId)) << "boot-up";
  size_t exchanges = 0;
  for (size_t i = 0; i < steps.size(); ++i) {
    const TranscriptStep& step = steps[i];
    if (step.kind == TranscriptStep::Kind::kTransmit) {
      checkProducedFrame(step);
    }
    if (step.kind != TranscriptStep::Kind::kReceive || !inRange(step.frame.id, 0x600U)) {
      continue;
    }
    const uint32_t nodeId = step.frame.id - 0x600U;
    if (i + 1U < steps.size() && steps[i + 1U].kind == TranscriptStep::Kind::kTransmit &&
        steps[i + 1U].frame.id == 0x580U + nodeId) {
      dictionary.setNodeId(static_cast<uint8_t>(nodeId));
      checkSdoExchange(dictionary, step, steps[i + 1U]);
      ++exchanges;
    }
  }
  EXPECT_GT(exchanges, 0U);
}

std::string draftName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.substr(kDraftDir.size() + 1U);
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      c = '_';
    }
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Drafts, GefranDraft, ::testing::ValuesIn(findTranscripts(kDraftDir)),
                         draftName);

TEST(GefranDrafts, CoverEveryNumberedExampleAndEveryPrintedPdo) {
  const std::vector<std::string> drafts = findTranscripts(kDraftDir);
  for (const char* prefix :
       {"example-1-", "example-2-", "example-3-", "example-4-", "example-5-", "example-6-",
        "example-7-", "example-8-", "example-9-", "pdo-1-", "pdo-2-", "pdo-3-", "pdo-4-"}) {
    size_t matches = 0;
    for (const std::string& path : drafts) {
      matches += path.find(kDraftDir + "/" + prefix) == 0U ? 1U : 0U;
    }
    EXPECT_EQ(matches, 1U) << prefix;
  }
}

}  // namespace
}  // namespace costa::test
