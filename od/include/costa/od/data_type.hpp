// CiA 301 basic data types as they appear in an EDS (DataType=0x0007 ...).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa::od {

enum class DataType : uint8_t {
  kBoolean = 0x0001,
  kInteger8 = 0x0002,
  kInteger16 = 0x0003,
  kInteger32 = 0x0004,
  kUnsigned8 = 0x0005,
  kUnsigned16 = 0x0006,
  kUnsigned32 = 0x0007,
  kReal32 = 0x0008,
  kVisibleString = 0x0009,
  kOctetString = 0x000A,
  kDomain = 0x000F,
  kReal64 = 0x0011,
  kInteger64 = 0x0015,
  kUnsigned64 = 0x001B,
};

namespace detail {
constexpr uint32_t typeBit(DataType t) noexcept {
  return static_cast<uint8_t>(t) < 32U ? uint32_t{1} << static_cast<uint8_t>(t) : 0U;
}
inline constexpr uint32_t kSignedTypes =
    typeBit(DataType::kInteger8) | typeBit(DataType::kInteger16) | typeBit(DataType::kInteger32) |
    typeBit(DataType::kInteger64);
inline constexpr uint32_t kUnsignedTypes =
    typeBit(DataType::kBoolean) | typeBit(DataType::kUnsigned8) | typeBit(DataType::kUnsigned16) |
    typeBit(DataType::kUnsigned32) | typeBit(DataType::kUnsigned64);
inline constexpr uint32_t kRealTypes = typeBit(DataType::kReal32) | typeBit(DataType::kReal64);
}  // namespace detail

// Each test is one bit test: these run on every access.

constexpr bool isSigned(DataType t) noexcept {
  return (detail::typeBit(t) & detail::kSignedTypes) != 0U;
}

constexpr bool isUnsigned(DataType t) noexcept {
  return (detail::typeBit(t) & detail::kUnsignedTypes) != 0U;
}

constexpr bool isReal(DataType t) noexcept {
  return (detail::typeBit(t) & detail::kRealTypes) != 0U;
}

/// Signed and unsigned integers (not BOOLEAN, whose values are 0 and 1 only).
constexpr bool isInteger(DataType t) noexcept {
  return (detail::typeBit(t) & (detail::kSignedTypes | detail::kUnsignedTypes) &
          ~detail::typeBit(DataType::kBoolean)) != 0U;
}

/// Integers, booleans and reals: values with a fixed size, limits and a numeric meaning.
constexpr bool isNumeric(DataType t) noexcept {
  return (detail::typeBit(t) &
          (detail::kSignedTypes | detail::kUnsignedTypes | detail::kRealTypes)) != 0U;
}

}  // namespace costa::od
