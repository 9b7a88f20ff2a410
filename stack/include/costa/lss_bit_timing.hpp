// A bit timing as CiA 305 (LSS) names it, and the CiA 305 standard bit timing table: the one
// mapping between table entries and bit rates in Costa.
#pragma once

#include <stdint.h>

namespace costa {

/// A bit timing as CiA 305 selects it. Table selector 0 is the CiA table, whose index means:
/// 0 = 1000, 1 = 800, 2 = 500, 3 = 250, 4 = 125 kbit/s, 5 reserved, 6 = 50, 7 = 20, 8 = 10 kbit/s,
/// 9 = automatic bit rate detection. Selectors 1..127 are reserved; 128..255 name
/// manufacturer-specific tables.
struct LssBitTiming {
  uint8_t tableSelector = 0;
  uint8_t tableIndex = 0;
};

inline bool operator==(const LssBitTiming& a, const LssBitTiming& b) noexcept {
  return a.tableSelector == b.tableSelector && a.tableIndex == b.tableIndex;
}
inline bool operator!=(const LssBitTiming& a, const LssBitTiming& b) noexcept {
  return !(a == b);
}

/// Bit rate of an entry of the CiA 305 standard bit timing table, in bit/s; 0 for index 5
/// (reserved) and for indices beyond 8 (9 is automatic bit rate detection).
constexpr uint32_t cia305BitRate(uint8_t tableIndex) noexcept {
  switch (tableIndex) {
    case 0: return 1000000;
    case 1: return 800000;
    case 2: return 500000;
    case 3: return 250000;
    case 4: return 125000;
    case 6: return 50000;
    case 7: return 20000;
    case 8: return 10000;
    default: return 0;
  }
}

/// Index of `bitsPerSecond` in the CiA 305 standard table, or -1 when the table has no entry
/// with that rate.
constexpr int cia305TableIndex(uint32_t bitsPerSecond) noexcept {
  for (uint8_t index = 0; index <= 8U; ++index) {
    if (bitsPerSecond != 0U && cia305BitRate(index) == bitsPerSecond) {
      return index;
    }
  }
  return -1;
}

/// Bit rate of `timing` in bit/s: its CiA 305 table rate, 0 when it has none (automatic bit
/// rate detection, a reserved entry, a manufacturer-specific table).
constexpr uint32_t bitRateOf(LssBitTiming timing) noexcept {
  return timing.tableSelector == 0U ? cia305BitRate(timing.tableIndex) : 0U;
}

static_assert(cia305TableIndex(500000) == 2);
static_assert(cia305TableIndex(10000) == 8);
static_assert(cia305TableIndex(0) == -1);
static_assert(cia305TableIndex(100000) == -1);
static_assert(bitRateOf(LssBitTiming{0, 3}) == 250000);
static_assert(bitRateOf(LssBitTiming{128, 3}) == 0);

}  // namespace costa
