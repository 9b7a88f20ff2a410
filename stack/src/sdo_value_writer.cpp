#include "costa/sdo_value_writer.hpp"

#include "costa/od/bytes.hpp"
#include "costa/sdo_streaming.hpp"

namespace costa {
namespace {

// Early verdict on the indicated size of a buffered download.
AbortCode checkIndicatedSize(const od::EntryRef& ref, size_t size, size_t bufferSize) {
  const bool fixedSize = od::isNumeric(ref.type()) || ref.type() == od::DataType::kOctetString;
  if ((fixedSize || ref.type() == od::DataType::kVisibleString) && size > ref.size()) {
    return AbortCode::kLengthTooHigh;
  }
  if (fixedSize && size < ref.size()) {
    return AbortCode::kLengthTooLow;
  }
  return size > bufferSize ? AbortCode::kOutOfMemory : AbortCode::kNone;
}

}  // namespace

AbortCode SdoValueWriter::writeStreamWhole(const od::EntryRef& ref, const uint8_t* data,
                                           size_t length) noexcept {
  const AbortCode written = access_.writeStream(ref, 0, data, length, true, length);
  if (written != AbortCode::kNone) {
    access_.abortWriteStream(ref, written);
  }
  return written;
}

AbortCode SdoValueWriter::begin(const od::EntryRef& ref, size_t indicatedSize) noexcept {
  ref_ = &ref;
  streamed_ = sdoStreams(ref, bufferSize_);
  indicated_ = indicatedSize;
  received_ = 0;
  flushed_ = 0;
  streamOpen_ = false;
  if (!streamed_) {
    return indicatedSize == kSizeNotIndicated ? AbortCode::kNone
                                              : checkIndicatedSize(ref, indicatedSize, bufferSize_);
  }
  const AbortCode started = access_.writeStream(ref, 0, buffer_, 0, false, indicatedSize);
  if (started != AbortCode::kNone) {
    access_.abortWriteStream(ref, started);
    return started;
  }
  streamOpen_ = true;
  return AbortCode::kNone;
}

AbortCode SdoValueWriter::append(const uint8_t* data, size_t length) noexcept {
  // (No value reaches kSizeNotIndicated, SIZE_MAX: an unindicated size is never exceeded.)
  if (received_ + length > indicated_) {
    return AbortCode::kLengthMismatch;
  }
  // A buffered value must fit the buffer; a streamed one goes to its hook a bufferful at a time.
  // (After a refusal the transfer ends: what was copied of the refused bytes is never used.)
  size_t held = received_ - flushed_;  // bytes in the buffer
  while (length > 0U) {
    if (held == bufferSize_) {
      if (!streamed_) {
        return AbortCode::kLengthTooHigh;
      }
      const AbortCode flushed = flush(false);
      if (flushed != AbortCode::kNone) {
        return flushed;
      }
      held = 0;
    }
    const size_t space = bufferSize_ - held;
    const size_t count = length < space ? length : space;
    copyBytes(buffer_ + held, data, count);
    held += count;
    received_ += count;
    data += count;
    length -= count;
  }
  return AbortCode::kNone;
}

AbortCode SdoValueWriter::flush(bool last) noexcept {
  const size_t pending = received_ - flushed_;
  const AbortCode written =
      access_.writeStream(*ref_, flushed_, buffer_, pending, last, indicated_);
  if (written == AbortCode::kNone) {
    flushed_ = received_;
  }
  return written;
}

AbortCode SdoValueWriter::finish() noexcept {
  if (indicated_ != kSizeNotIndicated && received_ != indicated_) {
    return AbortCode::kLengthMismatch;
  }
  const AbortCode written = streamed_ ? flush(true) : access_.write(*ref_, buffer_, received_);
  if (written == AbortCode::kNone) {
    streamOpen_ = false;
  }
  return written;
}

size_t SdoValueWriter::room() const noexcept {
  if (indicated_ != kSizeNotIndicated) {
    return received_ < indicated_ ? indicated_ - received_ : 0U;
  }
  if (!streamed_) {
    return bufferSize_ - received_;
  }
  return SIZE_MAX;
}

}  // namespace costa
