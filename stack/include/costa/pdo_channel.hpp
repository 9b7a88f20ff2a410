// What RPDO and TPDO channels share: where their parameters live, how their COB-ID is read,
// and the services they report to.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/node_clock.hpp"
#include "costa/object_access.hpp"
#include "costa/pdo_map.hpp"
#include "costa/pdo_profile.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class EmcyProducer;
class FrameRouter;
class NodeListeners;
class TpdoChannel;

/// Everything a PDO channel needs from its node.
struct PdoContext {
  ObjectAccess& access;
  TransmitPath& tx;
  const PdoProfile& profile;
  EmcyProducer& emcy;
  const NodeListeners& listeners;
  NodeClock& clock;
  FrameRouter& routes;  ///< told when a PDO's CAN-ID or validity changes
  /// The TPDO channels (set by PdoEngine::bind()): an RPDO's answering TPDO is one of them.
  TpdoChannel* tpdos = nullptr;
  /// The end of the last SYNC's window (0x1007; kNever without one): a synchronous RPDO that
  /// arrives from then on is discarded until the next SYNC (CiA 301).
  Microseconds syncWindowEnd = kNever;
};

/// A decoded PDO COB-ID (sub-index 1 of a communication parameter).
struct PdoCobId {
  uint32_t canId = 0;
  bool valid = false;
  bool rtrAllowed = false;
  bool extended = false;      ///< bit 29
  bool reservedBits = false;  ///< bits 28..11 set in an 11-bit COB-ID
};

/// Inline: each use keeps only the fields it reads, and where the polarity is a constant (a
/// build without quirk profiles) the test of it folds away.
inline PdoCobId decodePdoCobId(uint32_t value, PdoCobIdPolarity polarity) noexcept {
  PdoCobId cob;
  const bool bit31 = (value & 0x80000000U) != 0U;
  const bool bit30 = (value & 0x40000000U) != 0U;
  if (polarity == PdoCobIdPolarity::kCia301) {
    cob.valid = !bit31;
    cob.rtrAllowed = !bit30;
  } else {
    cob.valid = bit31;
    cob.rtrAllowed = bit30;
  }
  cob.extended = (value & 0x20000000U) != 0U;
  cob.canId = value & (cob.extended ? 0x1FFFFFFFU : 0x7FFU);
  cob.reservedBits = !cob.extended && (value & 0x1FFFF800U) != 0U;
  return cob;
}

/// What an RPDO and a TPDO channel share: their communication object and the parameters both
/// read from it (COB-ID, transmission type, event timer). The first eight bytes of either.
class PdoChannel {
 public:
  uint16_t communicationIndex() const noexcept { return index_; }
  bool valid() const noexcept { return valid_; }
  uint32_t canId() const noexcept { return canId_; }
  uint8_t transmissionType() const noexcept { return type_; }

 protected:
  /// Reads sub-indices 1 (COB-ID: validity, CAN-ID), 2 (type) and 5 (event timer); returns
  /// whether the COB-ID allows RTR.
  bool readCommunication(const PdoContext& context) noexcept;

 private:
  // The two kinds of channel read the fields as their own (readCommunication() writes them).
  friend class RpdoChannel;
  friend class TpdoChannel;

  uint16_t index_ = 0;
  uint16_t canId_ = 0;
  uint16_t eventTimerMs_ = 0;  ///< sub-index 5
  uint8_t type_ = 0;
  bool valid_ = false;
};

/// resolvePdoMapping()'s `written` when the count of mapped entries is the dictionary's (a
/// value no written count has: sub-index 0 is a byte).
constexpr size_t kMappedCount = SIZE_MAX;

/// Resolves into `map` the mapping of the PDO whose communication parameter is at
/// `communicationIndex` (an RPDO's below 0x1800, else a TPDO's): the mapping object (index +
/// 0x200) when the dictionary has one, else the device's static mapping
/// (PdoProfile::staticMappings; at most PdoMap::kMaxEntries entries of either). The mapping
/// cannot be resolved: its abort code (PdoMap::resolve), and `map` is left empty.
///
/// `written`: the count about to be written to the mapping object's sub-index 0, with its
/// entries as the dictionary holds them (a write checked before it is made). A count beyond
/// kMaxEntries or the object's sub-indices is kMappingTooLong, an entry of 0 among them
/// kParameterIncompatible (`map` left as it was for either).
AbortCode resolvePdoMapping(PdoContext& context, uint16_t communicationIndex, PdoMap* map,
                            size_t written = kMappedCount) noexcept;

}  // namespace costa
