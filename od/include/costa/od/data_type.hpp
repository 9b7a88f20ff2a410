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

constexpr bool isSigned(DataType t) noexcept {
  return t == DataType::kInteger8 || t == DataType::kInteger16 || t == DataType::kInteger32 ||
         t == DataType::kInteger64;
}

constexpr bool isUnsigned(DataType t) noexcept {
  return t == DataType::kBoolean || t == DataType::kUnsigned8 || t == DataType::kUnsigned16 ||
         t == DataType::kUnsigned32 || t == DataType::kUnsigned64;
}

constexpr bool isReal(DataType t) noexcept {
  return t == DataType::kReal32 || t == DataType::kReal64;
}

/// Integers, booleans and reals: values with a fixed size, limits and a numeric meaning.
constexpr bool isNumeric(DataType t) noexcept {
  return isSigned(t) || isUnsigned(t) || isReal(t);
}

}  // namespace costa::od
