// Streamed entries (ObjectHook::readStream / writeStream / abortWriteStream): what a hook sees
// of expedited, segmented and block transfers of a DOMAIN, its refusals, and the defaults.
#include <cstring>
#include <initializer_list>

#include "example_fixture.hpp"

namespace costa::test {
namespace {

/// Records every streaming call in fixed storage (hooks run where nothing may allocate).
class RecordingHook : public ObjectHook {
 public:
  struct Call {
    size_t offset;
    size_t length;
    bool last;
    size_t indicated;
  };

  AbortCode readStream(od::ObjectDictionary&, const od::EntryRef&, size_t offset,
                       uint8_t* destination, size_t capacity, size_t* produced,
                       size_t* totalSize) noexcept override {
    *totalSize = valueSize;
    if (capacity == 0U && refuseSize != AbortCode::kNone) {
      return refuseSize;  // the size query at the start of an upload
    }
    if (capacity > 0U && offset + capacity > refuseReadFrom) {
      return AbortCode::kHardwareError;
    }
    const size_t end = valueSize < shrinkTo ? valueSize : shrinkTo;
    const size_t available = offset < end ? end - offset : 0U;
    *produced = capacity < available ? capacity : available;
    for (size_t i = 0; i < *produced; ++i) {
      destination[i] = static_cast<uint8_t>(offset + i);
    }
    return AbortCode::kNone;
  }

  AbortCode writeStream(od::ObjectDictionary&, const od::EntryRef&, size_t offset,
                        const uint8_t* source, size_t length, bool last,
                        size_t indicatedSize) noexcept override {
    if (callCount < kMaxCalls) {
      calls[callCount++] = Call{offset, length, last, indicatedSize};
    }
    if (offset + length <= sizeof(data)) {
      std::memcpy(data + offset, source, length);
    }
    return last ? refuseLast : AbortCode::kNone;
  }

  void abortWriteStream(od::ObjectDictionary&, const od::EntryRef&,
                        AbortCode reason) noexcept override {
    if (abortCount < kMaxCalls) {
      aborts[abortCount++] = reason;
    }
  }

  static constexpr size_t kMaxCalls = 16;
  Call calls[kMaxCalls] = {};
  size_t callCount = 0;
  AbortCode aborts[kMaxCalls] = {};
  size_t abortCount = 0;
  uint8_t data[256] = {};
  AbortCode refuseLast = AbortCode::kNone;
  size_t valueSize = 10;
  size_t shrinkTo = SIZE_MAX;
  size_t refuseReadFrom = SIZE_MAX;
  AbortCode refuseSize = AbortCode::kNone;
};

/// A hook that keeps every default.
class PlainHook : public ObjectHook {};

class SdoStreaming : public ExampleNodeTest {
 protected:
  void SetUp() override {
    ExampleNodeTest::SetUp();
    ASSERT_TRUE(bus_.node().attachHook(0x2008, 0x2008, hook_));
  }
  void expectCalls(std::initializer_list<RecordingHook::Call> expected) {
    ASSERT_EQ(hook_.callCount, expected.size());
    size_t i = 0;
    for (const RecordingHook::Call& call : expected) {
      EXPECT_EQ(hook_.calls[i].offset, call.offset) << "call " << i;
      EXPECT_EQ(hook_.calls[i].length, call.length) << "call " << i;
      EXPECT_EQ(hook_.calls[i].last, call.last) << "call " << i;
      EXPECT_EQ(hook_.calls[i].indicated, call.indicated) << "call " << i;
      ++i;
    }
  }

