#include "sfxt.hpp"

namespace costa::solo {
namespace {

constexpr double kScale = static_cast<double>(kSfxtOne);  // 2^17: scaling by it is exact

// Scaled values at or beyond these round to a raw value outside INT32.
constexpr double kFirstAboveRange = 2147483647.5;
constexpr double kFirstBelowRange = -2147483648.5;

}  // namespace

int32_t sfxtFromDouble(double value) noexcept {
  if (value != value) {  // NaN
    return 0;
  }
  const double scaled = value * kScale;
  if (scaled >= kFirstAboveRange) {
    return kSfxtRawMax;
  }
  if (scaled <= kFirstBelowRange) {
    return kSfxtRawMin;
  }
  // In range: truncation fits INT32, and the fraction is exact (it is the low bits of scaled).
  const auto whole = static_cast<int32_t>(scaled);
  const double fraction = scaled - static_cast<double>(whole);
  if (fraction >= 0.5) {
    return whole + 1;
  }
  if (fraction <= -0.5) {
    return whole - 1;
  }
  return whole;
}

double sfxtToDouble(int32_t raw) noexcept {
  return static_cast<double>(raw) / kScale;
}

uint32_t int32ToData(int32_t value) noexcept {
  return static_cast<uint32_t>(value);
}

int32_t dataToInt32(uint32_t data) noexcept {
  if (data <= 0x7FFFFFFFU) {
    return static_cast<int32_t>(data);
  }
  // Negative: the magnitude minus one is the bitwise complement, which fits INT32.
  return -static_cast<int32_t>(~data) - 1;
}

void storeData(uint32_t data, uint8_t* bytes) noexcept {
  for (unsigned i = 0; i < 4U; ++i) {
    bytes[i] = static_cast<uint8_t>(data >> (8U * i));
  }
}

uint32_t loadData(const uint8_t* bytes) noexcept {
  uint32_t data = 0;
  for (unsigned i = 0; i < 4U; ++i) {
    data |= static_cast<uint32_t>(bytes[i]) << (8U * i);
  }
  return data;
}

}  // namespace costa::solo
