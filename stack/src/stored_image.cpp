#include "costa/stored_image.hpp"

#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

constexpr size_t kChunkSize = 32;

bool magicIsComplete(const uint8_t* bytes) noexcept {
  return sameBytes(bytes, kImageMagic, kImageMagicSize);
}

/// Each magic byte is erased or right: what an erase or a magic write leaves when cut short.
bool magicIsBlank(const uint8_t* bytes) noexcept {
  for (size_t i = 0; i < kImageMagicSize; ++i) {
    if (bytes[i] != 0xFFU && bytes[i] != kImageMagic[i]) {
      return false;
    }
  }
  return true;
}

ImageHeader decodeImageHeader(const uint8_t* bytes) noexcept {
  ImageHeader header{};
  header.formatVersion = bytes[4];
  header.kind = static_cast<ImageKind>(bytes[5]);
  header.region = loadU16(bytes + 6);
  header.layout = loadU32(bytes + 8);
  header.location = loadU32(bytes + 12);
  header.payloadLength = loadU32(bytes + 16);
  header.sequence = loadU32(bytes + 20);
  header.crc = loadU32(bytes + kImageCrcOffset);
  return header;
}

}  // namespace

void encodeImageHeader(const ImageHeader& header, uint8_t* out) noexcept {
  copyBytes(out, kImageMagic, kImageMagicSize);
  out[4] = header.formatVersion;
  out[5] = static_cast<uint8_t>(header.kind);
  storeU16(out + 6, header.region);
  storeU32(out + 8, header.layout);
  storeU32(out + 12, header.location);
  storeU32(out + 16, header.payloadLength);
  storeU32(out + 20, header.sequence);
}

SlotInfo inspectSlot(NvStorage& storage, size_t offset, size_t slotSize) noexcept {
  SlotInfo info;
  uint8_t bytes[kImageHeaderSize];
  if (slotSize < kImageHeaderSize || !storage.read(offset, bytes, kImageHeaderSize)) {
    info.state = SlotState::kUnreadable;
    return info;
  }
  if (!magicIsComplete(bytes)) {
    info.state = magicIsBlank(bytes) ? SlotState::kBlank : SlotState::kDamaged;
    return info;
  }
  info.header = decodeImageHeader(bytes);
  info.state = SlotState::kDamaged;
  if (info.header.payloadLength > slotSize - kImageHeaderSize) {
    return info;
  }
  Crc32 crc;
  crc.update(bytes, kImageCrcOffset);
  uint8_t chunk[kChunkSize];
  size_t position = 0;
  while (position < info.header.payloadLength) {
    const size_t remaining = info.header.payloadLength - position;
    const size_t length = remaining < kChunkSize ? remaining : kChunkSize;
    if (!storage.read(offset + kImageHeaderSize + position, chunk, length)) {
      info.state = SlotState::kUnreadable;
      return info;
    }
    crc.update(chunk, length);
    position += length;
  }
  if (crc.value() == info.header.crc) {
    info.state = SlotState::kIntact;
  }
  return info;
}

bool ImageWriter::begin(const ImageHeader& header) noexcept {
  ok_ = false;
  if (slotSize_ < kImageHeaderSize || header.payloadLength > slotSize_ - kImageHeaderSize) {
    return false;
  }
  encodeImageHeader(header, header_);
  crc_ = Crc32{};
  crc_.update(header_, kImageCrcOffset);
  staged_ = 0;
  written_ = 0;
  expected_ = header.payloadLength;
  ok_ = storage_.erase(slotOffset_, slotSize_);
  return ok_;
}

bool ImageWriter::append(const uint8_t* data, size_t length) noexcept {
  if (!ok_ || length > expected_ - written_ - staged_) {
    ok_ = false;
    return false;
  }
  crc_.update(data, length);
  while (length > 0U) {
    size_t piece = kStageSize - staged_;
    if (piece > length) {
      piece = length;
    }
    copyBytes(stage_ + staged_, data, piece);
    staged_ += piece;
    data += piece;
    length -= piece;
    if (staged_ == kStageSize && !flush()) {
      return false;
    }
  }
  return true;
}

bool ImageWriter::flush() noexcept {
  if (staged_ != 0U) {
    ok_ = ok_ && storage_.write(slotOffset_ + kImageHeaderSize + written_, stage_, staged_);
    written_ += staged_;
    staged_ = 0;
  }
  return ok_;
}

bool ImageWriter::finish() noexcept {
  if (!flush() || written_ != expected_) {
    ok_ = false;
    return false;
  }
  storeU32(header_ + kImageCrcOffset, crc_.value());
  // Everything but the magic first: the slot stays blank until the last byte of the magic.
  const bool written = storage_.write(slotOffset_ + kImageMagicSize, header_ + kImageMagicSize,
                                      kImageHeaderSize - kImageMagicSize) &&
                       storage_.write(slotOffset_, header_, kImageMagicSize);
  ok_ = written && storage_.commit();
  if (written && !ok_) {
    // The medium took the image but cannot make it durable (a file that cannot be replaced):
    // the save that failed is withdrawn, so that the slot kept before stays the one a load
    // reads, now and after the next commit that succeeds.
    (void)storage_.erase(slotOffset_, slotSize_);
  }
  return ok_;
}

ImageReader::ImageReader(NvStorage& storage, size_t slotOffset, const ImageHeader& header) noexcept
    : storage_(storage),
      payloadOffset_(slotOffset + kImageHeaderSize),
      payloadLength_(header.payloadLength),
      expectedCrc_(header.crc) {
  uint8_t bytes[kImageHeaderSize];
  encodeImageHeader(header, bytes);
  crc_.update(bytes, kImageCrcOffset);
}

bool ImageReader::read(uint8_t* destination, size_t length) noexcept {
  if (!ok_ || length > payloadLength_ - position_ ||
      !storage_.read(payloadOffset_ + position_, destination, length)) {
    ok_ = false;
    return false;
  }
  crc_.update(destination, length);
  position_ += length;
  return true;
}

bool ImageReader::matches() const noexcept {
  return ok_ && position_ == payloadLength_ && crc_.value() == expectedCrc_;
}

}  // namespace costa
