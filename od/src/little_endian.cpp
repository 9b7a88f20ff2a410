#include "costa/od/little_endian.hpp"

#include "costa/od/bytes.hpp"

namespace costa {

uint64_t loadNative(const uint8_t* address, size_t size) noexcept {
  switch (size) {
    case 1: return *address;
    case 2: return loadAligned<uint16_t>(address);
    case 4: return loadAligned<uint32_t>(address);
    case 8: return loadAligned<uint64_t>(address);
    default: return 0;
  }
}

void storeNative(uint8_t* address, uint64_t raw, size_t size) noexcept {
  if (size == 8U) {
    storeAligned(address, raw);
  } else {
    storeNative32(address, static_cast<uint32_t>(raw), size);
  }
}

void storeNative32(uint8_t* address, uint32_t raw, size_t size) noexcept {
  switch (size) {
    case 1: *address = static_cast<uint8_t>(raw); break;
    case 2: storeAligned(address, static_cast<uint16_t>(raw)); break;
    case 4: storeAligned(address, raw); break;
    default: break;
  }
}

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

void addLittleEndian(uint8_t* bytes, size_t length, uint8_t addend) noexcept {
  uint32_t carry = addend;
  for (size_t i = 0; i < length && carry != 0U; ++i) {
    carry += bytes[i];
    bytes[i] = static_cast<uint8_t>(carry);
    carry >>= 8U;
  }
}

int64_t signExtend(uint64_t raw, size_t length) noexcept {
  if (length == 0U) {
    return 0;
  }
  if (length >= 8U) {
    return static_cast<int64_t>(raw);
  }
  // With the bits above the sign cleared, flipping the sign bit and subtracting its weight
  // leaves a positive value as it is and takes 2^(8 length) from a negative one; done in 32 bits
  // on the half that holds the sign (no 64-bit shift by a variable to link).
  auto low = static_cast<uint32_t>(raw);
  auto high = static_cast<uint32_t>(raw >> 32U);
  if (length <= 4U) {
    const uint32_t sign = 1U << (8U * length - 1U);
    low = ((low & ((sign << 1U) - 1U)) ^ sign) - sign;
    high = (low & 0x80000000U) != 0U ? 0xFFFFFFFFU : 0U;
  } else {
    const uint32_t sign = 1U << (8U * (length - 4U) - 1U);
    high = ((high & ((sign << 1U) - 1U)) ^ sign) - sign;
  }
  return static_cast<int64_t>((static_cast<uint64_t>(high) << 32U) | low);
}

}  // namespace costa
