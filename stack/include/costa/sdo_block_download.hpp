// SDO block download, server side (CiA 301 7.2.4.3.9 - 7.2.4.3.12): sub-blocks of up to 127
// numbered segments, acknowledged by sequence number, closed by an end frame with the number of
// unused bytes and the CRC.
#pragma once

#include <stdint.h>

#include "costa/crc16.hpp"
#include "costa/sdo_channel.hpp"
#include "costa/sdo_value_writer.hpp"

namespace costa {

/// One transfer at a time, driven by SdoServer, which handles aborts from the client and the
/// timeout. Data goes to the SdoValueWriter as it arrives in sequence, except the last segment,
/// whose length is only known from the end frame; the value is completed only after the CRC
/// (when both sides use it) matched.
///
/// A segment out of sequence is dropped, and so is every later one of its sub-block; at the
/// sub-block's end (its last sequence number, or the segment marked last) the server
/// acknowledges the last segment received in sequence, and the client repeats from there. When
/// the sub-block's last segment is the one lost, nothing marks the end: the transfer times out.
///
/// The segment that closed a sub-block, received again before the next sub-block's first
/// segment (a CAN controller may deliver a frame twice), is ignored: it neither closes the new
/// sub-block nor aborts the transfer, and after the last segment the end frame is still
/// awaited. Exceptions: sequence number 1 (a sub-block of one segment) is taken as the next
/// sub-block's first; a last segment numbered 65, 67 ... 95 reads as an end request (its first
/// byte matches 110xxxx1) and is answered as one. When every segment of the next sub-block but
/// its closing one is lost and that one has the same number, the transfer times out instead of
/// being acknowledged with 0.
class SdoBlockDownload {
 public:
  SdoBlockDownload(SdoChannel& channel, SdoValueWriter& writer) noexcept
      : channel_(channel), writer_(writer) {}

  /// Handles an initiate block download request (ccs 6, cs 0) for the located, writable `ref`:
  /// starts the writer and answers with the server's block size. Returns the refusal, if any.
  AbortCode start(const od::EntryRef& ref, const uint8_t* request) noexcept;

  /// Handles a request of the running transfer (not an abort): a segment or the end frame.
  /// Returns kNone to go on, else the code to abort with.
  AbortCode onRequest(const uint8_t* request) noexcept;

  /// The end frame was answered: the value is written.
  bool finished() const noexcept { return phase_ == Phase::kDone; }

  /// Consistency of a running transfer: a block size of 1..127 and a sequence number within
  /// it. O(1).
  bool valid() const noexcept {
    return phase_ == Phase::kDone ||
           (blockSize_ >= 1U && blockSize_ <= kMaxBlockSize && lastSequence_ <= blockSize_);
  }

  static constexpr uint8_t kMaxBlockSize = 127;

 private:
  enum class Phase : uint8_t { kSegments, kEnd, kDone };

  AbortCode segment(const uint8_t* request) noexcept;
  AbortCode end(const uint8_t* request) noexcept;
  void acknowledge(uint8_t sequence) noexcept;
  uint8_t nextBlockSize() const noexcept;

  SdoChannel& channel_;
  SdoValueWriter& writer_;
  Phase phase_ = Phase::kDone;
  bool crcUsed_ = false;
  Crc16 crc_;
  uint8_t blockSize_ = 0;     ///< Segments in the current sub-block.
  uint8_t lastSequence_ = 0;  ///< Last segment received in sequence in this sub-block.
  /// Byte 0 of the last segment received (0: none yet). While no segment of the next sub-block
  /// has arrived, it is that of the segment that closed the previous one.
  uint8_t previousSegment_ = 0;
  uint8_t lastSegment_[7] = {};
};

}  // namespace costa
