// A bit timing as CiA 305 (LSS) names it: a table and an entry of it. The CiA 305 standard
// table itself (entry <-> bit rate) is the port layer's (costa/port/can_bit_rate.hpp), which
// drivers share.
#pragma once

#include <stdint.h>

#include "costa/port/can_bit_rate.hpp"

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

/// The table selector of a device's own bit timing table (the first manufacturer-specific one).
inline constexpr uint8_t kManufacturerBitTimingTable = 128;

/// A device's own bit timing table (NodeSettings::manufacturerBitRates): the rate in bit/s of
/// each index of table selector kManufacturerBitTimingTable.
struct BitRateTable {
  const uint32_t* bitsPerSecond = nullptr;
  uint8_t count = 0;
};

/// Bit rate of `timing` in bit/s: its CiA 305 table rate, or its rate in the device's own
/// `table` (selector 128); 0 when it has none (automatic bit rate detection, a reserved entry,
/// another manufacturer-specific table, an index beyond the device's table).
constexpr uint32_t bitRateOf(LssBitTiming timing, const BitRateTable* table = nullptr) noexcept {
  if (timing.tableSelector == 0U) {
    return cia305BitRate(timing.tableIndex);
  }
  return table != nullptr && timing.tableSelector == kManufacturerBitTimingTable &&
                 timing.tableIndex < table->count
             ? table->bitsPerSecond[timing.tableIndex]
             : 0U;
}

static_assert(bitRateOf(LssBitTiming{0, 3}) == 250000);
static_assert(bitRateOf(LssBitTiming{128, 3}) == 0);

}  // namespace costa
