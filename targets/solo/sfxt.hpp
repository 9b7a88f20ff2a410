// The SOLO data formats (manual lines 1619-1784): Sfxt(32-17) fixed point, INT32 and UINT32,
// each carried as one 32-bit data field, least significant byte first.
//
// Sfxt(32-17) is a signed 32-bit two's complement integer with 17 fractional bits: the value is
// raw / 2^17, from -16384 (raw 0x80000000) to 16383.99999237 (raw 0x7FFFFFFF) in steps of
// 2^-17 = 0.00000762939.
//
// Conversion to fixed point rounds to the nearest step (ties away from zero) and saturates at
// the two ends. The manual's own procedure (lines 1686-1701) truncates instead and, for negative
// values, omits the final "+1" of the two's complement, so it can land up to two steps away from
// the nearest value (docs/errata-solo.md, A2 and A3). Conversion from fixed point is exact: every
// raw value is a double.
//
// Freestanding: no heap, no exceptions, no library calls; plain double arithmetic only.
#pragma once

#include <stdint.h>

namespace costa::solo {

/// Fractional bits of Sfxt(32-17).
constexpr int kSfxtFractionBits = 17;
/// Raw value of 1.0.
constexpr int32_t kSfxtOne = int32_t{1} << kSfxtFractionBits;
/// Smallest and largest raw values; sfxtFromDouble() saturates at these.
constexpr int32_t kSfxtRawMin = INT32_MIN;
constexpr int32_t kSfxtRawMax = INT32_MAX;

/// Raw Sfxt(32-17) value nearest to `value` (ties away from zero). Values beyond the range
/// give kSfxtRawMin / kSfxtRawMax (infinities included); NaN gives 0.
int32_t sfxtFromDouble(double value) noexcept;

/// The value a raw Sfxt(32-17) stands for: raw / 2^17, exactly.
double sfxtToDouble(int32_t raw) noexcept;

/// The 32-bit data field of a signed value (two's complement): -56329 gives 0xFFFF23F7.
uint32_t int32ToData(int32_t value) noexcept;

/// The signed value of a 32-bit data field: 0xFFFCA8AD gives -218963.
int32_t dataToInt32(uint32_t data) noexcept;

/// Writes a data field as it travels in a frame: least significant byte first.
void storeData(uint32_t data, uint8_t* bytes) noexcept;

/// Reads a data field from four frame bytes, least significant byte first.
uint32_t loadData(const uint8_t* bytes) noexcept;

}  // namespace costa::solo
