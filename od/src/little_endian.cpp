#include "costa/od/little_endian.hpp"

namespace costa {

void storeLittleEndian(uint8_t* destination, uint64_t value, size_t length) noexcept {
  const auto low = static_cast<uint32_t>(value);
  const auto high = static_cast<uint32_t>(value >> 32U);
  for (size_t i = 0; i < length; ++i) {
    const uint32_t word = i < 4U ? low : high;
    destination[i] = static_cast<uint8_t>(word >> (8U * (i & 3U)));
  }
}

uint64_t loadLittleEndianBytes(const uint8_t* source, size_t length) noexcept {
  uint32_t low = 0;
  uint32_t high = 0;
  for (size_t i = 0; i < length; ++i) {
    const uint32_t byte = static_cast<uint32_t>(source[i]) << (8U * (i & 3U));
    if (i < 4U) {
      low |= byte;
    } else {
      high |= byte;
    }
  }
  return (static_cast<uint64_t>(high) << 32U) | low;
}

int64_t signExtend(uint64_t raw, size_t length) noexcept {
  if (length == 0U) {
    return 0;
  }
  if (length >= 8U) {
    return static_cast<int64_t>(raw);
  }
  const uint64_t sign = uint64_t{1} << (8U * length - 1U);
  const uint64_t mask = (uint64_t{1} << (8U * length)) - 1U;
  raw &= mask;
  return (raw & sign) != 0U ? static_cast<int64_t>(raw | ~mask) : static_cast<int64_t>(raw);
}

}  // namespace costa
