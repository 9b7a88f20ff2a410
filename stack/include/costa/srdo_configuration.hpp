// One SRDO's configuration (EN 50325-5 / CiA 304): communication parameters 0x1301 + n - 1
// (n = 1..64: 01 information direction 0 not valid / 1 transmit / 2 receive, 02 SCT in ms
// UNSIGNED16, 03 SRVT in ms UNSIGNED8, 04 transmission type 254, 05 COB-ID of the normal data,
// 06 COB-ID of the inverted data) and mapping 0x1381 + n - 1 (00 count, even; odd sub-indices
// map the normal data, each following even one its inverted copy: an entry of the same size
// that the application keeps (CiA 304), or the normal entry again, which the stack inverts).
//
// The signature (0x13FF:n) is the CRC-16 of CiA 301 (crc16.hpp, polynomial 0x1021, initial 0)
// over, in this order: direction (1 byte), SCT (2 bytes, little-endian), SRVT (1), COB-ID 1
// (4, little-endian), COB-ID 2 (4), mapping count (1), then per mapping entry its sub-index
// (1) and its value (4, little-endian); each value as the object reads (a $NODEID default with
// the node-id added). The transmission type is not part of it. A configuration tool computes
// the same bytes (docs/manual-errata.md, "SRDO signature").
//
// Also the write rules of these objects (checkSrdoWrite) and of a mapping as a whole.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/abort_code.hpp"
#include "costa/od/object_dictionary.hpp"

namespace costa {

namespace srdo {
inline constexpr uint16_t kFirstCommunication = 0x1301;
inline constexpr uint16_t kLastCommunication = 0x1340;
inline constexpr uint16_t kFirstMapping = 0x1381;
inline constexpr uint16_t kLastMapping = 0x13C0;
inline constexpr uint16_t kConfigurationValid = 0x13FE;
inline constexpr uint16_t kSignatures = 0x13FF;
inline constexpr uint8_t kValid = 0xA5;  ///< 0x13FE: the configuration is valid
inline constexpr uint8_t kNotValid = 0;
inline constexpr uint8_t kTransmit = 1;
inline constexpr uint8_t kReceive = 2;
inline constexpr uint8_t kTransmissionType = 254;
inline constexpr uint8_t kLongestMapping = 16;  ///< 8 bytes, each mapped twice
}  // namespace srdo

/// What is wrong with an SRDO's configuration.
enum class SrdoCheck : uint8_t {
  kValid,       ///< runs
  kNotValid,    ///< direction 0: does not run
  kParameters,  ///< a communication parameter is out of range
  kMapping,     ///< the mapping does not resolve (see checkSrdoMapping)
  kSignature,   ///< 0x13FF:n is not the CRC of the configuration
};

struct SrdoConfiguration {
  uint8_t number = 0;  ///< n: 1..64
  uint8_t direction = srdo::kNotValid;
  uint16_t cycleMs = 0;      ///< SCT
  uint8_t validationMs = 0;  ///< SRVT
  uint16_t normalId = 0;
  uint16_t invertedId = 0;
  uint8_t mappedCount = 0;  ///< mapping sub-index 0
  uint8_t length = 0;       ///< bytes of data in each of the two frames
  uint16_t signature = 0;   ///< the CRC computed over the configuration
};

/// Reads SRDO `number` from the dictionary and checks it against 0x13FF:number.
SrdoCheck readSrdoConfiguration(const od::ObjectDictionary& dictionary, uint8_t number,
                                SrdoConfiguration* out) noexcept;

/// Checks the first `count` entries of mapping object `mappingIndex` for `direction`: pairs of
/// a normal (odd sub-index) and an inverted (even) entry of the same size (else 0x06040043),
/// each an existing entry (0x06020000 / 0x06090011) mappable in that direction (0x06040041)
/// with its length in whole bytes equal to its size (0x06040043), at most 8 bytes of normal
/// data in all (0x06040042). The inverted entry may be the normal one again: the stack then
/// inverts the value itself. On success, *length = the bytes of each frame.
AbortCode checkSrdoMapping(const od::ObjectDictionary& dictionary, uint16_t mappingIndex,
                           uint8_t count, uint8_t direction, uint8_t* length) noexcept;

/// The rules of a write of `data` to an SRDO object at `ref` (0x1301..0x13C0), in
/// pre-operational or stopped: kNone when allowed. Direction 0..2, SCT and SRVT not 0,
/// transmission type 254 (0x06090030); COB-IDs 0x101..0x180, odd for the normal data and even
/// for the inverted (0x06090030); a mapping only while the SRDO's direction is 0 (0x06010000);
/// its entries only while its count is 0 (0x08000022), its count even and up to 16
/// (0x06040042) and the entries checked as checkSrdoMapping says.
AbortCode checkSrdoWrite(const od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                         const uint8_t* data, size_t length) noexcept;

}  // namespace costa
