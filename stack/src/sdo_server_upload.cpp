// SdoServer's uploads: the initiate (an expedited answer, or the start of a segmented upload of
// the value's snapshot) and the segments.
#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"
#include "costa/sdo_server.hpp"

namespace costa {
namespace {

constexpr uint8_t kScsInitiateUploadResponse = 0x40;
constexpr size_t kSegmentBytes = 7;

// Byte 0 of an upload segment response of `count` bytes (`toggleBit`: 0 or 0x10).
uint8_t segmentHeader(uint8_t toggleBit, size_t count, bool last) noexcept {
  return static_cast<uint8_t>(toggleBit | ((kSegmentBytes - count) << 1U) | (last ? 1U : 0U));
}

}  // namespace

void SdoServer::initiateUpload(const uint8_t* request) noexcept {
  ReadRequest details;
  copyBytes(details.requestData, request + 4, 4);
  index_ = loadU16(request + 1);
  subIndex_ = request[3];
  if constexpr (features::kSdoBlockTransfer && !kExpandFastPaths) {
    size_t size = 0;
    const AbortCode begun = beginUpload(details, &size);  // the block upload's copy
    if (begun != AbortCode::kNone) {
      refuse(begun);
      return;
    }
    answerUpload(size);
  } else {
    const AbortCode prepared = access_.prepareRead(index_, subIndex_, details, &ref_);
    if (prepared != AbortCode::kNone) {
      refuse(prepared);
      return;
    }
    // The usual read straight from the dictionary into the answer; built for size, every read
    // takes the reader, which answers the same bytes.
    if (kExpandFastPaths && od::isNumeric(ref_.type()) && ref_.size() <= 4U) {
      answerExpedited(request);
      return;
    }
    size_t size = 0;
    const AbortCode begun = reader_.begin(ref_, &size);
    if (begun != AbortCode::kNone) {
      refuse(begun);
      return;
    }
    answerUpload(size);
  }
}

COSTA_HOT_INLINE void SdoServer::answerExpedited(const uint8_t* request) noexcept {
  const size_t size = ref_.size();
  CanFrame response;
  channel_.address(response);
  copyBytes(response.data, request, 4);  // the multiplexer (index, sub-index) as asked
  response.data[0] =
      profile_.expeditedUpload == ExpeditedUploadFormat::kSizeIndicated
          ? static_cast<uint8_t>(kScsInitiateUploadResponse | ((4U - size) << 2U) | 0x03U)
          : static_cast<uint8_t>(kScsInitiateUploadResponse | 0x02U);
  access_.dictionary().readNumber(ref_, response.data + 4);
  channel_.send(response);
}

void SdoServer::answerUpload(size_t size) noexcept {
  if (size >= 1U && size <= 4U) {
    uint8_t value[4] = {};  // a value of fewer than 4 bytes is followed by zeros
    const AbortCode read = reader_.read(0, value, size);
    if (read != AbortCode::kNone) {
      refuse(read);
      return;
    }
    answer(profile_.expeditedUpload == ExpeditedUploadFormat::kSizeIndicated
               ? static_cast<uint8_t>(kScsInitiateUploadResponse | ((4U - size) << 2U) | 0x03U)
               : static_cast<uint8_t>(kScsInitiateUploadResponse | 0x02U),
           loadU32(value));
    return;
  }
  done_ = 0;
  toggleBit_ = 0;
  state_ = State::kUploadSegments;
  armTimeout();
  answer(kScsInitiateUploadResponse | 0x01U, static_cast<uint32_t>(size));
}

void SdoServer::uploadPaddedSegment(const uint8_t* request) noexcept {
  if ((request[0] & kToggleBit) != toggleBit_ || !reader_.padded()) {
    uploadSegment(request);
    return;
  }
  CanFrame response;
  channel_.address(response);
  // Seven bytes whatever the count: past the value's end, the zeros that follow the snapshot.
  static_assert(SdoValueReader::kZeroTail >= kSegmentBytes, "a whole segment past the end");
  copyBytes(response.data + 1, reader_.snapshot() + done_, kSegmentBytes);
  const size_t remaining = reader_.size() - done_;
  if (remaining > kSegmentBytes) {
    response.data[0] = toggleBit_;  // 7 bytes, more to come
    done_ += kSegmentBytes;
    toggleBit_ ^= kToggleBit;
    extendTimeout();
  } else {
    response.data[0] = segmentHeader(toggleBit_, remaining, true);
    done_ = reader_.size();
    endTransfer(AbortCode::kNone);
  }
  channel_.send(response);
}

void SdoServer::uploadSegment(const uint8_t* request) noexcept {
  if ((request[0] & kToggleBit) != toggleBit_) {
    abortTransfer(AbortCode::kToggleBit);
    return;
  }
  const size_t remaining = reader_.size() - done_;
  const bool last = remaining <= kSegmentBytes;
  const size_t count = last ? remaining : kSegmentBytes;
  if constexpr (kExpandFastPaths) {  // the segment read straight into the response
    CanFrame response;
    channel_.address(response);
    response.data[0] = segmentHeader(toggleBit_, count, last);
    const AbortCode read = reader_.read(done_, response.data + 1, count);
    if (read != AbortCode::kNone) {
      abortTransfer(read);
      return;
    }
    done_ += count;
    channel_.send(response);
  } else {  // built for size: through the channel's one frame builder
    // Bytes 1..7 of the response: the segment's, then zeros.
    alignas(4) uint8_t bytes[8] = {};
    const AbortCode read = reader_.read(done_, bytes + 1, count);
    if (read != AbortCode::kNone) {
      abortTransfer(read);
      return;
    }
    done_ += count;
    channel_.send(segmentHeader(toggleBit_, count, last), loadU16(bytes + 1), bytes[3],
                  loadU32(bytes + 4));
  }
  afterSegment(last);
}

}  // namespace costa
