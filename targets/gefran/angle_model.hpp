// The GRA/GRN angle computation (targets/gefran/README.md, "Angle computation"): a chip's raw
// 14-bit reading turned into the output angle by direction, resolution and zero point, and the
// two angles packed into the TPDO's first four bytes. Pure functions, freestanding.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa::gefran {

inline constexpr uint32_t kRawCounts = 16384;  ///< one turn of a 14-bit chip

/// Resolution codes of 0x2100: 1000 = 1°, 100 = 0.1°, 22 = 0.01°.
enum Resolution : uint16_t { kOneDegree = 1000, kTenthDegree = 100, kHundredthDegree = 22 };

/// Output values per turn for a resolution code (360, 3600, 36000), 0 for an unknown code.
constexpr uint32_t fullScale(uint16_t resolution) noexcept {
  return resolution == kOneDegree         ? 360U
         : resolution == kTenthDegree     ? 3600U
         : resolution == kHundredthDegree ? 36000U
                                          : 0U;
}

struct AngleSettings {
  uint16_t resolution = kTenthDegree;  ///< 0x2100.n
  uint16_t zeroPoint = 0;              ///< 0x2101.n, in units of the resolution
  bool clockwise = false;              ///< 0x2102.n
};

/// Output angle (0 .. fullScale - 1) of a raw reading: direction (CW counts backwards), scaling
/// by truncation, then the zero point subtracted modulo a turn. 0 for an unknown resolution.
constexpr uint32_t outputAngle(uint16_t raw, const AngleSettings& settings) noexcept {
  const uint32_t scale = fullScale(settings.resolution);
  if (scale == 0U) {
    return 0;
  }
  const uint32_t reading = raw % kRawCounts;
  const uint32_t directed = settings.clockwise ? (kRawCounts - reading) % kRawCounts : reading;
  const uint32_t scaled = directed * scale / kRawCounts;
  return (scaled + scale - settings.zeroPoint % scale) % scale;
}

/// TPDO bytes 1..4: angle 1 then angle 2, most significant byte first (0x5001 = 0) or least
/// significant first (0x5001 = 1).
inline void packAngles(uint16_t angle1, uint16_t angle2, bool littleEndian, uint8_t* out) noexcept {
  const uint16_t angles[2] = {angle1, angle2};
  for (size_t i = 0; i < 2U; ++i) {
    const auto high = static_cast<uint8_t>(angles[i] >> 8U);
    const auto low = static_cast<uint8_t>(angles[i]);
    out[2U * i] = littleEndian ? low : high;
    out[2U * i + 1U] = littleEndian ? high : low;
  }
}

/// Raw reading of a shaft angle in degrees (rounded, wrapped to one turn).
constexpr uint16_t rawFromDegrees(double degrees) noexcept {
  double turns = degrees / 360.0;
  turns -= static_cast<double>(static_cast<int64_t>(turns));
  if (turns < 0) {
    turns += 1.0;
  }
  // turns is in [0, 1): adding 0.5 and truncating rounds to nearest (std::lround is neither
  // constexpr nor freestanding).
  // NOLINTNEXTLINE(bugprone-incorrect-roundings): the value is never negative
  return static_cast<uint16_t>(static_cast<uint32_t>(turns * kRawCounts + 0.5) % kRawCounts);
}

}  // namespace costa::gefran
