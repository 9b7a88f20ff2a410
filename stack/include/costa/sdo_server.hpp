// SDO server (CiA 301 7.2.4): expedited, segmented and block upload and download on the default
// SDO channel 0x600+id / 0x580+id, or on an additional server's CAN-IDs (sdo_servers.hpp). Block
// transfers are optional (features::kSdoBlockTransfer): compiled out, their initiate requests are
// unknown command specifiers (0x05040001).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/compiled_out.hpp"
#include "costa/features.hpp"
#include "costa/hot_path.hpp"
#include "costa/node_clock.hpp"
#include "costa/object_access.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/sdo_block_download.hpp"
#include "costa/sdo_block_upload.hpp"
#include "costa/sdo_channel.hpp"
#include "costa/sdo_profile.hpp"
#include "costa/sdo_value_reader.hpp"
#include "costa/sdo_value_writer.hpp"
#include "costa/time.hpp"
#include "costa/transmit_path.hpp"

// A handler that serve() alone calls (directly or through onOtherRequest()): built for size,
// expanded into its caller, which saves a call and a stack frame each; built for speed, a call
// of its own, so that serve() needs no stack frame for the frequent requests.
#if defined(__OPTIMIZE_SIZE__)
#define COSTA_SDO_SERVE_PART [[gnu::always_inline]] inline
#else
#define COSTA_SDO_SERVE_PART
#endif

namespace costa {

class SdoServer {
 public:
  /// `buffer` holds a transfer's value; DOMAINs and values larger than the buffer are streamed
  /// through the entry's hook instead (ObjectHook::readStream/writeStream, sdo_streaming.hpp).
  /// `timeout` applies to every wait for the client.
  /// `clock` is told of every deadline a request sets.
  SdoServer(ObjectAccess& access, TransmitPath& tx, const SdoProfile& profile, NodeClock& clock,
            uint8_t* buffer, size_t bufferSize, Microseconds timeout) noexcept;

  void setNodeId(uint8_t nodeId) noexcept { channel_.setNodeId(nodeId); }
  /// Responses on `canId` instead (an additional server's COB-ID server -> client).
  void setResponseCanId(uint16_t canId) noexcept { channel_.setCanId(canId); }

  /// Handles a frame received on 0x600+id. RTR frames and frames with a DLC other than 8 are
  /// ignored, as CiA 301 requires (returns false for them), except requests of at least
  /// SdoProfile::shortestRequest bytes, whose missing bytes count as 0. O(log n) in the
  /// dictionary size plus the hook's cost.
  [[nodiscard]] bool onRequest(const CanFrame& frame, Microseconds now) noexcept;
  /// onRequest() for a request of 8 bytes, not RTR, which the server always uses (the node's
  /// way for its own server's requests, Node::onFrame).
  void serve(const uint8_t* request, Microseconds now) noexcept;

  /// Aborts a transfer that has been silent longer than the timeout (0x05040000); queues
  /// further segments of a block upload sub-block as the transmit queue has room.
  void process(Microseconds now) noexcept;

  /// Next time process() has work, or kNever. While a block upload sub-block has segments left
  /// and the transmit queue has room, that is the time of the last call: call again at once.
  Microseconds nextDeadline() const noexcept;

  /// Drops any transfer in progress without a frame (NMT reset, stopped state). A streamed
  /// download is reported to its hook (abortWriteStream, kGeneral).
  void reset() noexcept;

  bool busy() const noexcept { return state_ != State::kIdle; }

  /// Consistency of the transfer state (for tests and fuzzing): idle without a deadline, or a
  /// transfer with a deadline, a toggle of 0 or 1, an upload position within the value, and a
  /// block transfer whose own state is valid. O(1), changes nothing.
  bool valid() const noexcept;

 private:
  /// The toggle bit of a segment's byte 0 (CiA 301 7.2.4.3).
  static constexpr uint8_t kToggleBit = 0x10;

  enum class State : uint8_t {
    kIdle,
    kDownloadSegments,
    kUploadSegments,
    kBlockDownload,
    kBlockUpload
  };

