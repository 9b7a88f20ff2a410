// The sending end of an SDO upload: a snapshot of the value in the SDO buffer, or reads from the
// entry's hook for streamed entries (see sdo_streaming.hpp).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/object_access.hpp"
#include "costa/od/bytes.hpp"
#include "costa/sdo_streaming.hpp"

namespace costa {

/// One upload at a time. Any byte range may be read again (block upload retransmission). No
/// allocation; every call is O(count) plus the hook's cost.
class SdoValueReader {
 public:
  SdoValueReader(ObjectAccess& access, uint8_t* buffer, size_t bufferSize) noexcept
      : access_(access), buffer_(buffer), bufferSize_(bufferSize) {}

  /// Starts an upload of `ref` (already prepared with ObjectAccess::prepareRead): copies a
  /// buffered value into the buffer (the snapshot the whole transfer sends), or asks the
  /// streaming hook for the value's size. Sets `*size` to the bytes to transfer. `ref` is the
  /// transfer's own (the server's), which stays as it is until the transfer ends.
  AbortCode begin(const od::EntryRef& ref, size_t* size) noexcept {
    streamed_ = sdoStreams(ref, bufferSize_);
    AbortCode begun = AbortCode::kNone;
    if (streamed_) {
      ref_ = &ref;  // the hook is asked for every piece
      padded_ = false;
      begun = beginStreamed();
    } else {
      size_ = access_.dictionary().readWhole(ref, buffer_);
      padded_ = kExpandFastPaths && size_ + kZeroTail <= bufferSize_;  // (for the fast segments)
      if (padded_) {
        fillBytes(buffer_ + size_, 0, kZeroTail);
      }
    }
    *size = size_;
    return begun;
  }

  /// Copies bytes [offset, offset + count) of the value: the hook's refusal, or kNoData when the
  /// value ends before `offset + count` (a streamed value that shrank during the transfer).
  COSTA_SHARED_INLINE AbortCode read(size_t offset, uint8_t* destination, size_t count) noexcept {
    if (streamed_) {
      return readStreamed(offset, destination, count);
    }
    if (offset + count > size_) {
      return AbortCode::kNoData;
    }
    copyBytes(destination, buffer_ + offset, count);
    return AbortCode::kNone;
  }

  /// Zeros that follow a snapshot when the buffer has room for them: whoever sends it in
  /// segments of up to 7 bytes may copy 7 bytes for each, the last one too. (Built for size,
  /// none: every segment is read by its length.)
  static constexpr size_t kZeroTail = 7;
  /// The bytes of the value begun: its snapshot's, or the size the streaming hook gave.
  size_t size() const noexcept { return size_; }
  /// The value is not streamed and kZeroTail zeros follow its snapshot.
  bool padded() const noexcept { return padded_; }
  /// The snapshot of a value that is not streamed: its bytes in the SDO buffer.
  const uint8_t* snapshot() const noexcept { return buffer_; }

 private:
  /// Asks the streaming hook for the value's size (size_).
  AbortCode beginStreamed() noexcept;
  AbortCode readStreamed(size_t offset, uint8_t* destination, size_t count) noexcept;

  ObjectAccess& access_;
  uint8_t* buffer_;
  size_t bufferSize_;
  const od::EntryRef* ref_ = nullptr;  ///< a streamed value's entry
  bool streamed_ = false;
  bool padded_ = false;  ///< kZeroTail zeros follow the snapshot
  size_t size_ = 0;
};

inline AbortCode SdoValueReader::beginStreamed() noexcept {
  size_t produced = 0;
  return access_.readStream(*ref_, 0, buffer_, 0, &produced, &size_);
}

inline AbortCode SdoValueReader::readStreamed(size_t offset, uint8_t* destination,
                                              size_t count) noexcept {
  size_t produced = 0;
  size_t total = 0;
  const AbortCode got = access_.readStream(*ref_, offset, destination, count, &produced, &total);
  if (got != AbortCode::kNone) {
    return got;
  }
  return produced == count ? AbortCode::kNone : AbortCode::kNoData;
}

}  // namespace costa