  RecordingHook hook_;
};

TEST_F(SdoStreaming, SegmentedDownloadArrivesInBufferSizedPieces) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 08 20 00 28 00 00 00   # 40 bytes
    tx 581 [8] 60 08 20 00 00 00 00 00
    rx 601 [8] 00 01 02 03 04 05 06 07
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 10 08 09 0A 0B 0C 0D 0E
    tx 581 [8] 30 00 00 00 00 00 00 00
    rx 601 [8] 00 0F 10 11 12 13 14 15
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 10 16 17 18 19 1A 1B 1C
    tx 581 [8] 30 00 00 00 00 00 00 00
    rx 601 [8] 00 1D 1E 1F 20 21 22 23
    tx 581 [8] 20 00 00 00 00 00 00 00
    rx 601 [8] 15 24 25 26 27 28 00 00   # 5 bytes, last
    tx 581 [8] 30 00 00 00 00 00 00 00
  )");
  expectCalls({{0, 0, false, 40}, {0, 32, false, 40}, {32, 8, true, 40}});
  for (uint8_t i = 0; i < 40; ++i) {
    EXPECT_EQ(hook_.data[i], i + 1U);
  }
  EXPECT_EQ(hook_.abortCount, 0U);
}

TEST_F(SdoStreaming, ExpeditedDownloadIsOneLastCall) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 08 20 00 0A 0B 0C 0D
    tx 581 [8] 60 08 20 00 00 00 00 00
  )");
  expectCalls({{0, 4, true, 4}});
  EXPECT_EQ(hook_.data[3], 0x0D);
}

TEST_F(SdoStreaming, BlockDownloadWithoutSize) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] C4 08 20 00 00 00 00 00   # CRC, no size
    tx 581 [8] A4 08 20 00 7F 00 00 00   # streamed: the largest block size
    rx 601 [8] 81 61 62 63 00 00 00 00
    tx 581 [8] A2 01 7F 00 00 00 00 00
    rx 601 [8] D1 D6 9D 00 00 00 00 00   # CRC of "abc"
    tx 581 [8] A1 00 00 00 00 00 00 00
  )");
  expectCalls({{0, 0, false, kSizeNotIndicated}, {0, 3, true, kSizeNotIndicated}});
}

TEST_F(SdoStreaming, UploadsReadByOffset) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 20 00 00 00 00 00
    tx 581 [8] 41 08 20 00 0A 00 00 00   # the size comes from the hook
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 00 01 02 03 04 05 06
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 19 07 08 09 00 00 00 00
  )");
  hook_.valueSize = 3;
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 20 00 00 00 00 00
    tx 581 [8] 47 08 20 00 00 01 02 00   # expedited
  )");
}

TEST_F(SdoStreaming, ValueShrinkingDuringAnUpload_08000024) {
  hook_.shrinkTo = 8;
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 20 00 00 00 00 00
    tx 581 [8] 41 08 20 00 0A 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 00 00 01 02 03 04 05 06
    rx 601 [8] 70 00 00 00 00 00 00 00
    tx 581 [8] 80 08 20 00 24 00 00 08
    rx 601 [8] A4 08 20 00 7F 00 00 00
    tx 581 [8] C6 08 20 00 0A 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 00 01 02 03 04 05 06
    tx 581 [8] 80 08 20 00 24 00 00 08
  )");
}

TEST_F(SdoStreaming, ReadRefusedByTheHook) {
  hook_.refuseReadFrom = 7;
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] A4 08 20 00 7F 00 00 00
    tx 581 [8] C6 08 20 00 0A 00 00 00
    rx 601 [8] A3 00 00 00 00 00 00 00
    tx 581 [8] 01 00 01 02 03 04 05 06
    tx 581 [8] 80 08 20 00 00 00 06 06
  )");
  hook_.valueSize = 3;
  hook_.refuseReadFrom = 0;
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 20 00 00 00 00 00
    tx 581 [8] 80 08 20 00 00 00 06 06
  )");
}

