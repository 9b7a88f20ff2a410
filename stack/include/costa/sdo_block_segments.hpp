// How many segments of an SDO block transfer (CiA 301 7.2.4.3.12) carry a number of bytes.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// ceil(`bytes` / 7), the segments of 7 data bytes that carry `bytes`, but at most 127 (the
/// most a block has); 0 for 0 bytes. Without a division: `bytes` is capped at 127 x 7 = 889,
/// and (capped + 6) / 7 = (capped + 6) x 9363 >> 16, which is exact for every argument up to
/// 13,109 (the argument here is at most 895).
constexpr uint8_t blockSegments(size_t bytes) noexcept {
  constexpr uint32_t kMostBytes = 127U * 7U;
  const uint32_t capped = bytes < kMostBytes ? static_cast<uint32_t>(bytes) : kMostBytes;
  return static_cast<uint8_t>(((capped + 6U) * 9363U) >> 16U);
}

}  // namespace costa
