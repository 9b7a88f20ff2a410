// Little-endian encoding of integers, the byte order of every CANopen value on the wire.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// The CPU stores integers least significant byte first, as the wire does: values can be
/// copied between the dictionary and frames without conversion.
inline constexpr bool kLittleEndianHost = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

/// Writes the low `length` bytes of `value`, least significant first. `length` <= 8.
inline void storeLittleEndian(uint8_t* destination, uint64_t value, size_t length) noexcept {
  for (size_t i = 0; i < length; ++i) {
    destination[i] = static_cast<uint8_t>(value >> (8U * i));
  }
}

/// Reads `length` bytes, least significant first, zero-extended. `length` <= 8. The sizes of
/// numbers are one load on a little-endian CPU.
inline uint64_t loadLittleEndian(const uint8_t* source, size_t length) noexcept {
  if (kLittleEndianHost) {
    switch (length) {
      case 1: return *source;
      case 2: {
        uint16_t v = 0;
        __builtin_memcpy(&v, source, 2);
        return v;
      }
      case 4: {
        uint32_t v = 0;
        __builtin_memcpy(&v, source, 4);
        return v;
      }
      case 8: {
        uint64_t v = 0;
        __builtin_memcpy(&v, source, 8);
        return v;
      }
      default: break;
    }
  }
  uint64_t value = 0;
  for (size_t i = 0; i < length; ++i) {
    value |= static_cast<uint64_t>(source[i]) << (8U * i);
  }
  return value;
}

inline uint16_t loadU16(const uint8_t* source) noexcept {
  return static_cast<uint16_t>(loadLittleEndian(source, 2));
}

inline uint32_t loadU32(const uint8_t* source) noexcept {
  return static_cast<uint32_t>(loadLittleEndian(source, 4));
}

/// Sign-extends the low `length` bytes of `raw`. `length` in 1..8 (0 gives 0).
inline int64_t signExtend(uint64_t raw, size_t length) noexcept {
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
