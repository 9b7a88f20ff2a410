#include "costa/sdo_server.hpp"

#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

// Client command specifiers (bits 7..5 of byte 0), CiA 301 7.2.4.3.
constexpr uint8_t kCcsDownloadSegment = 0;
constexpr uint8_t kCcsInitiateDownload = 1;
constexpr uint8_t kCcsInitiateUpload = 2;
constexpr uint8_t kCcsUploadSegment = 3;
constexpr uint8_t kCcsAbort = 4;
constexpr uint8_t kAbortRequest = 0x80;  // byte 0 of an abort: ccs 4, nothing else
constexpr uint8_t kCcsBlockUpload = 5;
constexpr uint8_t kCcsBlockDownload = 6;

constexpr uint8_t kScsInitiateDownloadResponse = 0x60;
constexpr uint8_t kScsDownloadSegmentResponse = 0x20;

constexpr size_t kSegmentBytes = 7;

// Bytes a download with e=1, s=0 carries: the value's own size when it fits (a number or an
// OCTET_STRING of up to 4 bytes); else 4, a VISIBLE_STRING's trailing NULs trimmed.
size_t unspecifiedExpeditedLength(const od::EntryRef& ref, const uint8_t* data) {
  const bool fixedSize = od::isNumeric(ref.type()) || ref.type() == od::DataType::kOctetString;
  if (fixedSize && ref.size() <= 4U) {
    return ref.size();
  }
  size_t length = 4;
  if (ref.type() == od::DataType::kVisibleString) {
    while (length > 0U && data[length - 1U] == 0U) {
      --length;
    }
  }
  return length;
}

}  // namespace

SdoServer::SdoServer(ObjectAccess& access, TransmitPath& tx, const SdoProfile& profile,
                     NodeClock& clock, uint8_t* buffer, size_t bufferSize,
                     Microseconds timeout) noexcept
    : channel_(tx, profile),
      timeout_(timeout),
      access_(access),
      clock_(clock),
      profile_(profile),
      reader_(access, buffer, bufferSize),
      writer_(access, buffer, bufferSize),
      blockDownload_(channel_, writer_),
      blockUpload_(channel_, reader_) {}

void SdoServer::reset() noexcept {
  endTransfer(AbortCode::kGeneral);
}

bool SdoServer::valid() const noexcept {
  if (state_ == State::kIdle) {
    return deadline_ == kNever;
  }
  if (deadline_ == kNever || (toggleBit_ & ~kToggleBit) != 0U) {
    return false;
  }
  switch (state_) {
    case State::kDownloadSegments: return true;
    case State::kUploadSegments:
      return done_ < reader_.size() || (done_ == 0U && reader_.size() == 0U);
    case State::kBlockDownload:
    case State::kBlockUpload:
      if constexpr (features::kSdoBlockTransfer) {
        return blockTransferValid();
      }
      break;  // without block transfers, the server is never in these states
    case State::kIdle: break;
  }
  return false;
}

Microseconds SdoServer::nextDeadline() const noexcept {
  // Idle, deadline_ is kNever (valid()); where speed counts, idle returns at once.
  if (kExpandFastPaths && state_ == State::kIdle) {
    return kNever;
  }
  if constexpr (features::kSdoBlockTransfer) {
    if (blockSegmentsReady()) {
      return lastCall_;
    }
  }
  return deadline_;
}

void SdoServer::process(Microseconds now) noexcept {
  lastCall_ = now;
  // Never while idle: deadline_ is kNever (valid()); where speed counts, idle is tested first.
  if ((!kExpandFastPaths || state_ != State::kIdle) && reached(now, deadline_)) {
    abortTransfer(AbortCode::kTimeout);
    return;
  }
  if constexpr (features::kSdoBlockTransfer) {
    if (blockSegmentsReady()) {
      queueBlockSegments();
    }
  }
}

bool SdoServer::isClientAbort(const uint8_t* request) const noexcept {
  // Inside a block download, 0x81..0x9F are last segments with sequence numbers 1..31. (Without
  // block transfers, the server is never in that state.)
  return features::kSdoBlockTransfer && state_ == State::kBlockDownload
             ? request[0] == kAbortRequest
             : (request[0] >> 5U) == kCcsAbort;
}

