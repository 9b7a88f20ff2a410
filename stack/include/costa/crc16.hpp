// CRC-16 of CiA 301 SDO block transfers: polynomial x^16 + x^12 + x^5 + 1 (0x1021), initial
// value 0, no reflection, no final XOR (the CRC-16/XMODEM parameters). "123456789" gives 0x31C3.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// Incremental: feed the data in pieces of any size, in order. Bitwise (no table), so it costs
/// no ROM; eight shift steps per byte.
class Crc16 {
 public:
  static constexpr uint16_t kPolynomial = 0x1021;

  constexpr void update(uint8_t byte) noexcept {
    value_ = static_cast<uint16_t>(value_ ^ (static_cast<uint16_t>(byte) << 8U));
    for (int bit = 0; bit < 8; ++bit) {
      const bool carry = (value_ & 0x8000U) != 0U;
      value_ = static_cast<uint16_t>(value_ << 1U);
      if (carry) {
        value_ = static_cast<uint16_t>(value_ ^ kPolynomial);
      }
    }
  }

  constexpr void update(const uint8_t* data, size_t length) noexcept {
    for (size_t i = 0; i < length; ++i) {
      update(data[i]);
    }
  }

  constexpr uint16_t value() const noexcept { return value_; }
  constexpr void reset() noexcept { value_ = 0; }

 private:
  uint16_t value_ = 0;
};

/// CRC of one whole block of data.
constexpr uint16_t crc16(const uint8_t* data, size_t length) noexcept {
  Crc16 crc;
  crc.update(data, length);
  return crc.value();
}

}  // namespace costa
