// The sending end of an SDO upload: a snapshot of the value in the SDO buffer, or reads from the
// entry's hook for streamed entries (see sdo_streaming.hpp).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/object_access.hpp"

namespace costa {

/// One upload at a time. Any byte range may be read again (block upload retransmission). No
/// allocation; every call is O(count) plus the hook's cost.
class SdoValueReader {
 public:
  SdoValueReader(ObjectAccess& access, uint8_t* buffer, size_t bufferSize) noexcept
      : access_(access), buffer_(buffer), bufferSize_(bufferSize) {}

  /// Starts an upload of `ref` (already prepared with ObjectAccess::prepareRead): copies a
  /// buffered value into the buffer, or asks the streaming hook for the value's size. Sets
  /// `*size` to the bytes to transfer.
  AbortCode begin(const od::EntryRef& ref, size_t* size) noexcept;

  /// Copies bytes [offset, offset + count) of the value: the hook's refusal, or kNoData when a
  /// streamed value ends before `offset + count` (it shrank during the transfer).
  AbortCode read(size_t offset, uint8_t* destination, size_t count) noexcept;

  /// The snapshot of a value that is not streamed (its bytes in the SDO buffer), else null.
  const uint8_t* snapshot() const noexcept { return streamed_ ? nullptr : buffer_; }

 private:
  ObjectAccess& access_;
  uint8_t* buffer_;
  size_t bufferSize_;
  od::EntryRef ref_;
  bool streamed_ = false;
  size_t size_ = 0;
};

}  // namespace costa
