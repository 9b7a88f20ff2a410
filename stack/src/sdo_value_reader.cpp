#include "costa/sdo_value_reader.hpp"

namespace costa {

AbortCode SdoValueReader::beginStreamed() noexcept {
  size_t produced = 0;
  return access_.readStream(*ref_, 0, buffer_, 0, &produced, &size_);
}

AbortCode SdoValueReader::readStreamed(size_t offset, uint8_t* destination, size_t count) noexcept {
  size_t produced = 0;
  size_t total = 0;
  const AbortCode got = access_.readStream(*ref_, offset, destination, count, &produced, &total);
  if (got != AbortCode::kNone) {
    return got;
  }
  return produced == count ? AbortCode::kNone : AbortCode::kNoData;
}

}  // namespace costa
