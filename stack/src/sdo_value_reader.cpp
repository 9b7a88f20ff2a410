#include "costa/sdo_value_reader.hpp"

namespace costa {

AbortCode SdoValueReader::beginStreamed() noexcept {
  size_t produced = 0;
  return access_.readStream(*ref_, 0, buffer_, 0, &produced, &size_);
}

}  // namespace costa
