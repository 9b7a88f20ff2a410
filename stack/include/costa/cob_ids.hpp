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

/// Valid node-ids for a configured node.
inline constexpr bool isValidNodeId(uint8_t id) noexcept {
  return id >= 1U && id <= 127U;
}

}  // namespace costa::cob
