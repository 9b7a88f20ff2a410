// CRC-32/ISO-HDLC (the CRC of zlib, PNG and Ethernet), computed incrementally.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {
namespace detail {

struct Crc32NibbleTable {
  uint32_t entries[16];
};

/// Remainders of the 16 nibble values, reflected polynomial 0xEDB88320.
constexpr Crc32NibbleTable makeCrc32NibbleTable() noexcept {
  Crc32NibbleTable table{};
  for (uint32_t nibble = 0; nibble < 16U; ++nibble) {
    uint32_t remainder = nibble;
    for (int bit = 0; bit < 4; ++bit) {
      remainder = (remainder & 1U) != 0U ? (remainder >> 1U) ^ 0xEDB88320U : remainder >> 1U;
    }
    table.entries[nibble] = remainder;
  }
  return table;
}

inline constexpr Crc32NibbleTable kCrc32NibbleTable = makeCrc32NibbleTable();

}  // namespace detail

/// Parameters: polynomial 0x04C11DB7 (processed reflected, 0xEDB88320), initial value and final
/// XOR 0xFFFFFFFF, input and output reflected. Check value: "123456789" gives 0xCBF43926.
///
/// Processes a byte as two nibbles through a 16-entry table (64 bytes of ROM), so it needs no
/// RAM table and no start-up initialisation. Usable in constant expressions.
class Crc32 {
 public:
  /// Continues the CRC over `length` more bytes.
  constexpr void update(const uint8_t* data, size_t length) noexcept {
    for (size_t i = 0; i < length; ++i) {
      update(data[i]);
    }
  }

  constexpr void update(uint8_t byte) noexcept {
    state_ ^= byte;
    state_ = (state_ >> 4U) ^ detail::kCrc32NibbleTable.entries[state_ & 0x0FU];
    state_ = (state_ >> 4U) ^ detail::kCrc32NibbleTable.entries[state_ & 0x0FU];
  }

  /// CRC of all bytes passed so far (the object may continue to be updated).
  constexpr uint32_t value() const noexcept { return ~state_; }

 private:
  uint32_t state_ = 0xFFFFFFFFU;
};

/// CRC-32/ISO-HDLC of one buffer.
constexpr uint32_t crc32(const uint8_t* data, size_t length) noexcept {
  Crc32 crc;
  crc.update(data, length);
  return crc.value();
}

}  // namespace costa
