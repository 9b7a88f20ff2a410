// The Santeng controller's wire behaviour as a Costa device profile (docs/errata-santeng.md,
// section W), and its node-id range.
#pragma once

#include "costa/node.hpp"

namespace costa::santeng {

/// Node-ids 1..126 (manual lines 58, 84, 194; W11).
inline constexpr uint8_t kHighestNodeId = 126;

/// The bit rates of the manual's list, in its order (lines 60, 88; W12): the Santeng's own bit
/// timing table (CiA 305 selector 128), since 25 kbit/s is not in CiA 305's (W13).
inline constexpr uint32_t kBitRates[] = {1000000, 800000, 500000, 250000,
                                         125000,  50000,  25000,  10000};
inline constexpr uint8_t kBitRateCount = sizeof(kBitRates) / sizeof(kBitRates[0]);
inline constexpr BitRateTable kBitRateTable{kBitRates, kBitRateCount};
/// 250 kbit/s, the default (lines 60, 88, 125).
inline constexpr LssBitTiming kDefaultBitTiming{kManufacturerBitTimingTable, 3};

/// The Santeng profile: SDO requests of 4 bytes and more are served (W2), an expedited write
/// longer than its object keeps the object's low bytes (W3), 0x2C and its kin are expedited
/// writes of the byte count they give (W4); heartbeat only, no node guarding (W8).
/// Upload responses indicate the size and errors are CiA 301 aborts (W5): the defaults.
constexpr DeviceProfile profile() noexcept {
  DeviceProfile p{};
  // The device needs the quirk profiles (santeng_device.cpp); its header compiles in any tree.
#if COSTA_QUIRK_PROFILES
  p.sdo.shortestRequest = 4;
  p.sdo.expeditedKeepsLowBytes = true;
  p.sdo.expeditedByCountAlone = true;
  p.errorControl.nodeGuarding = false;
#endif
  return p;
}

}  // namespace costa::santeng