bool SdoServer::locateDownload(const uint8_t* request) noexcept {
  index_ = loadU16(request + 1);
  subIndex_ = request[3];
  const AbortCode located = access_.locateForWrite(index_, subIndex_, &ref_);
  if (located != AbortCode::kNone) {
    refuse(located);
    return false;
  }
  return true;
}

COSTA_SDO_SERVE_PART void SdoServer::initiateDownload(const uint8_t* request) noexcept {
  if (!locateDownload(request)) {  // (one locate for both kinds: expanded once)
    return;
  }
  if ((request[0] & 0x02U) == 0U) {
    initiateSegmentedDownload(request);
    return;
  }
  // Expedited: the value is in bytes 4..7; s = 1 gives its length, else the entry does.
  const size_t length = (request[0] & 0x01U) != 0U ? 4U - ((request[0] >> 2U) & 0x03U)
                                                   : unspecifiedExpeditedLength(ref_, request + 4);
  const AbortCode written = writer_.writeWhole(ref_, request + 4, length);
  // The answer straight into a frame where speed counts; built for size, every write takes
  // finishExpedited(), which answers the same bytes.
  if (!kExpandFastPaths || written != AbortCode::kNone) {
    finishExpedited(request, written);
    return;
  }
  CanFrame response;
  channel_.address(response);
  copyBytes(response.data, request, 4);  // the multiplexer as asked
  response.data[0] = kScsInitiateDownloadResponse;
  channel_.send(response);
}

void SdoServer::initiateSegmentedDownload(const uint8_t* request) noexcept {
  const bool sizeIndicated = (request[0] & 0x01U) != 0U;
  if (!sizeIndicated && (request[0] & 0x0CU) != 0U && profile_.expeditedByCountAlone) {
    downloadByCountAlone(request);
    return;
  }
  const AbortCode begun =
      writer_.begin(ref_, sizeIndicated ? indicatedSize(loadU32(request + 4)) : kSizeNotIndicated);
  if (begun == AbortCode::kNone) {
    state_ = State::kDownloadSegments;
    toggleBit_ = 0;
    armTimeout();
  }
  answerDownload(begun);
}

void SdoServer::downloadByCountAlone(const uint8_t* request) noexcept {
  finishExpedited(request,
                  writer_.writeWhole(ref_, request + 4, 4U - ((request[0] >> 2U) & 0x03U)));
}

void SdoServer::finishExpedited(const uint8_t* request, AbortCode verdict) noexcept {
  if (verdict == AbortCode::kLengthTooHigh && profile_.expeditedKeepsLowBytes &&
      od::isNumeric(ref_.type())) {
    // More bytes than the number has: little-endian, its low bytes come first.
    verdict = writer_.writeWhole(ref_, request + 4, ref_.size());
  }
  answerDownload(verdict);
}

void SdoServer::answerDownload(AbortCode verdict) noexcept {
  if (verdict != AbortCode::kNone) {
    refuse(verdict);
    return;
  }
  answer(kScsInitiateDownloadResponse);
}

// NOLINTNEXTLINE(misc-no-recursion): calls onRequest() once with 8 bytes, which never come back
bool SdoServer::onShortRequest(const CanFrame& frame, Microseconds now) noexcept {
  const uint8_t shortest = profile_.shortestRequest == 0U ? 1U : profile_.shortestRequest;
  if (frame.rtr || frame.dlc >= 8U || frame.dlc < shortest) {
    return false;  // CiA 301: an SDO frame has 8 bytes; RTR frames are no SDO requests
  }
  CanFrame whole = frame;
  fillBytes(whole.data + frame.dlc, 0, 8U - frame.dlc);  // the bytes it lacks count as 0
  whole.dlc = 8;
  return onRequest(whole, now);
}

// NOLINTNEXTLINE(misc-no-recursion): onShortRequest() calls back once, with 8 bytes
bool SdoServer::onRequest(const CanFrame& frame, Microseconds now) noexcept {
  if (frame.dlc != 8U || frame.rtr) {
    if constexpr (!features::kQuirkProfiles) {
      if (profile_.shortestRequest >= 8U) {
        return false;  // the fixed profile serves 8 bytes only (CiA 301): the frame is ignored
      }
    }
    return onShortRequest(frame, now);
  }
  serve(frame.data, now);
  return true;
}

