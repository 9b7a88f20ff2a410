// How a device's PDOs behave (PdoEngine and its channels, and the Linux tracer). Every field
// defaults to CiA 301.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/profile_choice.hpp"

namespace costa {

/// Meaning of bits 31 and 30 of a PDO COB-ID (sub-index 1 of 0x1400+/0x1800+).
enum class PdoCobIdPolarity : uint8_t {
  /// CiA 301: bit 31 = 1 means "PDO does not exist / not valid"; bit 30 = 1 means "no RTR
  /// allowed on this PDO".
  kCia301,
  /// The opposite: bit 31 = 1 enables the PDO, bit 30 = 1 allows RTR.
  kBit31EnablesBit30AllowsRtr,
};

/// What TPDO transmission type 0 means.
enum class TpdoType0 : uint8_t {
  /// CiA 301: synchronous acyclic: sent at a SYNC only when the application signalled an event
  /// since the previous SYNC.
  kAcyclicOnEvent,
  /// Sent at every SYNC.
  kEverySync,
};

/// Which TPDO transmission types answer a remote request (when the COB-ID allows RTR).
enum class TpdoRtrTypes : uint8_t {
  /// RTR-only types 252 and 253 and the event-driven types 254 and 255.
  kCia301,
  /// Additionally the synchronous types 0..240.
  kAllTypes,
};

/// An inclusive range of CAN-IDs; {0, 0} means "no device-specific restriction".
struct CanIdRange {
  uint16_t first = 0;
  uint16_t last = 0;
  constexpr bool restricts() const noexcept { return first != 0U || last != 0U; }
  constexpr bool contains(uint32_t id) const noexcept { return id >= first && id <= last; }
};

/// Entries a PDO maps at most: 64 bits at byte granularity.
inline constexpr size_t kMaxPdoEntries = 8;

/// A device's fixed mapping for a PDO that has no mapping object in its dictionary.
struct StaticPdoMapping {
  uint16_t communicationIndex;  ///< 0x1400.. or 0x1800..
  uint8_t count;
  uint32_t entries[kMaxPdoEntries];
};

struct StaticPdoMappings {
  const StaticPdoMapping* mappings = nullptr;
  size_t count = 0;
};

struct PdoProfile {
  // Member names, also where COSTA_PROFILE_CHOICE makes the fields constants.
  // NOLINTBEGIN(readability-identifier-naming)
  COSTA_PROFILE_CHOICE PdoCobIdPolarity cobIdPolarity = PdoCobIdPolarity::kCia301;
  COSTA_PROFILE_CHOICE TpdoType0 tpdoType0 = TpdoType0::kAcyclicOnEvent;
  COSTA_PROFILE_CHOICE TpdoRtrTypes tpdoRtrTypes = TpdoRtrTypes::kCia301;
  /// CAN-IDs an RPDO/TPDO may be given in addition to CiA 301's restricted-ID rule.
  COSTA_PROFILE_CHOICE CanIdRange rpdoCanIds{};
  COSTA_PROFILE_CHOICE CanIdRange tpdoCanIds{};
  /// Event-driven TPDOs (254/255) are sent once when the node enters OPERATIONAL. CiA 301 does
  /// not ask for it (events and the event timer trigger them), so the default is off.
  COSTA_PROFILE_CHOICE bool tpdoOnEnteringOperational = false;
  /// Every RPDO n the node accepts (of the right length, every entry written or, for a
  /// synchronous RPDO, held for the SYNC) is answered by the event-driven TPDO n (0x1800 + n-1
  /// for 0x1400 + n-1), at reception: a device whose TPDOs reply to its RPDOs. CiA 301 has
  /// no such link.
  COSTA_PROFILE_CHOICE bool tpdoAnswersRpdo = false;
  /// The mappings of PDOs that have no mapping object (0x1600+/0x1A00+) in the dictionary: a
  /// device with fixed mappings. CiA 301 maps through the mapping objects: none.
  COSTA_PROFILE_CHOICE StaticPdoMappings staticMappings{};
  // NOLINTEND(readability-identifier-naming)
};

}  // namespace costa
