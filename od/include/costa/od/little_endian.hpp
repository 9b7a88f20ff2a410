// Little-endian encoding of integers, the byte order of every CANopen value on the wire.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// The CPU stores integers least significant byte first, as the wire does: values can be
/// copied between the dictionary and frames without conversion.
inline constexpr bool kLittleEndianHost = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

/// The CPU loads and stores a 2- or 4-byte integer at any address (x86, Cortex-M3/M4/M7), so a
/// value in a frame is one load; without it (Cortex-M0/M0+), byte by byte.
#if defined(__ARM_FEATURE_UNALIGNED) || defined(__x86_64__) || defined(__i386__) || \
    defined(__aarch64__)
inline constexpr bool kUnalignedAccess = true;
#else
inline constexpr bool kUnalignedAccess = false;
#endif

/// Built for size (-Os): the inline fast paths of the dictionary's reads and writes are left out
/// and every access takes the one out-of-line path, which does the same with a call more.
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool kExpandFastPaths = false;
#else
inline constexpr bool kExpandFastPaths = true;
#endif

inline uint16_t loadU16(const uint8_t* source) noexcept {
  if constexpr (kLittleEndianHost && kUnalignedAccess) {
    uint16_t v = 0;
    __builtin_memcpy(&v, source, 2);
    return v;
  }
  return static_cast<uint16_t>(source[0] | (source[1] << 8U));
}

inline uint32_t loadU32(const uint8_t* source) noexcept {
  if constexpr (kLittleEndianHost && kUnalignedAccess) {
    uint32_t v = 0;
    __builtin_memcpy(&v, source, 4);
    return v;
  }
  return static_cast<uint32_t>(source[0]) | (static_cast<uint32_t>(source[1]) << 8U) |
         (static_cast<uint32_t>(source[2]) << 16U) | (static_cast<uint32_t>(source[3]) << 24U);
}

inline void storeU16(uint8_t* destination, uint16_t value) noexcept {
  destination[0] = static_cast<uint8_t>(value);
  destination[1] = static_cast<uint8_t>(value >> 8U);
}

inline void storeU32(uint8_t* destination, uint32_t value) noexcept {
  if constexpr (kLittleEndianHost && kUnalignedAccess) {
    __builtin_memcpy(destination, &value, 4);
    return;
  }
  destination[0] = static_cast<uint8_t>(value);
  destination[1] = static_cast<uint8_t>(value >> 8U);
  destination[2] = static_cast<uint8_t>(value >> 16U);
  destination[3] = static_cast<uint8_t>(value >> 24U);
}

/// Writes the low `length` bytes of `value`, least significant first. `length` <= 8.
void storeLittleEndian(uint8_t* destination, uint64_t value, size_t length) noexcept;

/// Reads `length` bytes, least significant first, zero-extended. `length` <= 8.
uint64_t loadLittleEndianBytes(const uint8_t* source, size_t length) noexcept;

/// loadLittleEndianBytes(); the sizes of numbers are one load where the CPU allows it.
inline uint64_t loadLittleEndian(const uint8_t* source, size_t length) noexcept {
  if constexpr (kExpandFastPaths && kLittleEndianHost && kUnalignedAccess) {
    switch (length) {
      case 1: return *source;
      case 2: return loadU16(source);
      case 4: return loadU32(source);
      default: break;
    }
  }
  return loadLittleEndianBytes(source, length);
}

/// The native bytes (CPU byte order) of a numeric value in a dictionary's value block: 1, 2, 4
/// or 8 of them, aligned as loadAligned() wants, zero-extended to 64 bits; 0 for another size.
uint64_t loadNative(const uint8_t* address, size_t size) noexcept;
/// Stores the low `size` bytes of `raw` as loadNative() loads them; nothing for another size.
void storeNative(uint8_t* address, uint64_t raw, size_t size) noexcept;
/// storeNative() of a number of 1, 2 or 4 bytes; nothing for another size.
void storeNative32(uint8_t* address, uint32_t raw, size_t size) noexcept;

/// Adds `addend` (a node-id) to the little-endian number of `length` bytes at `bytes`, carrying
/// into its higher bytes; what would go beyond its top byte is dropped, as in the number's own
/// width. In 8-bit steps: no 64-bit arithmetic, whatever the length.
void addLittleEndian(uint8_t* bytes, size_t length, uint8_t addend) noexcept;

/// Sign-extends the low `length` bytes of `raw`. `length` in 1..8 (0 gives 0).
int64_t signExtend(uint64_t raw, size_t length) noexcept;

}  // namespace costa
