#include "costa/sdo_block_download.hpp"

#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"
#include "costa/sdo_block_segments.hpp"

namespace costa {
namespace {

constexpr size_t kSegmentBytes = 7;

// Initiate request (client): ccs 6 in bits 7..5, cc (CRC) bit 2, s (size) bit 1, cs bit 0.
constexpr uint8_t kClientCrc = 0x04;
constexpr uint8_t kClientSizeIndicated = 0x02;
// End request (client): ccs 6, n (unused bytes) in bits 4..2, cs = 1.
constexpr uint8_t kEndMask = 0xE1;
constexpr uint8_t kEndRequest = 0xC1;
// Server frames: scs 5 in bits 7..5; sc (CRC) bit 2; ss in bits 1..0.
constexpr uint8_t kInitiateResponse = 0xA4;  // ss 0, sc 1: this server always checks the CRC
constexpr uint8_t kEndResponse = 0xA1;       // ss 1
constexpr uint8_t kSubBlockResponse = 0xA2;  // ss 2
constexpr uint8_t kLastSegment = 0x80;

}  // namespace

AbortCode SdoBlockDownload::start(const od::EntryRef& ref, const uint8_t* request) noexcept {
  const size_t size = (request[0] & kClientSizeIndicated) != 0U
                          ? indicatedSize(loadU32(request + 4))
                          : kSizeNotIndicated;
  const AbortCode begun = writer_.begin(ref, size);
  if (begun != AbortCode::kNone) {
    return begun;
  }
  crcUsed_ = (request[0] & kClientCrc) != 0U;
  crc_.reset();
  lastSequence_ = 0;
  previousSegment_ = 0;
  blockSize_ = nextBlockSize();
  phase_ = Phase::kSegments;
  const uint8_t response[8] = {kInitiateResponse, request[1], request[2], request[3], blockSize_};
  channel_.send(response);
  return AbortCode::kNone;
}

AbortCode SdoBlockDownload::onRequest(const uint8_t* request) noexcept {
  switch (phase_) {
    case Phase::kSegments: return segment(request);
    case Phase::kEnd: return end(request);
    case Phase::kDone: break;
  }
  return AbortCode::kCommandSpecifier;
}

AbortCode SdoBlockDownload::segment(const uint8_t* request) noexcept {
  const auto sequence = static_cast<uint8_t>(request[0] & 0x7FU);
  const bool last = (request[0] & kLastSegment) != 0U;
  // The segment that closed a sub-block, received twice. (A sub-block of one segment is closed
  // by one that leaves the value no room, or by the last one: the next segment 1 is taken as
  // such, and aborts when it does not fit.)
  if (lastSequence_ == 0U && sequence > 1U && request[0] == previousSegment_) {
    return AbortCode::kNone;
  }
  if (sequence == 0U || sequence > blockSize_) {
    return AbortCode::kSequenceNumber;
  }
  previousSegment_ = request[0];
  if (sequence != lastSequence_ + 1U) {
    // Dropped, like every later segment of this sub-block: the acknowledgement at its end
    // makes the client repeat from the last segment received in sequence.
    if (last || sequence == blockSize_) {
      acknowledge(lastSequence_);
    }
    return AbortCode::kNone;
  }
  lastSequence_ = sequence;
  if (last) {
    copyBytes(lastSegment_, request + 1, kSegmentBytes);  // its length comes with the end frame
    acknowledge(sequence);
    phase_ = Phase::kEnd;
    return AbortCode::kNone;
  }
  const AbortCode appended = writer_.append(request + 1, kSegmentBytes);
  if (appended != AbortCode::kNone) {
    return appended;
  }
  crc_.update(request + 1, kSegmentBytes);
  if (sequence == blockSize_) {
    acknowledge(sequence);
  }
  return AbortCode::kNone;
}

AbortCode SdoBlockDownload::end(const uint8_t* request) noexcept {
  if ((request[0] & kEndMask) != kEndRequest) {
    // The last segment received twice is ignored (unless its first byte reads as an end
    // request: sequence numbers 65, 67 ... 95); anything else is out of place.
    return request[0] == previousSegment_ ? AbortCode::kNone : AbortCode::kCommandSpecifier;
  }
  const size_t length = kSegmentBytes - ((request[0] >> 2U) & 0x07U);
  const AbortCode appended = writer_.append(lastSegment_, length);
  if (appended != AbortCode::kNone) {
    return appended;
  }
  crc_.update(lastSegment_, length);
  if (crcUsed_ && crc_.value() != loadU16(request + 1)) {
    return AbortCode::kCrc;
  }
  const AbortCode written = writer_.finish();
  if (written != AbortCode::kNone) {
    return written;
  }
  phase_ = Phase::kDone;
  const uint8_t response[8] = {kEndResponse};
  channel_.send(response);
  return AbortCode::kNone;
}

void SdoBlockDownload::acknowledge(uint8_t sequence) noexcept {
  blockSize_ = nextBlockSize();
  lastSequence_ = 0;
  const uint8_t response[8] = {kSubBlockResponse, sequence, blockSize_};
  channel_.send(response);
}

uint8_t SdoBlockDownload::nextBlockSize() const noexcept {
  const uint8_t segments = blockSegments(writer_.room());  // at most kMaxBlockSize
  return segments < 1U ? uint8_t{1} : segments;
}

}  // namespace costa
