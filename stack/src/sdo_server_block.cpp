// SdoServer's side of block transfers: initiation, the protocol switch threshold, and passing
// the transfer's frames to SdoBlockDownload / SdoBlockUpload.
#include "costa/od/little_endian.hpp"
#include "costa/sdo_server.hpp"

namespace costa {
namespace {

constexpr uint8_t kDownloadSubcommand = 0x01;  // cs of a block download request: 1 = end
constexpr uint8_t kUploadSubcommand = 0x03;    // cs of a block upload request: 0 = initiate
constexpr size_t kBlockSizeByte = 4;           // initiate block upload: blksize, then pst
constexpr size_t kProtocolSwitchByte = 5;

}  // namespace

bool SdoServer::blockSegmentsReady() const noexcept {
  return state_ == State::kBlockUpload && blockUpload_.sending() && channel_.roomForBurst();
}

bool SdoServer::blockTransferValid() const noexcept {
  if (state_ == State::kBlockDownload) {
    return !blockDownload_.finished() && blockDownload_.valid();
  }
  return state_ == State::kBlockUpload && !blockUpload_.finished() && blockUpload_.valid();
}

void SdoServer::queueBlockSegments() noexcept {
  afterBlockStep(blockUpload_.pump(), false);
}

void SdoServer::initiateBlockDownload(const uint8_t* request) noexcept {
  if ((request[0] & kDownloadSubcommand) != 0U) {  // the end of a transfer that is not running
    sendAbort(0, 0, AbortCode::kCommandSpecifier);
    return;
  }
  index_ = loadU16(request + 1);
  subIndex_ = request[3];
  AbortCode started = access_.locateForWrite(index_, subIndex_, &ref_);
  if (started == AbortCode::kNone) {
    started = blockDownload_.start(ref_, request);
  }
  if (started != AbortCode::kNone) {
    refuse(started);
    return;
  }
  state_ = State::kBlockDownload;
  armTimeout();
}

AbortCode SdoServer::beginUpload(const ReadRequest& details, size_t* size) noexcept {
  const AbortCode prepared = access_.prepareRead(index_, subIndex_, details, &ref_);
  return prepared != AbortCode::kNone ? prepared : reader_.begin(ref_, size);
}

void SdoServer::initiateBlockUpload(const uint8_t* request) noexcept {
  if ((request[0] & kUploadSubcommand) != 0U) {  // a step of a transfer that is not running
    sendAbort(0, 0, AbortCode::kCommandSpecifier);
    return;
  }
  index_ = loadU16(request + 1);
  subIndex_ = request[3];
  const uint8_t blockSize = request[kBlockSizeByte];
  if (blockSize < 1U || blockSize > SdoBlockUpload::kMaxBlockSize) {
    refuse(AbortCode::kBlockSize);
    return;
  }
  // Bytes 4..7 carry blksize and pst here, not request data for the hook.
  size_t size = 0;
  const AbortCode begun = beginUpload(ReadRequest{}, &size);
  if (begun != AbortCode::kNone) {
    refuse(begun);
    return;
  }
  const uint8_t threshold = request[kProtocolSwitchByte];
  if (threshold != 0U && size <= threshold) {
    answerUpload(size);  // expedited or segmented instead
    return;
  }
  blockUpload_.start(request, size);
  state_ = State::kBlockUpload;
  armTimeout();
  if (blockSegmentsReady()) {
    clock_.schedule(atOnce(lastCall_));
  }
}

void SdoServer::continueBlock(const uint8_t* request) noexcept {
  if (state_ == State::kBlockDownload) {
    const AbortCode result = blockDownload_.onRequest(request);
    afterBlockStep(result, blockDownload_.finished());
  } else {
    const AbortCode result = blockUpload_.onRequest(request);
    afterBlockStep(result, blockUpload_.finished());
  }
  if (blockSegmentsReady()) {
    clock_.schedule(atOnce(lastCall_));  // a sub-block to send
  }
}

void SdoServer::afterBlockStep(AbortCode result, bool finished) noexcept {
  if (result != AbortCode::kNone) {
    abortTransfer(result);
  } else if (finished) {
    endTransfer(AbortCode::kNone);
  } else {
    armTimeout();
  }
}

}  // namespace costa