  /// A request other than the frequent ones: aborts, download segments, block transfers, and
  /// requests that do not fit the transfer's state.
  COSTA_SDO_SERVE_PART void onOtherRequest(const uint8_t* request, uint8_t ccs) noexcept;
  /// The deadline of the client's next request, from now (lastCall_: every request, every
  /// process() sets it first, so the handlers need no `now` of their own); the node's clock is
  /// told.
  COSTA_SHARED_INLINE void armTimeout() noexcept {
    deadline_ = at(lastCall_, timeout_);
    clock_.schedule(deadline_);
  }
  /// armTimeout() within a transfer whose start armed it. Time does not go back, so the
  /// deadline moves only later; the clock's next time is no later than deadline_ from that
  /// armTimeout() on (schedule() then, and every process() that reaches it sets it from
  /// nextDeadline()), so it need not be told again.
  void extendTimeout() noexcept { deadline_ = at(lastCall_, timeout_); }
  /// A request while no transfer runs: starts one, or aborts.
  COSTA_SDO_SERVE_PART void initiate(const uint8_t* request, uint8_t ccs) noexcept;
  /// A request shorter than 8 bytes, or an RTR frame: served as 8 bytes, the missing ones 0,
  /// when the profile serves its length (SdoProfile::shortestRequest: onRequest() once more,
  /// with 8 bytes), else ignored (false).
  [[gnu::noinline]] bool onShortRequest(const CanFrame& frame, Microseconds now) noexcept;
  /// An initiate download request while no transfer runs.
  COSTA_SDO_SERVE_PART void initiateDownload(const uint8_t* request) noexcept;
  /// Locates the entry of an initiate download request (index_, subIndex_, ref_); false after
  /// the abort when it cannot be written.
  COSTA_HOT_INLINE bool locateDownload(const uint8_t* request) noexcept;
  /// initiateDownload() of a located entry, not expedited: a segmented download begins (or,
  /// for some devices, an expedited one by its byte count alone). Out of line: the expedited
  /// download keeps fewer registers.
  [[gnu::noinline]] void initiateSegmentedDownload(const uint8_t* request) noexcept;
  /// A byte count without e and s: an expedited download of that count, for a device that
  /// reads the count alone (SdoProfile::expeditedByCountAlone).
  [[gnu::noinline]] void downloadByCountAlone(const uint8_t* request) noexcept;
  /// An expedited download off the usual path, given the write's `verdict`: a number refused
  /// as too long is written again as its low bytes (SdoProfile::expeditedKeepsLowBytes); then
  /// the response or the abort.
  void finishExpedited(const uint8_t* request, AbortCode verdict) noexcept;
  /// The initiate download response, or the abort of the request when `verdict` is one.
  void answerDownload(AbortCode verdict) noexcept;
  COSTA_SDO_SERVE_PART void downloadSegment(const uint8_t* request) noexcept;
  /// An initiate upload request while no transfer runs.
  void initiateUpload(const uint8_t* request) noexcept;
  /// Locates the entry of an upload (index_, subIndex_) for reading, into ref_, and begins the
  /// reader (`*size`): the refusal, if any. Built for size with block transfers, this one copy
  /// (sdo_server_block.cpp) of the dictionary's and the hooks' checks and of the reader's start
  /// serves the segmented and the block upload; else initiateUpload() expands them.
  [[gnu::noinline]] AbortCode beginUpload(const ReadRequest& details, size_t* size) noexcept;
  /// The initiate upload response, expedited or segmented, for a value the reader has begun.
  void answerUpload(size_t size) noexcept;
  /// The expedited answer to an upload of a numeric value of up to 4 bytes.
  COSTA_HOT_INLINE void answerExpedited(const uint8_t* request) noexcept;
  /// The next segment of an upload, built for speed. Itself only the usual segment: seven bytes
  /// of a snapshot followed by zeros (SdoValueReader::padded()); uploadSegment() the others.
  void uploadPaddedSegment(const uint8_t* request) noexcept;
  /// The next segment of an upload, any segment (built for size, every one): a streamed
  /// value's segment, one of a value that fills the buffer, a wrong toggle bit.
  [[gnu::noinline]] void uploadSegment(const uint8_t* request) noexcept;
  bool isClientAbort(const uint8_t* request) const noexcept;
  // Block transfers (sdo_server_block.cpp, compiled only with features::kSdoBlockTransfer).
  /// A block upload sub-block has segments to queue and the transmit queue has room for them.
  bool blockSegmentsReady() const noexcept;
  /// valid() for a running block transfer.
  bool blockTransferValid() const noexcept;
  void queueBlockSegments() noexcept;
  void initiateBlockDownload(const uint8_t* request) noexcept;
  void initiateBlockUpload(const uint8_t* request) noexcept;
  void continueBlock(const uint8_t* request) noexcept;
  void afterBlockStep(AbortCode result, bool finished) noexcept;

  void sendAbort(uint16_t index, uint8_t subIndex, AbortCode code) noexcept;
  /// The response to the request of the transfer (index_, subIndex_): `command`, the
  /// multiplexer, `data` in bytes 4..7.
  COSTA_SHARED_INLINE void answer(uint8_t command, uint32_t data = 0) noexcept {
    channel_.send(command, index_, subIndex_, data);
  }
  /// The abort of the request of the transfer (index_, subIndex_), which leaves the state as it
  /// is: a request refused while no transfer runs.
  void refuse(AbortCode code) noexcept;
  /// refuse(), then the transfer is over.
  void abortTransfer(AbortCode code) noexcept;
  /// The transfer is over (`reason` kNone: completed): idle, no deadline; an open streamed
  /// download is told `reason`.
  COSTA_SHARED_INLINE void endTransfer(AbortCode reason) noexcept {
    writer_.cancel(reason);
    state_ = State::kIdle;
    deadline_ = kNever;
  }
  /// After a segment's response: the transfer ends with the `last` segment, else waits for the
  /// next one, of the other toggle.
  COSTA_SHARED_INLINE void afterSegment(bool last) noexcept {
    if (last) {
      endTransfer(AbortCode::kNone);
    } else {
      toggleBit_ ^= kToggleBit;
      extendTimeout();
    }
  }

  // The channel first, then the small fields: the channel's address is the server's own, which
  // every response passes as is, and Thumb-1 loads and stores reach a byte only 31 bytes from
  // the object's start (a word 124), so every field behind the reader and the writer would cost
  // an address computation at each use.
  SdoChannel channel_;
  State state_ = State::kIdle;
  uint8_t toggleBit_ = 0;  ///< the toggle of the next segment, where it lies in byte 0: 0 or 0x10
  uint8_t subIndex_ = 0;
  uint16_t index_ = 0;
  size_t done_ = 0;  ///< Bytes uploaded so far (of reader_.size()).
  Microseconds deadline_ = kNever;
  Microseconds lastCall_ = 0;  ///< `now` of the latest call.
  Microseconds timeout_;

  ObjectAccess& access_;
  NodeClock& clock_;
  const SdoProfile& profile_;
  od::EntryRef ref_;
  SdoValueReader reader_;
  SdoValueWriter writer_;
  ServiceIf<features::kSdoBlockTransfer, SdoBlockDownload, CompiledOut> blockDownload_;
  ServiceIf<features::kSdoBlockTransfer, SdoBlockUpload, CompiledOut> blockUpload_;
};

}  // namespace costa
