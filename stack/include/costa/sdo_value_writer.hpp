// The receiving end of an SDO download: collects a value whole in the SDO buffer, or streams it
// to the entry's hook (see sdo_streaming.hpp).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/object_access.hpp"
#include "costa/object_hook.hpp"
#include "costa/sdo_streaming.hpp"

namespace costa {

/// One download at a time. A buffered value is written (through the hook's write()) only when
/// complete, so an aborted transfer leaves the old value. A streamed value goes to
/// ObjectAccess::writeStream() in buffer-sized pieces; an aborted one is reported with
/// abortWriteStream(). No allocation; every call is O(length) plus the hook's cost.
class SdoValueWriter {
 public:
  SdoValueWriter(ObjectAccess& access, uint8_t* buffer, size_t bufferSize) noexcept
      : access_(access), buffer_(buffer), bufferSize_(bufferSize) {}

  /// Writes a value that arrived in one piece (expedited download).
  COSTA_HOT_INLINE AbortCode writeWhole(const od::EntryRef& ref, const uint8_t* data,
                                        size_t length) noexcept {
    if (!sdoStreams(ref, bufferSize_)) {
      return access_.write(ref, data, length);
    }
    return writeStreamWhole(ref, data, length);
  }

  /// Starts a segmented or block download of `ref` with `indicatedSize` bytes (or
  /// kSizeNotIndicated): refuses a size the entry or the buffer cannot take, or lets a streaming
  /// hook refuse. Nothing is left to cancel after a refusal. `ref` is the transfer's own (the
  /// server's), which stays as it is until the transfer ends.
  AbortCode begin(const od::EntryRef& ref, size_t indicatedSize) noexcept;

  /// Adds the next `length` bytes: kLengthMismatch beyond the indicated size, kLengthTooHigh
  /// beyond the buffer, or the streaming hook's refusal.
  AbortCode append(const uint8_t* data, size_t length) noexcept;

  /// Completes the value: kLengthMismatch when it differs from the indicated size, else the
  /// write's (or the streaming hook's last call's) verdict. The transfer is over on success;
  /// after a failure the caller cancels it.
  AbortCode finish() noexcept;

  /// Ends an unfinished download: a streaming hook is told to discard. No-op when none is open
  /// (the usual case: every transfer's end cancels, the end of an upload too).
  void cancel(AbortCode reason) noexcept {
    if (streamOpen_) {
      access_.abortWriteStream(*ref_, reason);
    }
    streamOpen_ = false;
  }

  /// Bytes received so far.
  size_t received() const noexcept { return received_; }
  /// Bytes the value may still take: the rest of the indicated size, of the buffer, or SIZE_MAX
  /// for a streamed value of unindicated size.
  size_t room() const noexcept;

 private:
  AbortCode flush(bool last) noexcept;
  AbortCode writeStreamWhole(const od::EntryRef& ref, const uint8_t* data, size_t length) noexcept;

  ObjectAccess& access_;
  uint8_t* buffer_;
  size_t bufferSize_;
  const od::EntryRef* ref_ = nullptr;  ///< the entry of the download begun
  bool streamOpen_ = false;  ///< a streamed download begun, not finished: cancel() tells its hook
  bool streamed_ = false;
  size_t indicated_ = kSizeNotIndicated;
  size_t received_ = 0;  ///< Bytes appended.
  size_t flushed_ = 0;   ///< Bytes already handed to the streaming hook.
};

}  // namespace costa
