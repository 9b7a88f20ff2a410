// Validation of writes to PDO communication and mapping parameters (CiA 301 7.5.2.35-39).
#include "costa/cob_ids.hpp"
#include "costa/od/little_endian.hpp"
#include "costa/pdo_engine.hpp"

namespace costa {
namespace {

// The UNSIGNED32 a write carries (built for size, a call of the dictionary's loader, not four
// byte loads inline at each use).
uint32_t writtenU32(const uint8_t* data) noexcept {
  return static_cast<uint32_t>(loadLittleEndian(data, 4));
}

// Sub-index 1, the COB-ID: the rules every 11-bit COB-ID shares (cob::acceptableCobId(): no
// 29-bit CAN-ID, no bits 11..28, a CAN-ID in use not restricted, a valid PDO made not valid
// before its CAN-ID changes), or, where the device gives its PDOs a range of CAN-IDs, that range
// instead of the restricted ones.
AbortCode checkCobIdWrite(const PdoProfile& profile, bool receive, bool currentlyValid,
                          uint32_t currentCanId, const uint8_t* data, size_t length) noexcept {
  if (length != 4U) {
    return AbortCode::kNone;  // the dictionary reports the length error
  }
  const uint32_t value = writtenU32(data);
  const PdoCobId cob = decodePdoCobId(value, profile.cobIdPolarity);
  const CanIdRange range = receive ? profile.rpdoCanIds : profile.tpdoCanIds;
  const bool acceptable = cob::acceptableCobId(value, cob.valid && !range.restricts(),
                                               currentlyValid && cob.valid, currentCanId) &&
                          !(cob.valid && range.restricts() && !range.contains(cob.canId));
  return acceptable ? AbortCode::kNone : AbortCode::kInvalidValue;
}

/// The highest SYNC start value (TPDO communication parameter sub-index 6, CiA 301).
constexpr uint8_t kLastSyncStartValue = 240;

}  // namespace

AbortCode PdoEngine::checkCommunicationWrite(const PdoChannel& channel, bool receive,
                                             const od::EntryRef& ref, const uint8_t* data,
                                             size_t length) const noexcept {
  const PdoProfile& profile = context_.profile;
  const bool currentlyValid = channel.valid();
  const uint32_t currentCanId = channel.canId();
  const uint8_t subIndex = ref.subIndex();
  if (subIndex == 1U) {
    return checkCobIdWrite(profile, receive, currentlyValid, currentCanId, data, length);
  }
  bool refused = false;
  if (subIndex == 2U && length >= 1U) {
    // The type: 241..251 (RPDO: 241..253) are reserved, and so is what a wider type
    // (UNSIGNED32) adds above 255.
    const uint64_t type = loadLittleEndian(data, length);
    refused = type > 240U && (type > 0xFFU || type < (receive ? 254U : 252U));
  } else if (subIndex == 3U || subIndex == 6U) {
    // The inhibit time and the SYNC start value of a TPDO change only while it is not valid;
    // SYNC start values 241..255 are reserved (0: not used, 1..240).
    refused = !receive &&
              (currentlyValid || (subIndex == 6U && length >= 1U && data[0] > kLastSyncStartValue));
  }
  return refused ? AbortCode::kInvalidValue : AbortCode::kNone;
}

AbortCode PdoEngine::checkMappingWrite(const PdoChannel& channel, bool receive,
                                       const od::EntryRef& ref, const uint8_t* data,
                                       size_t length) const noexcept {
  if (channel.valid()) {
    return AbortCode::kCannotStoreState;  // mapping changes only while the PDO is invalid
  }
  const od::ObjectDictionary& dictionary = context_.access.dictionary();
  const uint16_t index = ref.index();
  const PdoDirection direction = receive ? PdoDirection::kReceive : PdoDirection::kTransmit;
  if (ref.subIndex() != 0U) {
    if (dictionary.readUnsigned32(index, 0, 0) != 0U) {
      return AbortCode::kCannotStoreState;  // disable the mapping (sub-index 0 = 0) first
    }
    return length == 4U ? PdoMap::checkEntry(dictionary, writtenU32(data), direction)
                        : AbortCode::kNone;
  }
  if (length != 1U) {
    return AbortCode::kNone;
  }
  PdoMap candidate;
  return resolvePdoMapping(context_, channel.communicationIndex(), &candidate, data[0]);
}

}  // namespace costa