TEST_F(SdoStreaming, AHookThatRefusesTheSizeAbortsTheInitiateWithItsCode) {
  hook_.refuseSize = AbortCode::kCannotStoreState;  // a code the server never makes up itself
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 20 00 00 00 00 00   # upload
    tx 581 [8] 80 08 20 00 22 00 00 08
    rx 601 [8] A4 08 20 00 7F 00 00 00   # block upload
    tx 581 [8] 80 08 20 00 22 00 00 08
    rx 601 [8] 40 08 20 00 00 00 00 00   # nothing of either is left behind
    tx 581 [8] 80 08 20 00 22 00 00 08
  )");
  hook_.refuseSize = AbortCode::kNone;
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 40 08 20 00 00 00 00 00
    tx 581 [8] 41 08 20 00 0A 00 00 00
  )");
}

TEST_F(SdoStreaming, RefusalOfTheLastPieceAbortsWithTheHooksCode) {
  hook_.refuseLast = AbortCode::kInvalidValue;
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 08 20 00 03 00 00 00
    tx 581 [8] 60 08 20 00 00 00 00 00
    rx 601 [8] 09 61 62 63 00 00 00 00
    tx 581 [8] 80 08 20 00 30 00 09 06
    rx 601 [8] 2F 08 20 00 01 00 00 00   # expedited
    tx 581 [8] 80 08 20 00 30 00 09 06
  )");
  ASSERT_EQ(hook_.abortCount, 2U);
  EXPECT_EQ(hook_.aborts[0], AbortCode::kInvalidValue);
  EXPECT_EQ(hook_.aborts[1], AbortCode::kInvalidValue);
}

TEST_F(SdoStreaming, EveryEndOtherThanSuccessIsReported) {
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 21 08 20 00 0A 00 00 00   # client abort
    tx 581 [8] 60 08 20 00 00 00 00 00
    rx 601 [8] 80 08 20 00 00 00 06 06
    rx 601 [8] 21 08 20 00 0A 00 00 00   # timeout
    tx 581 [8] 60 08 20 00 00 00 00 00
    wait 1000
    tx 581 [8] 80 08 20 00 00 00 04 05
    rx 601 [8] C6 08 20 00 01 00 00 00   # CRC error
    tx 581 [8] A4 08 20 00 01 00 00 00
    rx 601 [8] 81 61 00 00 00 00 00 00
    tx 581 [8] A2 01 01 00 00 00 00 00
    rx 601 [8] D9 00 00 00 00 00 00 00
    tx 581 [8] 80 08 20 00 04 00 04 05
    rx 601 [8] C2 08 20 00 0A 00 00 00   # NMT reset communication
    tx 581 [8] A4 08 20 00 02 00 00 00
    rx 000 [2] 82 01
    tx 701 [1] 00
  )");
  ASSERT_EQ(hook_.abortCount, 4U);
  EXPECT_EQ(hook_.aborts[0], AbortCode::kHardwareError);  // the client's code
  EXPECT_EQ(hook_.aborts[1], AbortCode::kTimeout);
  EXPECT_EQ(hook_.aborts[2], AbortCode::kCrc);
  EXPECT_EQ(hook_.aborts[3], AbortCode::kGeneral);
}

TEST_F(SdoStreaming, DefaultsRefuseWritesAndReadAnEmptyDomain_08000020) {
  PlainHook plain;
  ASSERT_TRUE(bus_.node().attachHook(0x2008, 0x2008, plain));
  EXPECT_TRANSCRIPT(R"(
    rx 601 [8] 23 08 20 00 01 02 03 04
    tx 581 [8] 80 08 20 00 20 00 00 08
    rx 601 [8] 21 08 20 00 0A 00 00 00
    tx 581 [8] 80 08 20 00 20 00 00 08
    rx 601 [8] C6 08 20 00 0A 00 00 00
    tx 581 [8] 80 08 20 00 20 00 00 08
    rx 601 [8] 40 08 20 00 00 00 00 00
    tx 581 [8] 41 08 20 00 00 00 00 00
    rx 601 [8] 60 00 00 00 00 00 00 00
    tx 581 [8] 0F 00 00 00 00 00 00 00
  )");
}

}  // namespace
}  // namespace costa::test
