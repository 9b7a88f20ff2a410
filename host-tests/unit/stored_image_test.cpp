// One slot image: header bytes, what inspectSlot() makes of every state a slot can be in, the
// write order of ImageWriter (blank until complete), and ImageReader's re-check.
#include <gtest/gtest.h>

#include <vector>

#include "costa/port/memory/memory_storage.hpp"
#include "costa/stored_image.hpp"

namespace costa {
namespace {

constexpr size_t kSlot = 16;      // slot offset used by the tests
constexpr size_t kSlotSize = 48;  // header + up to 20 payload bytes

ImageHeader sampleHeader(size_t payloadLength) {
  ImageHeader header{};
  header.formatVersion = kImageFormatVersion;
  header.kind = ImageKind::kValues;
  header.region = 0x0102;
  header.layout = 0x11223344U;
  header.location = kSlot;
  header.payloadLength = static_cast<uint32_t>(payloadLength);
  header.sequence = 0xCAFEBABEU;
  return header;
}

const std::vector<uint8_t> kPayload = {10, 20, 30, 40, 50, 60, 70};

bool writeSample(NvStorage& storage, const std::vector<uint8_t>& payload = kPayload) {
  ImageWriter writer(storage, kSlot, kSlotSize);
  return writer.begin(sampleHeader(payload.size())) && writer.append(payload.data(), 3) &&
         writer.append(payload.data() + 3, payload.size() - 3) && writer.finish();
}

TEST(StoredImageTest, HeaderBytesAreLittleEndianInTheDocumentedOrder) {
  uint8_t bytes[kImageCrcOffset] = {};
  encodeImageHeader(sampleHeader(5), bytes);
  const std::vector<uint8_t> expected = {'C',  'S',  'T',  'P',  0x02, 0x01, 0x02, 0x01,
                                         0x44, 0x33, 0x22, 0x11, 0x10, 0x00, 0x00, 0x00,
                                         0x05, 0x00, 0x00, 0x00, 0xBE, 0xBA, 0xFE, 0xCA};
  EXPECT_EQ(std::vector<uint8_t>(bytes, bytes + kImageCrcOffset), expected);
}

TEST(StoredImageTest, SequencesCompareAcrossTheWrap) {
  EXPECT_TRUE(isNewerSequence(2, 1));
  EXPECT_FALSE(isNewerSequence(1, 2));
  EXPECT_FALSE(isNewerSequence(7, 7));
  EXPECT_TRUE(isNewerSequence(0, 0xFFFFFFFFU));
  EXPECT_TRUE(isNewerSequence(3, 0xFFFFFFF0U));
  EXPECT_FALSE(isNewerSequence(0xFFFFFFFFU, 0));
}

TEST(StoredImageTest, AWrittenImageIsIntactWithItsHeaderAndCrc) {
  port::MemoryStorageOf<128> storage;
  ASSERT_TRUE(writeSample(storage));
  const SlotInfo info = inspectSlot(storage, kSlot, kSlotSize);
  ASSERT_EQ(info.state, SlotState::kIntact);
  EXPECT_EQ(info.header.region, 0x0102U);
  EXPECT_EQ(info.header.layout, 0x11223344U);
  EXPECT_EQ(info.header.location, kSlot);
  EXPECT_EQ(info.header.payloadLength, kPayload.size());
  EXPECT_EQ(info.header.sequence, 0xCAFEBABEU);
  std::vector<uint8_t> covered(storage.bytes() + kSlot, storage.bytes() + kSlot + kImageCrcOffset);
  covered.insert(covered.end(), kPayload.begin(), kPayload.end());
  EXPECT_EQ(info.header.crc, crc32(covered.data(), covered.size()));
  EXPECT_EQ(std::vector<uint8_t>(storage.bytes() + kSlot + kImageHeaderSize,
                                 storage.bytes() + kSlot + kImageHeaderSize + kPayload.size()),
            kPayload);
  EXPECT_EQ(storage.commits(), 1U);
}

TEST(StoredImageTest, ErasedAndPartlyWrittenMagicsAreBlankOtherBytesAreDamaged) {
  port::MemoryStorageOf<128> storage;
  EXPECT_EQ(inspectSlot(storage, kSlot, kSlotSize).state, SlotState::kBlank);
  const uint8_t blanks[][4] = {{'C', 0xFF, 0xFF, 0xFF},
                               {'C', 'S', 'T', 0xFF},
                               {0xFF, 0xFF, 'T', 'P'},
                               {0xFF, 'S', 0xFF, 'P'}};
  for (const auto& magic : blanks) {
    ASSERT_TRUE(storage.write(kSlot, magic, 4));
    EXPECT_EQ(inspectSlot(storage, kSlot, kSlotSize).state, SlotState::kBlank);
  }
  const uint8_t damaged[][4] = {{'X', 'S', 'T', 'P'}, {0, 0, 0, 0}, {'C', 'S', 'T', 0x00}};
  for (const auto& magic : damaged) {
    ASSERT_TRUE(storage.write(kSlot, magic, 4));
    EXPECT_EQ(inspectSlot(storage, kSlot, kSlotSize).state, SlotState::kDamaged);
  }
}

TEST(StoredImageTest, AnyChangedByteOfHeaderOrPayloadMakesTheImageDamaged) {
  port::MemoryStorageOf<128> storage;
  ASSERT_TRUE(writeSample(storage));
  for (size_t i = 0; i < kImageHeaderSize + kPayload.size(); ++i) {
    storage.bytes()[kSlot + i] ^= 0x01U;
    EXPECT_EQ(inspectSlot(storage, kSlot, kSlotSize).state, SlotState::kDamaged) << "byte " << i;
    storage.bytes()[kSlot + i] ^= 0x01U;
  }
  storage.bytes()[kSlot + kImageHeaderSize + kPayload.size()] = 0x00;  // after the payload
  EXPECT_EQ(inspectSlot(storage, kSlot, kSlotSize).state, SlotState::kIntact);
}

TEST(StoredImageTest, APayloadLongerThanTheSlotIsDamaged) {
  port::MemoryStorageOf<128> storage;
  ASSERT_TRUE(writeSample(storage));
  EXPECT_EQ(inspectSlot(storage, kSlot, kImageHeaderSize + kPayload.size()).state,
            SlotState::kIntact);
  EXPECT_EQ(inspectSlot(storage, kSlot, kImageHeaderSize + kPayload.size() - 1U).state,
            SlotState::kDamaged);
}

TEST(StoredImageTest, ReadsTheMediumRefusesMakeTheSlotUnreadable) {
  port::MemoryStorageOf<64> storage;
  EXPECT_EQ(inspectSlot(storage, 60, kSlotSize).state, SlotState::kUnreadable);
  EXPECT_EQ(inspectSlot(storage, 0, kImageHeaderSize - 1U).state, SlotState::kUnreadable);
  // The header fits, the payload runs past the end of the medium.
  ImageWriter writer(storage, kSlot, kSlotSize);
  ASSERT_TRUE(writer.begin(sampleHeader(20)));
  const std::vector<uint8_t> payload(20, 0xAB);
  ASSERT_TRUE(writer.append(payload.data(), payload.size()));
  ASSERT_TRUE(writer.finish());
  port::MemoryStorage shorter(storage.bytes(), kSlot + kImageHeaderSize + 10U);
  EXPECT_EQ(inspectSlot(shorter, kSlot, kSlotSize).state, SlotState::kUnreadable);
}

TEST(StoredImageTest, TheSlotStaysBlankUntilTheLastByteOfAWrite) {
  port::MemoryStorageOf<128> measure;
  ASSERT_TRUE(writeSample(measure));
  const size_t total = measure.bytesErased() + measure.bytesWritten();
  EXPECT_EQ(measure.bytesErased(), kSlotSize);
  EXPECT_EQ(measure.bytesWritten(), kImageHeaderSize + kPayload.size());

  for (size_t cut = 0; cut <= total; ++cut) {
    port::MemoryStorageOf<128> storage;
    storage.cutPowerAfter(cut);
    EXPECT_EQ(writeSample(storage), cut == total) << "cut after " << cut;
    storage.restorePower();
    EXPECT_EQ(inspectSlot(storage, kSlot, kSlotSize).state,
              cut == total ? SlotState::kIntact : SlotState::kBlank)
        << "cut after " << cut;
  }
}

TEST(StoredImageTest, BeginErasesTheWholeSlotAndNothingElse) {
  port::MemoryStorageOf<128> storage;
  for (size_t i = 0; i < storage.size(); ++i) {
    storage.bytes()[i] = 0x00;
  }
  ASSERT_TRUE(writeSample(storage));
  EXPECT_EQ(storage.bytes()[kSlot - 1U], 0x00U);
  EXPECT_EQ(storage.bytes()[kSlot + kImageHeaderSize + kPayload.size()], 0xFFU);
  EXPECT_EQ(storage.bytes()[kSlot + kSlotSize - 1U], 0xFFU);
  EXPECT_EQ(storage.bytes()[kSlot + kSlotSize], 0x00U);
}

TEST(StoredImageTest, TheWriterRefusesPayloadsOfAnotherLengthThanDeclared) {
  port::MemoryStorageOf<128> storage;
  const uint8_t data[4] = {1, 2, 3, 4};
  {
    ImageWriter writer(storage, kSlot, kSlotSize);
    ASSERT_TRUE(writer.begin(sampleHeader(3)));
    EXPECT_FALSE(writer.append(data, 4));
    EXPECT_FALSE(writer.finish());
  }
  {
    ImageWriter writer(storage, kSlot, kSlotSize);
    ASSERT_TRUE(writer.begin(sampleHeader(3)));
    EXPECT_TRUE(writer.append(data, 2));
    EXPECT_FALSE(writer.finish());
  }
  {
    ImageWriter writer(storage, kSlot, kSlotSize);
    EXPECT_FALSE(writer.begin(sampleHeader(kSlotSize - kImageHeaderSize + 1U)));
    EXPECT_FALSE(writer.append(data, 1));
  }
  EXPECT_EQ(storage.commits(), 0U);
  EXPECT_EQ(inspectSlot(storage, kSlot, kSlotSize).state, SlotState::kBlank);
}

TEST(StoredImageTest, TheWriterFailsWhenTheMediumFails) {
  port::MemoryStorageOf<128> storage;
  storage.cutPowerAfter(0);
  ImageWriter writer(storage, kSlot, kSlotSize);
  EXPECT_FALSE(writer.begin(sampleHeader(kPayload.size())));
  EXPECT_FALSE(writer.append(kPayload.data(), kPayload.size()));
  EXPECT_FALSE(writer.finish());
}

TEST(StoredImageTest, LongPayloadsGoOutInChunksAndReadBackInAnyPieces) {
  port::MemoryStorageOf<256> storage;
  std::vector<uint8_t> payload(100);
  for (size_t i = 0; i < payload.size(); ++i) {
    payload[i] = static_cast<uint8_t>(i * 3U);
  }
  ImageWriter writer(storage, 0, 160);
  ImageHeader header = sampleHeader(100);
  header.location = 0;
  ASSERT_TRUE(writer.begin(header));
  for (size_t i = 0; i < payload.size(); ++i) {
    ASSERT_TRUE(writer.append(&payload[i], 1));
  }
  ASSERT_TRUE(writer.finish());
  EXPECT_LE(storage.writeCalls(), 6U) << "payload staged, not written byte by byte";

  const SlotInfo info = inspectSlot(storage, 0, 160);
  ASSERT_EQ(info.state, SlotState::kIntact);
  ImageReader reader(storage, 0, info.header);
  std::vector<uint8_t> back(100);
  EXPECT_TRUE(reader.read(back.data(), 33));
  EXPECT_FALSE(reader.matches()) << "not all read yet";
  EXPECT_TRUE(reader.read(back.data() + 33, 67));
  EXPECT_TRUE(reader.matches());
  EXPECT_EQ(back, payload);
}

TEST(StoredImageTest, TheReaderNoticesAMediumThatChangedSinceTheCheck) {
  port::MemoryStorageOf<128> storage;
  ASSERT_TRUE(writeSample(storage));
  const SlotInfo info = inspectSlot(storage, kSlot, kSlotSize);
  ASSERT_EQ(info.state, SlotState::kIntact);
  storage.bytes()[kSlot + kImageHeaderSize + 2U] ^= 0x80U;
  ImageReader reader(storage, kSlot, info.header);
  std::vector<uint8_t> back(kPayload.size());
  EXPECT_TRUE(reader.read(back.data(), back.size()));
  EXPECT_FALSE(reader.matches());

  ImageReader beyond(storage, kSlot, info.header);
  EXPECT_FALSE(beyond.read(back.data(), back.size() + 1U));
  EXPECT_FALSE(beyond.read(back.data(), 1));
  EXPECT_FALSE(beyond.matches());
}

}  // namespace
}  // namespace costa
