// Pre-defined connection set of CiA 301: the CAN identifiers of a node's services.
#pragma once

#include <stdint.h>

namespace costa::cob {

inline constexpr uint32_t kNmt = 0x000;
inline constexpr uint32_t kSync = 0x080;
inline constexpr uint32_t kEmcyBase = 0x080;
inline constexpr uint32_t kTpdo1Base = 0x180;
inline constexpr uint32_t kRpdo1Base = 0x200;
inline constexpr uint32_t kSdoTxBase = 0x580;  ///< Server to client.
inline constexpr uint32_t kSdoRxBase = 0x600;  ///< Client to server.
inline constexpr uint32_t kErrorControlBase = 0x700;
inline constexpr uint32_t kLssFromMaster = 0x7E5;
inline constexpr uint32_t kLssToMaster = 0x7E4;

inline constexpr uint8_t kLssUnconfigured = 0xFF;

/// CiA 301 7.3.5: CAN-IDs that no configurable communication object (SYNC, EMCY, PDO) may use,
/// because they belong to NMT, SDO, NMT error control and LSS, or are reserved: 0x000,
/// 0x001-0x07F, 0x101-0x180, 0x581-0x5FF, 0x601-0x67F, 0x6E0-0x6FF, 0x701-0x7FF.
inline constexpr bool isRestrictedCanId(uint32_t canId) noexcept {
  return canId <= 0x07FU || (canId >= 0x101U && canId <= 0x180U) ||
         (canId >= 0x581U && canId <= 0x5FFU) || (canId >= 0x601U && canId <= 0x67FU) ||
         (canId >= 0x6E0U && canId <= 0x6FFU) || canId >= 0x701U;
}

/// The rules of CiA 301 that every write of an 11-bit COB-ID shares (SYNC, TIME, EMCY, EMCY
/// consumer, PDO): bit 29 (a 29-bit CAN-ID) and bits 11..28 clear; a CAN-ID the object uses is not
/// restricted (7.3.5); where the object says so, the CAN-ID does not change.
/// used: the object uses the written CAN-ID (it is valid, or the object has no valid bit);
/// kept: this write may not change the CAN-ID (each object has its own rule for when, e.g. EMCY
/// while it is valid and stays valid); currentCanId: the CAN-ID it keeps.
bool acceptableCobId(uint32_t value, bool used, bool kept, uint32_t currentCanId) noexcept;

/// Valid node-ids for a configured node.
inline constexpr bool isValidNodeId(uint8_t id) noexcept {
  return id >= 1U && id <= 127U;
}

}  // namespace costa::cob
