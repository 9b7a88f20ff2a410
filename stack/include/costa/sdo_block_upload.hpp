// SDO block upload, server side (CiA 301 7.2.4.3.13 - 7.2.4.3.16): the server sends sub-blocks
// of the client's block size, the client acknowledges by sequence number, the server closes
// with the number of unused bytes and the CRC.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/crc16.hpp"
#include "costa/sdo_channel.hpp"
#include "costa/sdo_value_reader.hpp"

namespace costa {

/// One transfer at a time, driven by SdoServer, which handles aborts from the client, the
/// timeout and the protocol switch threshold. A sub-block may be longer than the transmit queue:
/// its segments are queued while there is room (SdoChannel::roomForBurst) and the rest by
/// pump(), which the server calls from process(). Segments the client did not acknowledge are
/// read again from the SdoValueReader and repeated.
class SdoBlockUpload {
 public:
  SdoBlockUpload(SdoChannel& channel, SdoValueReader& reader) noexcept
      : channel_(channel), reader_(reader) {}

  /// Answers an initiate block upload request (ccs 5, cs 0, block size already checked) for a
  /// value of `size` bytes that the reader has begun.
  void start(const uint8_t* request, size_t size) noexcept;

  /// Handles a request of the running transfer (not an abort): start, sub-block
  /// acknowledgement, end response. Returns kNone to go on, else the code to abort with.
  AbortCode onRequest(const uint8_t* request) noexcept;

  /// Queues segments of the current sub-block while the transmit queue has room. Returns the
  /// reader's refusal, if any.
  AbortCode pump() noexcept;

  /// Segments of the current sub-block wait to be queued.
  bool sending() const noexcept { return phase_ == Phase::kSubBlock && sent_ < planned_; }
  /// The client confirmed the end: the transfer is complete.
  bool finished() const noexcept { return phase_ == Phase::kDone; }

  /// Consistency of a running transfer: the client's block size of 1..127, no more segments
  /// planned than it and no more sent than planned, the sub-block and the CRC within the value.
  /// O(1).
  bool valid() const noexcept;

  static constexpr uint8_t kMaxBlockSize = 127;

 private:
  enum class Phase : uint8_t { kWaitStart, kSubBlock, kWaitEndResponse, kDone };

  AbortCode beginSubBlock() noexcept;
  AbortCode acknowledged(uint8_t sequence, uint8_t nextBlockSize) noexcept;
  AbortCode sendSegment(uint8_t sequence) noexcept;
  void sendEnd() noexcept;

  SdoChannel& channel_;
  SdoValueReader& reader_;
  Phase phase_ = Phase::kDone;
  Crc16 crc_;
  size_t crcDone_ = 0;     ///< Bytes already in the CRC (segments sent at least once).
  size_t size_ = 0;        ///< Bytes of the value.
  size_t blockStart_ = 0;  ///< Offset of the current sub-block's first byte.
  uint8_t blockSize_ = 0;  ///< Segments per sub-block, as the client asked.
  uint8_t planned_ = 0;    ///< Segments in the current sub-block.
  uint8_t sent_ = 0;       ///< Segments of the current sub-block queued so far.
};

}  // namespace costa
