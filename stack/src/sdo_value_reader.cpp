#include "costa/sdo_value_reader.hpp"

#include "costa/od/bytes.hpp"
#include "costa/sdo_streaming.hpp"

namespace costa {

AbortCode SdoValueReader::begin(const od::EntryRef& ref, size_t* size) noexcept {
  ref_ = ref;
  streamed_ = sdoStreams(ref, bufferSize_);
  if (streamed_) {
    size_t produced = 0;
    const AbortCode sized = access_.readStream(ref, 0, buffer_, 0, &produced, &size_);
    if (sized != AbortCode::kNone) {
      return sized;
    }
  } else {
    const od::ObjectDictionary& dictionary = access_.dictionary();
    size_ = dictionary.read(ref, 0, buffer_, bufferSize_);
  }
  *size = size_;
  return AbortCode::kNone;
}

AbortCode SdoValueReader::read(size_t offset, uint8_t* destination, size_t count) noexcept {
  if (!streamed_) {
    if (offset + count > size_) {
      return AbortCode::kNoData;
    }
    copyBytes(destination, buffer_ + offset, count);
    return AbortCode::kNone;
  }
  size_t produced = 0;
  size_t total = 0;
  const AbortCode got = access_.readStream(ref_, offset, destination, count, &produced, &total);
  if (got != AbortCode::kNone) {
    return got;
  }
  return produced == count ? AbortCode::kNone : AbortCode::kNoData;
}

}  // namespace costa
