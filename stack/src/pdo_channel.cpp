#include "costa/pdo_channel.hpp"

namespace costa {

bool PdoChannel::readCommunication(const PdoContext& context) noexcept {
  const od::ObjectDictionary& dictionary = context.access.dictionary();
  const uint32_t value = dictionary.readUnsigned32(index_, 1, 0x80000000U);
  const PdoCobId cob = decodePdoCobId(value, context.profile.cobIdPolarity);
  valid_ = cob.valid && !cob.extended;
  canId_ = static_cast<uint16_t>(value & 0x7FFU);
  type_ = static_cast<uint8_t>(dictionary.readUnsigned32(index_, 2, 255));
  eventTimerMs_ = static_cast<uint16_t>(dictionary.readUnsigned32(index_, 5, 0));
  return cob.rtrAllowed;
}

namespace {

// The mapping values of the PDO whose communication parameter is at `communicationIndex` (see
// resolvePdoMapping); returns how many were written to `values`.
size_t readMappingValues(const od::ObjectDictionary& dictionary, const StaticPdoMappings& fixed,
                         uint16_t communicationIndex, uint32_t* values) noexcept {
  const auto mappingIndex = static_cast<uint16_t>(communicationIndex + 0x200U);
  if (dictionary.findObject(mappingIndex) != nullptr) {
    auto count = static_cast<size_t>(dictionary.readUnsigned32(mappingIndex, 0, 0));
    if (count > PdoMap::kMaxEntries) {
      count = PdoMap::kMaxEntries;
    }
    for (size_t i = 0; i < count; ++i) {
      values[i] = dictionary.readUnsigned32(mappingIndex, static_cast<uint8_t>(i + 1U), 0);
    }
    return count;
  }
  for (size_t i = 0; i < fixed.count; ++i) {
    const StaticPdoMapping& mapping = fixed.mappings[i];
    if (mapping.communicationIndex == communicationIndex) {
      size_t count = mapping.count;
      if (count > PdoMap::kMaxEntries) {
        count = PdoMap::kMaxEntries;
      }
      for (size_t e = 0; e < count; ++e) {
        values[e] = mapping.entries[e];
      }
      return count;
    }
  }
  return 0;
}

}  // namespace

bool resolvePdoMapping(PdoContext& context, uint16_t communicationIndex, PdoDirection direction,
                       PdoMap* map) noexcept {
  uint32_t values[PdoMap::kMaxEntries];
  const size_t count = readMappingValues(
      context.access.dictionary(), context.profile.staticMappings, communicationIndex, values);
  return map->resolve(context.access, values, count, direction) == AbortCode::kNone;
}

}  // namespace costa