void SdoServer::serve(const uint8_t* request, Microseconds now) noexcept {
  lastCall_ = now;
  const auto ccs = static_cast<uint8_t>(request[0] >> 5U);
  // The frequent requests first: a new transfer, the next segment of an upload. Built for
  // speed, each is a call of its own, so that this dispatch needs no stack frame: a segment does
  // not pay for what an initiate needs (built for size, the rarer handlers, the initiated
  // download among them, are expanded here: COSTA_SDO_SERVE_PART).
  if (state_ == State::kIdle && ccs == kCcsInitiateUpload) {
    initiateUpload(request);
  } else if (state_ == State::kIdle && ccs == kCcsInitiateDownload) {
    initiateDownload(request);
  } else if (state_ == State::kUploadSegments && ccs == kCcsUploadSegment) {
    if constexpr (kExpandFastPaths) {
      uploadPaddedSegment(request);
    } else {
      uploadSegment(request);  // built for size, every segment takes the one general path
    }
  } else {
    onOtherRequest(request, ccs);
  }
}

COSTA_SDO_SERVE_PART void SdoServer::onOtherRequest(const uint8_t* request, uint8_t ccs) noexcept {
  if (isClientAbort(request)) {
    endTransfer(static_cast<AbortCode>(loadU32(request + 4)));
    return;
  }
  switch (state_) {
    case State::kIdle: initiate(request, ccs); break;
    case State::kDownloadSegments:
      if (ccs == kCcsDownloadSegment) {
        downloadSegment(request);
      } else {
        abortTransfer(AbortCode::kCommandSpecifier);
      }
      break;
    case State::kUploadSegments: abortTransfer(AbortCode::kCommandSpecifier); break;
    case State::kBlockDownload:
    case State::kBlockUpload:
      if constexpr (features::kSdoBlockTransfer) {
        continueBlock(request);
      }
      break;
  }
}

COSTA_SDO_SERVE_PART void SdoServer::initiate(const uint8_t* request, uint8_t ccs) noexcept {
  if constexpr (features::kSdoBlockTransfer) {
    if (ccs == kCcsBlockDownload) {
      initiateBlockDownload(request);
      return;
    }
    if (ccs == kCcsBlockUpload) {
      initiateBlockUpload(request);
      return;
    }
  }  // without block transfers, their requests are unknown command specifiers (below)
  const bool segment = ccs == kCcsDownloadSegment || ccs == kCcsUploadSegment;
  index_ = segment ? uint16_t{0} : loadU16(request + 1);  // a segment has no transfer to continue
  subIndex_ = segment ? uint8_t{0} : request[3];
  refuse(AbortCode::kCommandSpecifier);
}

COSTA_SDO_SERVE_PART void SdoServer::downloadSegment(const uint8_t* request) noexcept {
  if ((request[0] & kToggleBit) != toggleBit_) {
    abortTransfer(AbortCode::kToggleBit);
    return;
  }
  const size_t count = kSegmentBytes - ((request[0] >> 1U) & 0x07U);
  const bool last = (request[0] & 0x01U) != 0U;
  AbortCode verdict = writer_.append(request + 1, count);
  if (verdict == AbortCode::kNone && last) {
    verdict = writer_.finish();
  }
  if (verdict != AbortCode::kNone) {
    abortTransfer(verdict);
    return;
  }
  // Every segment's response, the last one's too: nothing but the toggle of the segment.
  channel_.send(static_cast<uint8_t>(kScsDownloadSegmentResponse | toggleBit_), 0, 0, 0);
  afterSegment(last);
}

void SdoServer::refuse(AbortCode code) noexcept {
  sendAbort(index_, subIndex_, code);
}

void SdoServer::abortTransfer(AbortCode code) noexcept {
  refuse(code);
  endTransfer(code);
}

void SdoServer::sendAbort(uint16_t index, uint8_t subIndex, AbortCode code) noexcept {
  channel_.sendAbort(index, subIndex, code);
}

}  // namespace costa
