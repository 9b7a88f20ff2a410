#include "costa/sdo_block_upload.hpp"

#include "costa/od/little_endian.hpp"
#include "costa/sdo_block_segments.hpp"

namespace costa {
namespace {

constexpr size_t kSegmentBytes = 7;

// Client frames: ccs 5 in bits 7..5, cs in bits 1..0 (bit 2 of the initiate request: cc).
constexpr uint8_t kClientCommandMask = 0xE3;
constexpr uint8_t kEndResponse = 0xA1;       // cs 1
constexpr uint8_t kSubBlockResponse = 0xA2;  // cs 2
constexpr uint8_t kStartUpload = 0xA3;       // cs 3
// Server frames: scs 6 in bits 7..5.
constexpr uint8_t kInitiateResponse = 0xC6;  // sc 1 (CRC supported), s 1 (size), ss 0
constexpr uint8_t kEndRequest = 0xC1;        // n in bits 4..2, ss 1
constexpr uint8_t kLastSegment = 0x80;

}  // namespace

void SdoBlockUpload::start(const uint8_t* request, size_t size) noexcept {
  crc_.reset();
  crcDone_ = 0;
  size_ = size;
  blockStart_ = 0;
  blockSize_ = request[4];
  planned_ = 0;
  sent_ = 0;
  phase_ = Phase::kWaitStart;
  uint8_t response[8] = {kInitiateResponse, request[1], request[2], request[3]};
  storeU32(response + 4, static_cast<uint32_t>(size));
  channel_.send(response);
}

bool SdoBlockUpload::valid() const noexcept {
  if (phase_ == Phase::kDone) {
    return true;
  }
  const bool counts = blockSize_ >= 1U && blockSize_ <= kMaxBlockSize && planned_ <= blockSize_ &&
                      sent_ <= planned_ && blockStart_ <= size_ && crcDone_ <= size_;
  if (!counts || phase_ != Phase::kSubBlock) {
    return counts;
  }
  // Every planned segment starts within the value (the only segment of an empty one at 0).
  return planned_ >= 1U && blockStart_ + (planned_ - 1U) * kSegmentBytes <= size_;
}

AbortCode SdoBlockUpload::onRequest(const uint8_t* request) noexcept {
  const auto command = static_cast<uint8_t>(request[0] & kClientCommandMask);
  switch (phase_) {
    case Phase::kWaitStart:
      if (command == kStartUpload) {
        return beginSubBlock();
      }
      break;
    case Phase::kSubBlock:
      if (command == kSubBlockResponse) {
        return acknowledged(request[1], request[2]);
      }
      break;
    case Phase::kWaitEndResponse:
      if (command == kEndResponse) {
        phase_ = Phase::kDone;
        return AbortCode::kNone;
      }
      break;
    case Phase::kDone: break;
  }
  return AbortCode::kCommandSpecifier;
}

AbortCode SdoBlockUpload::beginSubBlock() noexcept {
  const size_t remaining = size_ - blockStart_;
  const uint8_t segments = remaining == 0U ? uint8_t{1} : blockSegments(remaining);
  planned_ = segments < blockSize_ ? segments : blockSize_;
  sent_ = 0;
  phase_ = Phase::kSubBlock;
  return pump();
}

AbortCode SdoBlockUpload::pump() noexcept {
  while (sending() && channel_.roomForBurst()) {
    const AbortCode sent = sendSegment(static_cast<uint8_t>(sent_ + 1U));
    if (sent != AbortCode::kNone) {
      return sent;
    }
    ++sent_;
  }
  return AbortCode::kNone;
}

AbortCode SdoBlockUpload::sendSegment(uint8_t sequence) noexcept {
  const size_t offset = blockStart_ + (sequence - 1U) * kSegmentBytes;
  const size_t remaining = size_ - offset;
  const size_t count = remaining < kSegmentBytes ? remaining : kSegmentBytes;
  const bool last = offset + count == size_;
  uint8_t segment[8] = {static_cast<uint8_t>((last ? kLastSegment : 0U) | sequence)};
  const AbortCode read = reader_.read(offset, segment + 1, count);
  if (read != AbortCode::kNone) {
    return read;
  }
  if (offset == crcDone_) {  // first time this segment is sent
    crc_.update(segment + 1, count);
    crcDone_ += count;
  }
  channel_.send(segment);
  return AbortCode::kNone;
}

AbortCode SdoBlockUpload::acknowledged(uint8_t sequence, uint8_t nextBlockSize) noexcept {
  if (sequence > sent_) {
    return AbortCode::kSequenceNumber;
  }
  if (nextBlockSize < 1U || nextBlockSize > kMaxBlockSize) {
    return AbortCode::kBlockSize;
  }
  const size_t covered = blockStart_ + planned_ * kSegmentBytes;  // end of this sub-block
  if (sequence == planned_ && covered >= size_) {
    sendEnd();
    return AbortCode::kNone;
  }
  blockStart_ += sequence * kSegmentBytes;
  blockSize_ = nextBlockSize;
  return beginSubBlock();
}

void SdoBlockUpload::sendEnd() noexcept {
  // blockStart_ is a multiple of 7 below size_ (or 0), and the last sub-block plans just the
  // segments left: what they span beyond size_ is the last segment's unused bytes (all 7 of the
  // one empty segment of a value of 0 bytes).
  const auto unused = static_cast<uint8_t>(blockStart_ + planned_ * kSegmentBytes - size_);
  // The initiate response announced CRC support (sc = 1), so the end frame carries the valid
  // CRC whether the client asked for it or not: CiA 301 makes it 0 only when unused, and masters
  // that check it whenever sc is set (without having set cc) accept a valid one either way.
  const uint16_t crc = crc_.value();
  const uint8_t request[8] = {static_cast<uint8_t>(kEndRequest | (unused << 2U)),
                              static_cast<uint8_t>(crc), static_cast<uint8_t>(crc >> 8U)};
  channel_.send(request);
  phase_ = Phase::kWaitEndResponse;
}

}  // namespace costa
